#include "scenegraph/io/SceneReference.h"

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/io/detail/InventorTypes.h"

#include <sstream>

namespace texsplat::sg {

namespace {

// `text` with '|' escaped, so that it stays in its table cell.
std::string escapeCell(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        escaped += c == '|' ? std::string("\\|") : std::string(1, c);
    }
    return escaped;
}

// A value as a table cell: code; a field without a value (SFTrigger) says so, since an empty
// code span shows as two backticks.
std::string valueCell(const std::string& text) {
    return text.empty() ? "(no value)" : "`" + escapeCell(text) + "`";
}

void writeType(std::ostringstream& out, const NodeType& type) {
    out << "### " << type.name() << "\n\n";
    const std::shared_ptr<FieldContainer> instance = type.create();
    const auto* engine = dynamic_cast<const Engine*>(instance.get());
    out << (engine != nullptr ? "Engine" : "Node");
    if (type.parent() != nullptr) {
        out << ", derived from " << type.parent()->name();
    }
    out << ". ";
    if (dynamic_cast<const Group*>(instance->asNode()) != nullptr) {
        out << "Takes child nodes. ";
    }
    out << (detail::isInventorType(type.name())
                ? "Standard Inventor type."
                : "Extension type: written with its `fields [ … ]` description.")
        << "\n\n";
    if (instance->fields().empty()) {
        out << "No fields.\n\n";
    } else {
        out << "| " << (engine != nullptr ? "input" : "field") << " | type | default | meaning |\n"
            << "|---|---|---|---|\n";
        for (const Field* field : instance->fields()) {
            std::string typeText(field->typeName());
            if (const auto* enumField = dynamic_cast<const SFEnum*>(field);
                enumField != nullptr && enumField->enumNames() != nullptr) {
                typeText += " (" + enumField->enumNames()->list() + ")";
            }
            out << "| " << field->name() << " | " << typeText << " | "
                << valueCell(field->valueText()) << " | "
                << escapeCell(type.fieldDescription(field->name())) << " |\n";
        }
        out << "\n";
    }
    if (engine != nullptr && !engine->outputs().empty()) {
        out << "| output | type | meaning |\n|---|---|---|\n";
        for (const EngineOutputBase* output : engine->outputs()) {
            out << "| " << output->name() << " | " << output->typeName() << " | "
                << escapeCell(type.fieldDescription(output->name())) << " |\n";
        }
        out << "\n";
    }
}

} // namespace

std::string sceneReferenceMarkdown() {
    std::ostringstream out;
    out << "## Node and engine types\n\n";
    for (const NodeType* type : NodeRegistry::instance().types()) {
        if (!type->isAbstract()) {
            writeType(out, *type);
        }
    }
    return out.str();
}

std::string replaceGeneratedReference(const std::string& document, const std::string& generated,
                                      const std::string& documentName) {
    const std::string begin = kGeneratedReferenceBegin;
    const std::string end = kGeneratedReferenceEnd;
    const std::size_t beginAt = document.find(begin);
    const std::size_t endAt = document.find(end);
    if (beginAt == std::string::npos || endAt == std::string::npos || endAt < beginAt) {
        throw DataError(documentName + ": expected the lines '" + begin + "' and then '" + end +
                        "' around the generated reference");
    }
    const std::size_t contentAt = beginAt + begin.size();
    return document.substr(0, contentAt) + "\n\n" + generated + document.substr(endAt);
}

} // namespace texsplat::sg
