#include "scenegraph/io/WriteAction.h"

#include "scenegraph/AtomicFile.h"
#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/io/UnknownNode.h"
#include "scenegraph/io/detail/ContainerGraph.h"
#include "scenegraph/io/detail/InventorTypes.h"

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>

namespace texsplat::sg {

namespace {

constexpr int kIndentWidth = 4;
// Indentation stops growing at this depth, so that the file of a deep graph grows linearly
// with its size instead of quadratically.
constexpr int kMaxIndentLevels = 32;
// Lists wrap before a value would pass this column.
constexpr std::size_t kLineWidth = 100;

} // namespace

WriteAction::WriteAction(std::ostream& output) : Action(methods()), mOutput(output) {}

MethodTable& WriteAction::methods() {
    static MethodTable table = [] {
        MethodTable methodTable;
        methodTable.add(Node::classType(), [](Action& action, Node& node) {
            static_cast<WriteAction&>(action).writeNodeMethod(node);
        });
        return methodTable;
    }();
    return table;
}

std::string WriteAction::writeString(Node& root) {
    std::ostringstream text;
    WriteAction(text).apply(root);
    return text.str();
}

void WriteAction::writeFile(Node& root, const std::string& path) {
    writeFileAtomically(path, [&root](std::ofstream& stream) { WriteAction(stream).apply(root); });
}

void WriteAction::beginTraversal(Node& root) {
    mReferenceCounts = detail::countReferences(root);
    mWritten.clear();
    mUsedNames.clear();
    mNextAutomaticName = 0;
    mIndent = 0;
    mColumn = 0;
    write("#Inventor V2.1 ascii\n\n");
    mColumn = 0;
}

void WriteAction::writeNodeMethod(Node& node) {
    writeContainer(node);
    if (pathNodes().size() == 1) {
        write("\n");
    }
}

void WriteAction::writeContainer(FieldContainer& container) {
    const std::string name = definitionName(container);
    mWritten.emplace(&container, name);
    const ListState outerList = mList;
    mList = {};
    if (!name.empty()) {
        write("DEF " + name + " ");
    }
    write(container.typeName() + " {");
    ++mIndent;
    writeDescriptions(container);
    for (const Field* field : container.fields()) {
        writeFieldEntry(*field);
    }
    if (const auto* group = dynamic_cast<const Group*>(container.asNode())) {
        for (const Node::Ptr& child : group->children()) {
            newLine();
            writeReference(*child);
        }
    }
    --mIndent;
    newLine();
    write("}");
    mList = outerList;
}

void WriteAction::writeDescriptions(FieldContainer& container) {
    if (detail::isInventorType(container.typeName()) &&
        dynamic_cast<const UnknownNode*>(&container) == nullptr) {
        return;
    }
    const auto* engine = dynamic_cast<const Engine*>(&container);
    newLine();
    write(engine != nullptr ? "inputs" : "fields");
    beginList();
    for (const Field* field : container.fields()) {
        writeToken(std::string(field->typeName()) + " " + field->name());
    }
    endList();
    if (engine != nullptr) {
        newLine();
        write("outputs");
        beginList();
        for (const EngineOutputBase* output : engine->outputs()) {
            writeToken(std::string(output->typeName()) + " " + output->name());
        }
        endList();
    }
}

void WriteAction::writeFieldEntry(const Field& field) {
    if (!detail::isFieldWritten(field)) {
        return;
    }
    newLine();
    write(field.name());
    const Field* source = field.connectedField();
    const EngineOutputBase* output = field.connectedOutput();
    if (source != nullptr && source->container() != nullptr) {
        write(" = ");
        writeReference(*source->container());
        write(" . " + source->name());
    } else if (output != nullptr) {
        write(" = ");
        writeReference(output->engine());
        write(" . " + output->name());
    } else {
        field.writeValue(*this);
    }
}

void WriteAction::writeReference(FieldContainer& container) {
    if (const auto written = mWritten.find(&container); written != mWritten.end()) {
        write("USE " + written->second);
    } else if (Node* node = container.asNode()) {
        traverse(*node);
    } else {
        // Engines are not traversed by actions; bound their nesting the same way.
        if (mEngineNesting >= kMaxDepth) {
            throw DataError("cannot write " + container.describe() +
                            ": engines are connected deeper than the limit of " +
                            std::to_string(kMaxDepth) + " levels");
        }
        ++mEngineNesting;
        writeContainer(container);
        --mEngineNesting;
    }
}

std::string WriteAction::definitionName(const FieldContainer& container) {
    const std::string& own = container.name();
    if (own.empty() && mReferenceCounts[&container] < 2) {
        return {};
    }
    std::string name = own;
    if (own.empty() || mUsedNames.count(own) != 0) {
        name += "+" + std::to_string(mNextAutomaticName++);
    }
    mUsedNames.insert(name);
    return name;
}

void WriteAction::write(std::string_view text) {
    mOutput << text;
    mColumn += text.size();
}

void WriteAction::newLine() {
    mColumn = static_cast<std::size_t>(std::min(mIndent, kMaxIndentLevels) * kIndentWidth);
    mOutput << '\n' << std::string(mColumn, ' ');
}

void WriteAction::writeToken(std::string_view text) {
    if (!mList.isOpen) {
        write(" ");
    } else if (mList.count > 0 && mColumn + text.size() + 2 > kLineWidth) {
        write(",");
        ++mIndent;
        newLine();
        --mIndent;
    } else {
        write(mList.count > 0 ? ", " : " ");
    }
    write(text);
    ++mList.count;
}

void WriteAction::writeNode(const std::shared_ptr<Node>& node) {
    // In a list each node starts a line of its own, one level in.
    const bool isInList = mList.isOpen;
    if (isInList) {
        mList.hasNodes = true;
        ++mIndent;
        newLine();
    } else {
        write(" ");
    }
    if (node) {
        writeReference(*node);
    } else {
        write("NULL");
    }
    if (isInList) {
        --mIndent;
    }
}

void WriteAction::beginList() {
    write(" [");
    mList = {true, false, 0};
}

void WriteAction::endList() {
    if (mList.hasNodes) {
        newLine();
        write("]");
    } else {
        write(" ]");
    }
    mList = {};
}

} // namespace texsplat::sg
