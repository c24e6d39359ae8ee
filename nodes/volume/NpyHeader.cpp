#include "nodes/volume/NpyHeader.h"

#include "nodes/volume/GridGeometry.h"
#include "nodes/volume/detail/Printable.h"
#include "scenegraph/Error.h"

#include <cctype>
#include <limits>
#include <string_view>

namespace texsplat::volume {
namespace {

using detail::printable;

constexpr std::string_view kMagic = "\x93NUMPY";
// numpy itself refuses headers over 10000 bytes unless told otherwise; a longer one is not an
// array header we could read.
constexpr std::uint32_t kMaxHeaderBytes = 65536;
constexpr int kMaxAxes = 4;

// One value of the header's dict literal.
struct Value {
    enum class Kind { String, Bool, Tuple } kind = Kind::String;
    std::string text;
    bool flag = false;
    std::vector<std::int64_t> numbers;
};

// A recursive-descent reader of the one dict literal numpy writes; positions in messages count
// characters of the header (1-based).
class DictReader {
public:
    DictReader(std::string_view text, const std::string& source) : mText(text), mSource(source) {}

    [[noreturn]] void fail(const std::string& what) const { fail(mPosition, what); }
    [[noreturn]] void fail(std::size_t position, const std::string& what) const {
        throw ParseError(mSource + ": .npy header, character " + std::to_string(position + 1) +
                         ": " + what);
    }

    void skipBlanks() {
        while (mPosition < mText.size() &&
               (mText[mPosition] == ' ' || mText[mPosition] == '\t' || mText[mPosition] == '\n' ||
                mText[mPosition] == '\r'))
            ++mPosition;
    }
    bool atEnd() const { return mPosition >= mText.size(); }
    std::size_t position() const { return mPosition; }

    // What stands at the current position, for "found ..." in messages.
    std::string found() const {
        if (atEnd())
            return "the end of the header";
        return "'" + printable(mText.substr(mPosition, 1)) + "'";
    }

    bool accept(char c) {
        skipBlanks();
        if (!atEnd() && mText[mPosition] == c) {
            ++mPosition;
            return true;
        }
        return false;
    }
    void expect(char c, const std::string& what) {
        if (!accept(c))
            fail("expected " + what + ", found " + found());
    }

    std::string readString() {
        skipBlanks();
        if (atEnd() || (mText[mPosition] != '\'' && mText[mPosition] != '"'))
            fail("expected a quoted string, found " + found());
        const char quote = mText[mPosition];
        const std::size_t start = ++mPosition;
        while (mPosition < mText.size() && mText[mPosition] != quote) {
            if (mText[mPosition] == '\\')
                fail("escapes in strings are not supported");
            ++mPosition;
        }
        if (atEnd())
            fail(start - 1, "string is not closed");
        return std::string(mText.substr(start, mPosition++ - start));
    }

    std::int64_t readInteger() {
        skipBlanks();
        const std::size_t start = mPosition;
        std::int64_t value = 0;
        while (mPosition < mText.size() &&
               std::isdigit(static_cast<unsigned char>(mText[mPosition])) != 0) {
            const int digit = mText[mPosition] - '0';
            if (value > (std::numeric_limits<std::int64_t>::max() - digit) / 10)
                fail(start, "axis length does not fit in 64 bits");
            value = value * 10 + digit;
            ++mPosition;
        }
        if (mPosition == start)
            fail("expected an axis length (a whole number), found " + found());
        if (mPosition < mText.size() && mText[mPosition] == 'L') // Python 2's long integers
            ++mPosition;
        return value;
    }

    Value readValue() {
        skipBlanks();
        Value value;
        if (atEnd())
            fail("expected a value, found the end of the header");
        const char c = mText[mPosition];
        if (c == '\'' || c == '"') {
            value.kind = Value::Kind::String;
            value.text = readString();
        } else if (c == '(') {
            ++mPosition;
            value.kind = Value::Kind::Tuple;
            if (!accept(')')) {
                do {
                    skipBlanks();
                    if (!atEnd() && mText[mPosition] == ')')
                        break; // a trailing comma: (64,)
                    if (value.numbers.size() == kMaxAxes + 1)
                        fail("shape has more than " + std::to_string(kMaxAxes + 1) + " axes");
                    value.numbers.push_back(readInteger());
                } while (accept(','));
                expect(')', "',' or ')' in the shape");
            }
        } else if (mText.substr(mPosition, 4) == "True" || mText.substr(mPosition, 5) == "False") {
            value.kind = Value::Kind::Bool;
            value.flag = mText[mPosition] == 'T';
            mPosition += value.flag ? 4 : 5;
        } else {
            fail("expected a string, True, False or a tuple, found " + found());
        }
        return value;
    }

private:
    std::string_view mText;
    const std::string& mSource;
    std::size_t mPosition = 0;
};

std::uint32_t littleEndian(const unsigned char* bytes, int count) {
    std::uint32_t value = 0;
    for (int i = count - 1; i >= 0; --i)
        value = (value << 8) | bytes[i];
    return value;
}

} // namespace

void parseNpyDescr(const std::string& descr, const std::string& source, RawHeader& layout) {
    const auto unsupported = [&] {
        return DataError(source + ": data type '" + printable(descr) +
                         "' is not supported; expected <f4, <f8, |u1, |i1, <u2, <i2, <u4 or <i4 "
                         "(or > for big endian)");
    };
    if (descr.size() != 3)
        throw unsupported();
    const char order = descr[0];
    const std::string kind = descr.substr(1);
    struct Known {
        const char* name;
        RawValueType type;
    };
    constexpr Known kKnown[] = {{"f4", RawValueType::Float32}, {"f8", RawValueType::Float64},
                                {"u1", RawValueType::UInt8},   {"i1", RawValueType::Int8},
                                {"u2", RawValueType::UInt16},  {"i2", RawValueType::Int16},
                                {"u4", RawValueType::UInt32},  {"i4", RawValueType::Int32}};
    for (const Known& known : kKnown) {
        if (kind != known.name)
            continue;
        const bool oneByte = bytesPerValue(known.type) == 1;
        // '|' (no byte order) is what numpy writes for single bytes; '=' is the writer's order.
        if (order == '<' || (order == '|' && oneByte))
            layout.endian = RawEndian::Little;
        else if (order == '>')
            layout.endian = RawEndian::Big;
        else if (order == '=')
            layout.endian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? RawEndian::Little
                                                                      : RawEndian::Big;
        else
            throw unsupported();
        layout.type = known.type;
        return;
    }
    throw unsupported();
}

std::string npyShapeText(const std::vector<std::int64_t>& shape) {
    std::string text = "(";
    for (std::size_t i = 0; i < shape.size(); ++i)
        text += (i == 0 ? "" : ", ") + std::to_string(shape[i]);
    return text + (shape.size() == 1 ? ",)" : ")");
}

NpyHeader NpyHeader::parse(std::istream& in, const std::string& source) {
    unsigned char start[8] = {};
    in.read(reinterpret_cast<char*>(start), sizeof start);
    const std::string_view magic(reinterpret_cast<const char*>(start),
                                 static_cast<std::size_t>(in.gcount()));
    if (magic.substr(0, kMagic.size()) != kMagic || in.gcount() < 8)
        throw ParseError(source + ": not a NumPy .npy file: expected it to start with the bytes "
                                  "\\x93NUMPY and a format version");
    NpyHeader header;
    header.majorVersion = start[6];
    if (header.majorVersion < 1 || header.majorVersion > 3)
        throw ParseError(source + ": unsupported .npy format version " +
                         std::to_string(start[6]) + "." + std::to_string(start[7]) +
                         "; this reader reads versions 1, 2 and 3");
    const int lengthBytes = header.majorVersion == 1 ? 2 : 4;
    unsigned char lengthField[4] = {};
    in.read(reinterpret_cast<char*>(lengthField), lengthBytes);
    if (in.gcount() != lengthBytes)
        throw ParseError(source + ": .npy file ends inside its header length");
    const std::uint32_t length = littleEndian(lengthField, lengthBytes);
    if (length > kMaxHeaderBytes)
        throw ParseError(source + ": .npy header length " + std::to_string(length) +
                         " is more than " + std::to_string(kMaxHeaderBytes) +
                         " bytes; is this a NumPy .npy file?");
    std::string text(length, '\0');
    in.read(text.data(), static_cast<std::streamsize>(length));
    if (static_cast<std::uint32_t>(in.gcount()) != length)
        throw ParseError(source + ": .npy file ends inside its header: the header is " +
                         std::to_string(length) + " bytes long, but only " +
                         std::to_string(in.gcount()) + " follow");
    header.dataOffset = 8 + lengthBytes + std::int64_t{length};

    DictReader reader(text, source);
    reader.expect('{', "'{' starting the header's dict");
    bool hasDescr = false;
    bool hasOrder = false;
    bool hasShape = false;
    while (!reader.accept('}')) {
        const std::size_t keyPosition = (reader.skipBlanks(), reader.position());
        const std::string key = reader.readString();
        bool* seen = key == "descr"           ? &hasDescr
                     : key == "fortran_order" ? &hasOrder
                     : key == "shape"         ? &hasShape
                                              : nullptr;
        if (seen == nullptr)
            reader.fail(keyPosition, "unknown key '" + printable(key) +
                                         "'; expected 'descr', 'fortran_order' and 'shape'");
        if (*seen)
            reader.fail(keyPosition, "duplicate key '" + key + "'");
        *seen = true;
        reader.expect(':', "':' after the key '" + key + "'");
        const std::size_t valuePosition = (reader.skipBlanks(), reader.position());
        const Value value = reader.readValue();
        const auto expectKind = [&](Value::Kind kind, const char* what) {
            if (value.kind != kind)
                reader.fail(valuePosition, "'" + key + "' must be " + what);
        };
        if (key == "descr") {
            if (value.kind == Value::Kind::Tuple)
                reader.fail(valuePosition, "'descr' must be a string; structured arrays are not "
                                           "supported");
            expectKind(Value::Kind::String, "a string");
            header.descr = value.text;
        } else if (key == "fortran_order") {
            expectKind(Value::Kind::Bool, "True or False");
            header.fortranOrder = value.flag;
        } else {
            expectKind(Value::Kind::Tuple, "a tuple of axis lengths");
            header.shape = value.numbers;
        }
        if (!reader.accept(',')) {
            reader.expect('}', "',' or '}' after the value of '" + key + "'");
            break;
        }
    }
    reader.skipBlanks();
    if (!reader.atEnd())
        reader.fail("expected the end of the header after '}', found " + reader.found());
    for (const auto& [present, key] : {std::pair{hasDescr, "descr"},
                                       std::pair{hasOrder, "fortran_order"},
                                       std::pair{hasShape, "shape"}})
        if (!present)
            throw ParseError(source + ": .npy header has no '" + key + "'");

    parseNpyDescr(header.descr, source, header.layout);
    const std::size_t axes = header.shape.size();
    const bool vectors = axes == 4 && header.shape[3] == 3;
    if (axes == 0 || axes > 4 || (axes == 4 && !vectors))
        throw DataError(source + ": array of shape " + header.shapeText() +
                        " is not supported; expected (x), (y, x), (z, y, x) or (z, y, x, 3)");
    header.layout.components = vectors ? 3 : 1;
    const std::size_t gridAxes = vectors ? 3 : axes;
    glm::i64vec3 dims(1);
    for (std::size_t i = 0; i < gridAxes; ++i)
        dims[static_cast<int>(i)] = header.shape[gridAxes - 1 - i];
    try {
        static_cast<void>(GridGeometry(dims));
        header.layout.dims = dims;
        static_cast<void>(header.layout.dataBytes());
    } catch (const DataError& error) {
        throw DataError(source + ": array of shape " + header.shapeText() + ": " + error.what());
    }
    return header;
}

} // namespace texsplat::volume
