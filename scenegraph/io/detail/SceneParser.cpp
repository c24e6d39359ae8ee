#include "scenegraph/io/detail/SceneParser.h"

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/SourceFiles.h"
#include "scenegraph/fields/Field.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/ValueFormat.h"
#include "scenegraph/io/RelativeFileNames.h"
#include "scenegraph/io/UnknownNode.h"
#include "scenegraph/io/detail/NumberText.h"

#include <cctype>
#include <limits>

namespace texsplat::sg::detail {

namespace {

bool isIdentifier(std::string_view word) {
    if (word.empty() || std::isdigit(static_cast<unsigned char>(word.front())) != 0) {
        return false;
    }
    for (char c : word) {
        if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') {
            return false;
        }
    }
    return true;
}

bool startsNumber(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.';
}

// What a node or engine costs besides its instance (NodeType::instanceBytes()), its field list
// and its fields' values, in resident memory: the shared pointer's count, its parent list, its
// slot in its parent's child list, malloc's headers and what the heap cannot give back between
// them. Measured as the resident size per node less its sizeof (docs/reliability.md, "Memory per
// scene node": Group 383 - 128, Separator 663 - 352, Transform 743 - 400 bytes; a 100 MB file
// of Transforms, 731 - 400).
constexpr std::uint64_t kInstanceOverheadBytes = 300;

// The memory limit is asked each time the file's nodes hold this much more: a 100 MB file of
// small nodes took 2.6 GB, so each check covers about 20 KB of such a file.
constexpr std::uint64_t kMemoryCheckBytes = std::uint64_t{1} << 20;

} // namespace

SceneParser::SceneParser(std::string_view text, std::string fileName, std::string baseDirectory,
                         std::shared_ptr<const DataRoots> dataRoots)
    : mSourceFile(internSourceFile(fileName)), mLexer(text, std::move(fileName)),
      mBaseDirectory(std::move(baseDirectory)), mDataRoots(std::move(dataRoots)),
      mHeldBytes(text.size()), mNextMemoryCheck(text.size()) {}

void SceneParser::countHeldBytes(std::uint64_t bytes) {
    mHeldBytes += bytes;
    if (mHeldBytes < mNextMemoryCheck) {
        return;
    }
    mNextMemoryCheck = mHeldBytes + kMemoryCheckBytes;
    const SourceLocation where = mLexer.location();
    checkMemory(sourceFileName(mSourceFile) + ":" + SceneLexer::format(where) +
                    ": the scene read up to here (its text and the nodes made of it)",
                mHeldBytes, "use a smaller scene file, or a larger --memory-limit");
}

void SceneParser::countInstance(const FieldContainer& container) {
    countHeldBytes(container.type().instanceBytes() + kInstanceOverheadBytes +
                   container.fields().size() * sizeof(Field*));
}

std::shared_ptr<Node> SceneParser::parseFile() {
    mLexer.readHeader();
    std::vector<std::shared_ptr<Node>> roots;
    while (!mLexer.isAtEnd()) {
        const SourceLocation where = mLexer.location();
        std::shared_ptr<Node> node = readNode();
        if (!node) {
            mLexer.fail(where, "expected a node, got 'NULL' at the top level");
        }
        roots.push_back(std::move(node));
    }
    if (roots.empty()) {
        mLexer.fail(mLexer.location(), "expected a node after the header, got end of file");
    }
    std::shared_ptr<Node> root = roots.front();
    if (roots.size() > 1) {
        const Separator::Ptr separator = Separator::create();
        for (std::shared_ptr<Node>& node : roots) {
            separator->addChild(std::move(node));
        }
        root = separator;
    }
    if (const ReadConnection* unheld = keepUnheldSources(*root, mConnections)) {
        mLexer.fail(unheld->where, "cannot keep " + unheld->source->describe() +
                                       " alive as the source of " + unheld->field->fullName() +
                                       ": it contains " + unheld->field->container()->describe() +
                                       " (directly or through others), and nothing else in the "
                                       "scene holds it");
    }
    return root;
}

float SceneParser::readFloat() {
    const std::string word = valueWord("a number");
    float value = 0.0f;
    switch (parseFloat(word, value)) {
    case ParsedNumber::Valid:
        break;
    case ParsedNumber::Malformed:
        failExpected("a number", SceneLexer::quote(word));
    case ParsedNumber::OutOfRange:
        fail("number out of range" + fieldContext() + ": " + SceneLexer::quote(word) +
             " (largest float is " + formatFloat(std::numeric_limits<float>::max()) + ")");
    }
    return value;
}

std::int32_t SceneParser::readInt32() {
    const std::string word = valueWord("an integer");
    std::int32_t value = 0;
    switch (parseInt32(word, value)) {
    case ParsedNumber::Valid:
        break;
    case ParsedNumber::Malformed:
        failExpected("an integer", SceneLexer::quote(word));
    case ParsedNumber::OutOfRange:
        fail("integer out of range" + fieldContext() + ": " + SceneLexer::quote(word) +
             " (expected -2147483648 to 2147483647)");
    }
    return value;
}

std::string SceneParser::readString() {
    checkListNotTruncated();
    if (mLexer.peek() == '"') {
        mTokenStart = mLexer.location();
        return mLexer.readQuoted();
    }
    return valueWord("a string");
}

std::string SceneParser::readName() { return valueWord("a value"); }

bool SceneParser::readChar(char c) {
    if (c == ']') {
        checkListNotTruncated();
    }
    const SourceLocation where = mLexer.location();
    if (!mLexer.consumeIf(c)) {
        return false;
    }
    if (c == '[') {
        mOpenList = where;
        mHasReadList = true;
    } else if (c == ']') {
        mOpenList.reset();
    }
    return true;
}

std::shared_ptr<Node> SceneParser::readNode() {
    checkListNotTruncated();
    const SourceLocation where = mLexer.location();
    mTokenStart = where;
    const std::string word = mLexer.readName();
    if (word == "NULL") {
        return nullptr;
    }
    const std::shared_ptr<FieldContainer> container = readContainerAfter(word, where);
    if (container->asNode() == nullptr) {
        mLexer.fail(where, "expected a node, got engine " + container->describe() +
                               " (engines appear only in connections: field = Engine { } . output)");
    }
    return std::static_pointer_cast<Node>(container);
}

void SceneParser::fail(const std::string& message) { mLexer.fail(mTokenStart, message); }

std::shared_ptr<FieldContainer> SceneParser::readContainerAfter(const std::string& word,
                                                                SourceLocation where) {
    if (word == "USE") {
        const SourceLocation nameAt = mLexer.location();
        const std::string name = mLexer.readName();
        if (name.empty()) {
            mLexer.fail(nameAt, "expected a name after USE, got " + mLexer.describeNext());
        }
        const auto found = mDefinitions.find(name);
        if (found == mDefinitions.end()) {
            mLexer.fail(nameAt, "USE of undefined name " + SceneLexer::quote(name));
        }
        return found->second;
    }
    if (word == "DEF") {
        const SourceLocation nameAt = mLexer.location();
        const std::string name = mLexer.readName();
        if (name.empty()) {
            mLexer.fail(nameAt, "expected a name after DEF, got " + mLexer.describeNext());
        }
        const SourceLocation typeAt = mLexer.location();
        return readInstance(readIdentifier("a node type name after DEF " + name), typeAt, name);
    }
    if (!isIdentifier(word)) {
        mLexer.fail(where, "expected a node type name, got " +
                               (word.empty() ? mLexer.describeNext() : SceneLexer::quote(word)));
    }
    return readInstance(word, where, "");
}

std::shared_ptr<FieldContainer> SceneParser::readInstance(const std::string& typeName,
                                                          SourceLocation where,
                                                          const std::string& defName) {
    if (mNesting >= kMaxNesting) {
        mLexer.fail(where, "nodes nested deeper than the limit of " +
                               std::to_string(kMaxNesting) + " levels");
    }
    struct NestingGuard {
        int& nesting;
        ~NestingGuard() { --nesting; }
    } guard{++mNesting};
    const SourceLocation brace = mLexer.location();
    if (!mLexer.consumeIf('{')) {
        mLexer.fail(brace, "expected '{' after " + typeName + ", got " + mLexer.describeNext());
    }
    const std::shared_ptr<FieldContainer> container = createInstance(typeName, where);
    if (Node* node = container->asNode()) {
        node->setSourceLocation(mSourceFile, static_cast<std::uint32_t>(where.line),
                                static_cast<std::uint32_t>(where.column));
    }
    if (!defName.empty()) {
        // `name+N` is how Inventor writers make repeated or missing names unique: the node's
        // own name is the part before '+'. "+N" (ours) and "_+N" (Coin's) mean it has none, and
        // so does a bare "_" (setName() reserves it: a second node named "_" would be written
        // as "_+N" and read back nameless).
        std::string name = defName.substr(0, defName.find('+'));
        if (name == "_") {
            name.clear();
        }
        try {
            container->setName(name);
        } catch (const DataError& error) {
            mLexer.fail(where, error.what());
        }
        // Defined before the body is read, so fields may connect from the node's own fields.
        mDefinitions[defName] = container;
    }
    readBody(*container, where);
    return container;
}

std::shared_ptr<FieldContainer> SceneParser::createInstance(const std::string& typeName,
                                                            SourceLocation where) {
    const std::optional<Description> fields = readDescription("fields");
    const std::optional<Description> inputs = readDescription("inputs");
    const std::optional<Description> outputs = readDescription("outputs");
    if (const NodeType* type = NodeRegistry::instance().find(typeName)) {
        if (type->isAbstract()) {
            mLexer.fail(where, "node type " + SceneLexer::quote(typeName) +
                                   " is abstract and cannot be read");
        }
        std::shared_ptr<FieldContainer> container = type->create();
        countInstance(*container);
        if (auto* files = dynamic_cast<RelativeFileNames*>(container.get())) {
            files->setBaseDirectory(mBaseDirectory);
            files->setDataRoots(mDataRoots);
        }
        for (const std::optional<Description>& description : {fields, inputs}) {
            if (description) {
                checkDescription(*container, *description, false);
            }
        }
        if (outputs) {
            checkDescription(*container, *outputs, true);
        }
        return container;
    }
    if (inputs || outputs) {
        mLexer.fail(where, "unknown engine type " + SceneLexer::quote(typeName) +
                               " (engines must be registered to be read)");
    }
    if (!fields) {
        mLexer.fail(where, "unknown node type " + SceneLexer::quote(typeName) +
                               " (not registered, and no 'fields [ ... ]' description follows)");
    }
    const UnknownNode::Ptr node = UnknownNode::create(typeName);
    countHeldBytes(sizeof(UnknownNode) + kInstanceOverheadBytes);
    for (const DescribedField& entry : *fields) {
        if (!UnknownNode::isDescribableFieldType(entry.type)) {
            mLexer.fail(entry.where, "unknown field type " + SceneLexer::quote(entry.type) +
                                         " for field " + SceneLexer::quote(entry.name) + " of " +
                                         typeName);
        }
        if (node->findField(entry.name) != nullptr) {
            mLexer.fail(entry.where,
                        "field " + SceneLexer::quote(entry.name) + " of " + typeName +
                            " is described twice");
        }
        node->addDescribedField(entry.type, entry.name);
    }
    return node;
}

std::optional<SceneParser::Description> SceneParser::readDescription(std::string_view keyword) {
    if (!mLexer.consumeKeywordBeforeList(keyword)) {
        return std::nullopt;
    }
    const SourceLocation opened = mLexer.location();
    mLexer.consumeIf('[');
    Description description;
    while (!mLexer.consumeIf(']')) {
        if (mLexer.isAtEnd()) {
            mLexer.fail(mLexer.location(), "expected ']' to close the " + std::string(keyword) +
                                               " description opened at " +
                                               SceneLexer::format(opened) + ", got end of file");
        }
        DescribedField entry;
        entry.where = mLexer.location();
        entry.type = readIdentifier("a field type in the " + std::string(keyword) + " description");
        entry.name = readIdentifier("a field name after " + entry.type);
        description.push_back(std::move(entry));
        mLexer.consumeIf(',');
    }
    return description;
}

void SceneParser::checkDescription(const FieldContainer& container,
                                   const Description& description, bool describesOutputs) {
    const auto* engine = dynamic_cast<const Engine*>(&container);
    for (const DescribedField& entry : description) {
        std::string_view actualType;
        if (describesOutputs) {
            const EngineOutputBase* output = engine != nullptr ? engine->findOutput(entry.name) : nullptr;
            actualType = output != nullptr ? output->typeName() : std::string_view();
        } else if (const Field* field = container.findField(entry.name)) {
            actualType = field->typeName();
        }
        if (actualType.empty()) {
            mLexer.fail(entry.where, container.typeName() + " has no " +
                                         (describesOutputs ? "output " : "field ") +
                                         SceneLexer::quote(entry.name) + " (described as " +
                                         entry.type + ")");
        }
        if (actualType != entry.type) {
            mLexer.fail(entry.where, "field " + SceneLexer::quote(entry.name) + " of " +
                                         container.typeName() +
                                         " is " + std::string(actualType) +
                                         ", but the description says " + entry.type);
        }
    }
}

void SceneParser::readBody(FieldContainer& container, SourceLocation opened) {
    auto* group = dynamic_cast<Group*>(container.asNode());
    while (true) {
        const SourceLocation where = mLexer.location();
        const char next = mLexer.peek();
        if (next == '}') {
            mLexer.consumeIf('}');
            return;
        }
        if (next == '\0') {
            mLexer.fail(where, "expected '}' to close " + container.typeName() + " opened at " +
                                   SceneLexer::format(opened));
        }
        const std::string word = mLexer.readName();
        if (word.empty()) {
            mLexer.fail(where, std::string("expected a field name") +
                                   (group != nullptr ? ", a child node" : "") + " or '}' in " +
                                   container.typeName() + ", got " + mLexer.describeNext());
        }
        if (Field* field = container.findField(word)) {
            readFieldEntry(*field);
            continue;
        }
        const bool isNode = word == "DEF" || word == "USE" || mLexer.peek() == '{';
        if (isNode && group == nullptr) {
            mLexer.fail(where, container.typeName() + " cannot have children, got " +
                                   SceneLexer::quote(word) +
                                   " (only groups such as Separator can)");
        }
        if (!isNode) {
            std::string known;
            for (const Field* field : container.fields()) {
                known += (known.empty() ? "" : ", ") + field->name();
            }
            mLexer.fail(where, "unknown field " + SceneLexer::quote(word) + " of " +
                                   container.typeName() +
                                   (known.empty() ? " (it has no fields)"
                                                  : " (fields: " + known + ")"));
        }
        const std::shared_ptr<FieldContainer> child = readContainerAfter(word, where);
        if (child->asNode() == nullptr) {
            mLexer.fail(where, "expected a node, got engine " + child->describe() +
                                   " (engines appear only in connections: field = Engine { } . output)");
        }
        try {
            group->addChild(std::static_pointer_cast<Node>(child));
        } catch (const DataError& error) {
            mLexer.fail(where, error.what());
        }
    }
}

void SceneParser::readFieldEntry(Field& field) {
    // Node values nest other field entries: restore the outer entry's context afterwards.
    const Field* outerField = mCurrentField;
    const std::optional<SourceLocation> outerList = mOpenList;
    const bool outerHasReadList = mHasReadList;
    mCurrentField = &field;
    mOpenList.reset();
    mHasReadList = false;
    if (mLexer.peek() != '=') {
        const SourceLocation valueAt = mLexer.location();
        mTokenStart = valueAt;
        try {
            auto* unknown = dynamic_cast<UnknownNode*>(field.container());
            if (unknown != nullptr && field.typeName() == "SFEnum") {
                unknown->setEnumValue(static_cast<SFEnum&>(field), readName());
            } else {
                field.readValue(*this);
            }
        } catch (const DataError& error) {
            mLexer.fail(valueAt, error.what());
        }
        countHeldBytes(field.heapBytes());
        checkNoExtraValue(field);
    }
    if (mLexer.consumeIf('=')) {
        readConnection(field);
    }
    mCurrentField = outerField;
    mOpenList = outerList;
    mHasReadList = outerHasReadList;
}

void SceneParser::readConnection(Field& field) {
    const SourceLocation sourceAt = mLexer.location();
    const std::shared_ptr<FieldContainer> source = readContainerAfter(mLexer.readName(), sourceAt);
    const SourceLocation dot = mLexer.location();
    if (!mLexer.consumeIf('.')) {
        mLexer.fail(dot, "expected '.' and a field or output name after the source of the "
                         "connection to " + field.fullName() + ", got " + mLexer.describeNext());
    }
    const SourceLocation nameAt = mLexer.location();
    const std::string name = readIdentifier("a field or output name after '.'");
    try {
        const auto* engine = dynamic_cast<const Engine*>(source.get());
        if (EngineOutputBase* output = engine != nullptr ? engine->findOutput(name) : nullptr) {
            field.connectFrom(*output);
        } else if (Field* sourceField = source->findField(name)) {
            field.connectFrom(*sourceField);
            // Whether anything else holds the source is known once the whole graph is read.
            mConnections.push_back(
                {&field, field.container()->shared_from_this(), source, sourceAt});
        } else {
            mLexer.fail(nameAt, source->describe() + " has no field or output " +
                                    SceneLexer::quote(name));
        }
    } catch (const DataError& error) {
        mLexer.fail(nameAt, error.what());
    }
}

void SceneParser::checkNoExtraValue(const Field& field) {
    if (!startsNumber(mLexer.peek()) && !isAnotherWordValue(field)) {
        return;
    }
    const bool isSingleMulti = field.typeName().substr(0, 2) == "MF" && !mHasReadList;
    mLexer.fail(mLexer.location(), "too many values for " + field.fullName() + " (" +
                                       std::string(field.typeName()) + "), got " +
                                       mLexer.describeNext() +
                                       (isSingleMulti ? " (put several values in [ ])" : ""));
}

bool SceneParser::isAnotherWordValue(const Field& field) {
    const std::string_view type = field.typeName();
    if (mLexer.peek() == '"') {
        return type == "SFString" || type == "MFString";
    }
    const std::string word = mLexer.peekWord();
    if (word.empty() || field.container()->findField(word) != nullptr) {
        return false;
    }
    if (type == "SFBool") {
        return word == "TRUE" || word == "FALSE";
    }
    const auto* enumField = dynamic_cast<const SFEnum*>(&field);
    return enumField != nullptr && enumField->enumNames() != nullptr &&
           enumField->enumNames()->value(word).has_value();
}

std::string SceneParser::readIdentifier(const std::string& what) {
    const SourceLocation where = mLexer.location();
    const std::string name = mLexer.readName();
    if (!isIdentifier(name)) {
        mLexer.fail(where, "expected " + what + ", got " +
                               (name.empty() ? mLexer.describeNext() : SceneLexer::quote(name)));
    }
    return name;
}

std::string SceneParser::valueWord(const std::string& what) {
    checkListNotTruncated();
    mTokenStart = mLexer.location();
    std::string word = mLexer.readWord();
    if (word.empty()) {
        failExpected(what, mLexer.describeNext());
    }
    return word;
}

void SceneParser::checkListNotTruncated() {
    if (mOpenList && mLexer.isAtEnd()) {
        mLexer.fail(mLexer.location(), "expected ']' to close the list opened at " +
                                           SceneLexer::format(*mOpenList) + ", got end of file");
    }
}

std::string SceneParser::fieldContext() const {
    if (mCurrentField == nullptr) {
        return "";
    }
    return " for " + mCurrentField->fullName() + " (" + std::string(mCurrentField->typeName()) +
           ")";
}

void SceneParser::failExpected(const std::string& what, const std::string& got) {
    fail("expected " + what + fieldContext() + ", got " + got);
}

} // namespace texsplat::sg::detail
