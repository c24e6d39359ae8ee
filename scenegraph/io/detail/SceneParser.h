#pragma once

#include "scenegraph/SourceFiles.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/io/DataRoots.h"
#include "scenegraph/io/detail/ConnectionSources.h"
#include "scenegraph/io/detail/SceneLexer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace texsplat::sg::detail {

/// @brief The grammar of Inventor ASCII files: nodes, engines, DEF/USE, fields, field
/// descriptions and connections. Fields parse their own values through the FieldValueReader
/// interface this class implements; any error throws a located ParseError, and since the
/// graph is only returned at the end, a failed parse leaves nothing behind. Once the graph is
/// complete, field-to-field connections whose source nothing else holds are made to hold it
/// (keepUnheldSources()).
class SceneParser final : public FieldValueReader {
public:
    /// @brief Deepest nesting of nodes and engines a file may have. Each level costs a few
    /// stack frames of this recursive-descent parser; the limit keeps hostile input from
    /// exhausting the stack (also under AddressSanitizer) and leaves room below the actions'
    /// own limit, so everything read can be traversed.
    static constexpr int kMaxNesting = 1000;

    /// @brief A parser for `text`, which came from `fileName` (for messages). Nodes that read
    /// files (RelativeFileNames) get `baseDirectory` to resolve relative names against (empty
    /// leaves them resolving against the working directory) and `dataRoots` to confine them to.
    SceneParser(std::string_view text, std::string fileName, std::string baseDirectory = {},
                std::shared_ptr<const DataRoots> dataRoots = nullptr);

    /// @brief Parses the whole file: one top-level node is the result; several are put under
    /// a new Separator (as Inventor's SoDB::readAll does).
    std::shared_ptr<Node> parseFile();

    // FieldValueReader: what fields call to parse their values. Messages name the field being
    // read and point at the token.
    float readFloat() override;
    std::int32_t readInt32() override;
    std::string readString() override;
    std::string readName() override;
    bool readChar(char c) override;
    std::shared_ptr<Node> readNode() override;
    [[noreturn]] void fail(const std::string& message) override;

private:
    // One entry of a `fields [ … ]`, `inputs [ … ]` or `outputs [ … ]` description.
    struct DescribedField {
        std::string type;
        std::string name;
        SourceLocation where;
    };
    using Description = std::vector<DescribedField>;

    std::shared_ptr<FieldContainer> readContainerAfter(const std::string& word,
                                                       SourceLocation where);
    std::shared_ptr<FieldContainer> readInstance(const std::string& typeName,
                                                 SourceLocation where,
                                                 const std::string& defName);
    std::shared_ptr<FieldContainer> createInstance(const std::string& typeName,
                                                   SourceLocation where);
    std::optional<Description> readDescription(std::string_view keyword);
    void checkDescription(const FieldContainer& container, const Description& description,
                          bool describesOutputs);
    void readBody(FieldContainer& container, SourceLocation opened);
    void readFieldEntry(Field& field);
    void readConnection(Field& field);
    void checkNoExtraValue(const Field& field);
    bool isAnotherWordValue(const Field& field);
    std::string readIdentifier(const std::string& what);
    std::string valueWord(const std::string& what);
    void checkListNotTruncated();
    std::string fieldContext() const;
    [[noreturn]] void failExpected(const std::string& what, const std::string& got);
    // Counts `bytes` more that what the file made holds, and refuses a file whose nodes pass the
    // memory limit, at the token being read (asked once a kMemoryCheckBytes more are held).
    void countHeldBytes(std::uint64_t bytes);
    // countHeldBytes() of a node or engine just made: the instance, its shared pointer's count
    // and its field list.
    void countInstance(const FieldContainer& container);

    SourceFileId mSourceFile; // where the nodes read were, for Node::sourceLocation()
    SceneLexer mLexer;
    std::string mBaseDirectory;
    std::shared_ptr<const DataRoots> mDataRoots;
    std::map<std::string, std::shared_ptr<FieldContainer>, std::less<>> mDefinitions;
    std::vector<ReadConnection> mConnections;
    int mNesting = 0;
    const Field* mCurrentField = nullptr;
    SourceLocation mTokenStart;
    std::optional<SourceLocation> mOpenList;
    bool mHasReadList = false;
    std::uint64_t mHeldBytes = 0;       // the text and what was made of it, estimated
    std::uint64_t mNextMemoryCheck = 0; // when mHeldBytes reaches it
};

} // namespace texsplat::sg::detail
