#pragma once

// The text layer of the NRRD header parser (NrrdHeader): lines with their byte count, and the
// words and vectors of a field's value with their columns, for located messages.

#include "nodes/volume/detail/Printable.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::volume::detail {

/// @brief The longest header line read; a longer one is not NRRD text.
constexpr std::size_t kMaxNrrdLineLength = 8192;
/// @brief The longest header read: far beyond any real one (teem writes a few hundred bytes),
/// it bounds the work on garbage.
constexpr std::int64_t kMaxNrrdHeaderBytes = std::int64_t{1} << 20;

/// @brief Where a value stands in the header (1-based line and column), for messages.
struct NrrdPlace {
    int line = 0;
    int column = 0;
};

/// @brief Reads a header line by line, counting the bytes it consumed (where attached data
/// start).
class NrrdLineReader {
public:
    /// @brief Reads from `in`; `source` names the file in messages.
    NrrdLineReader(std::istream& in, const std::string& source) : mIn(in), mSource(source) {}

    /// @brief The next line, without its line end, into `text`; false at the end of input.
    /// @throws ParseError for a line or header too long to be NRRD text.
    bool next(std::string& text) {
        text.clear();
        char c = 0;
        bool any = false;
        while (mIn.get(c)) {
            any = true;
            ++mConsumed;
            if (c == '\n')
                break;
            if (text.size() == kMaxNrrdLineLength)
                throw ParseError(where({mLine + 1, 1}) + "header line longer than " +
                                 std::to_string(kMaxNrrdLineLength) +
                                 " characters; is this a NRRD file?");
            text += c;
        }
        if (!any)
            return false;
        if (mConsumed > kMaxNrrdHeaderBytes)
            throw ParseError(where({mLine + 1, 1}) + "NRRD header longer than " +
                             std::to_string(kMaxNrrdHeaderBytes) + " bytes; is this a NRRD file?");
        if (!text.empty() && text.back() == '\r')
            text.pop_back();
        ++mLine;
        return true;
    }

    /// @brief "<source>:<line>:<column>: ", the start of a message.
    std::string where(NrrdPlace place) const {
        return mSource + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) +
               ": ";
    }
    /// @brief The number of the line read last.
    int line() const { return mLine; }
    /// @brief Bytes consumed so far, the magic bytes counted by countMagic() included.
    std::int64_t consumed() const { return mConsumed; }
    /// @brief Counts `bytes` read from the stream before the first line (the magic).
    void countMagic(std::int64_t bytes) { mConsumed += bytes; }

private:
    std::istream& mIn;
    const std::string& mSource;
    int mLine = 0;
    std::int64_t mConsumed = 0;
};

/// @brief A field's value as words and parenthesized vectors, each knowing its column.
class NrrdValueScanner {
public:
    /// @brief Scans `text`, which starts at `firstColumn` of line `line` of `reader`'s header.
    NrrdValueScanner(std::string_view text, int firstColumn, const NrrdLineReader& reader,
                     int line)
        : mText(text), mFirstColumn(firstColumn), mReader(reader), mLine(line) {}

    /// @brief Whether only blanks are left.
    bool atEnd() {
        skipBlanks();
        return mPosition >= mText.size();
    }
    /// @brief Where the scan stands.
    NrrdPlace place() const { return {mLine, mFirstColumn + static_cast<int>(mPosition)}; }
    /// @brief Throws ParseError "<where>: <what>".
    [[noreturn]] void fail(NrrdPlace at, const std::string& what) const {
        throw ParseError(mReader.where(at) + what);
    }

    /// @brief The next blank-separated word; empty at the end.
    std::string word() {
        skipBlanks();
        const std::size_t start = mPosition;
        while (mPosition < mText.size() && mText[mPosition] != ' ' && mText[mPosition] != '\t')
            ++mPosition;
        return std::string(mText.substr(start, mPosition - start));
    }

    /// @brief The words left, joined by one blank each ("unsigned short int").
    std::string words() {
        std::string joined = word();
        for (std::string next = word(); !next.empty(); next = word())
            joined += " " + next;
        return joined;
    }

    /// @brief The next word as a `Number`.
    /// @throws ParseError "expected <kind> in '<field>', found '...'".
    template <typename Number> Number number(const std::string& field, const char* kind) {
        skipBlanks();
        const NrrdPlace at = place();
        const std::string text = word();
        Number value{};
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc() || end != text.data() + text.size())
            fail(at, "expected " + std::string(kind) + " in '" + field + "', found " +
                         (text.empty() ? std::string("nothing") : "'" + printable(text) + "'"));
        return value;
    }

    /// @brief The next vector: "(1,0,0)" gives {1, 0, 0}, "none" nullopt.
    /// @throws ParseError for anything else.
    std::optional<std::vector<double>> vector(const std::string& field) {
        skipBlanks();
        const NrrdPlace at = place();
        if (mText.substr(mPosition, 4) == "none") {
            mPosition += 4;
            return std::nullopt;
        }
        if (mPosition >= mText.size() || mText[mPosition] != '(')
            fail(at, "expected a vector '(x,y,z)' or 'none' in '" + field + "', found " +
                         (mPosition >= mText.size() ? std::string("nothing")
                                                    : "'" + printable(word()) + "'"));
        const std::size_t close = mText.find(')', mPosition);
        if (close == std::string_view::npos)
            fail(at, "vector in '" + field + "' is not closed with ')'");
        std::vector<double> values;
        std::string_view inside = mText.substr(mPosition + 1, close - mPosition - 1);
        mPosition = close + 1;
        while (true) {
            const std::size_t comma = std::min(inside.find(','), inside.size());
            std::string_view item = inside.substr(0, comma);
            while (!item.empty() && (item.front() == ' ' || item.front() == '\t'))
                item.remove_prefix(1);
            while (!item.empty() && (item.back() == ' ' || item.back() == '\t'))
                item.remove_suffix(1);
            double value = 0.0;
            const char* last = item.data() + item.size();
            const auto [end, error] = std::from_chars(item.data(), last, value);
            if (item.empty() || error != std::errc() || end != last)
                fail(at, "expected numbers in the vector of '" + field + "', found '" +
                             printable(item) + "'");
            values.push_back(value);
            if (comma == inside.size())
                break;
            inside.remove_prefix(comma + 1);
        }
        return values;
    }

private:
    void skipBlanks() {
        while (mPosition < mText.size() && (mText[mPosition] == ' ' || mText[mPosition] == '\t'))
            ++mPosition;
    }

    std::string_view mText;
    int mFirstColumn;
    const NrrdLineReader& mReader;
    int mLine;
    std::size_t mPosition = 0;
};

} // namespace texsplat::volume::detail
