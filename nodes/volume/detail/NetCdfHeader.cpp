#include "nodes/volume/detail/NetCdfHeader.h"

#include "nodes/volume/detail/DeclaredSizes.h"
#include "nodes/volume/detail/Printable.h"
#include "scenegraph/MemoryLimit.h"

#include <cstdint>
#include <string>
#include <vector>

namespace texsplat::volume::detail {
namespace {

// The header's layout, from the NetCDF classic format specification ("The NetCDF Classic
// Format", NetCDF User's Guide): big-endian words; counts and lengths are 4 bytes in CDF-1 and
// CDF-2, 8 in CDF-5; lists start with a tag, or two zero words when absent.
constexpr std::uint64_t kDimensionTag = 0x0A;
constexpr std::uint64_t kVariableTag = 0x0B;
constexpr std::uint64_t kAttributeTag = 0x0C;

class HeaderWalk {
public:
    HeaderWalk(DeclaredSizes& file, int version) : mFile(file), mVersion(version) {}

    void walk() {
        std::uint64_t records = count("the record count");
        if (records == (mVersion == 5 ? ~std::uint64_t{0} : 0xffffffffu))
            records = 0; // streaming: libnetcdf counts the records from the file's size
        std::vector<std::uint64_t> dimensions;
        list(kDimensionTag, "the dimension list", [&] {
            name();
            dimensions.push_back(count("a dimension's length"));
        });
        attributes("the global attributes");
        list(kVariableTag, "the variable list", [&] {
            const std::string variable = name();
            const std::uint64_t axes = count("a variable's dimensions");
            mFile.sized(axes, mVersion == 5 ? 8 : 4, "its dimension ids");
            std::vector<std::uint64_t> ids;
            for (std::uint64_t i = 0; i < axes; ++i)
                ids.push_back(count("a variable's dimension id"));
            attributes("a variable's attributes");
            // libnetcdf divides by the size of the variable's type: an unknown type (size 0
            // there) stops the process with a floating-point exception.
            const std::uint64_t type = mFile.bigEndian(4, "a variable's type");
            if (type < 1 || type > (mVersion == 5 ? 11u : 6u))
                mFile.corrupt("a variable's type is " + std::to_string(type) + ", expected 1 to " +
                              (mVersion == 5 ? "11" : "6"));
            mFile.skip(mVersion == 5 ? 8 : 4, "a variable's size");
            const std::uint64_t begin = mFile.bigEndian(mVersion == 1 ? 4 : 8, "its offset");
            checkData(variable, begin, typeSize(type), ids, dimensions, records);
        });
    }

private:
    std::uint64_t count(const std::string& what) {
        return mFile.bigEndian(mVersion == 5 ? 8 : 4, what);
    }

    // Padded to a multiple of 4 bytes.
    static std::uint64_t padded(std::uint64_t bytes) { return (bytes + 3) / 4 * 4; }

    std::string name() {
        const std::uint64_t length = count("a name's length");
        std::string text = mFile.bytes(length, "a name");
        mFile.skip(padded(length) - length, "a name's padding");
        return text;
    }

    // A variable's values, from byte `begin` (its records: one in each record of the file, the
    // first at `begin`), must lie in the file: libnetcdf reads what lies beyond as fill values,
    // so a header of 400 bytes could declare gigabytes to read and convert.
    void checkData(const std::string& variable, std::uint64_t begin, std::uint64_t typeBytes,
                   const std::vector<std::uint64_t>& ids,
                   const std::vector<std::uint64_t>& dimensions, std::uint64_t records) const {
        std::uint64_t bytes = typeBytes;
        for (std::size_t axis = 0; axis < ids.size(); ++axis) {
            if (ids[axis] >= dimensions.size())
                return; // libnetcdf refuses it itself
            const bool isRecord = axis == 0 && dimensions[ids[axis]] == 0;
            bytes = byteProduct(bytes, isRecord ? records : dimensions[ids[axis]]);
        }
        const std::uint64_t end = mFile.offset() + mFile.left();
        if (begin > end || bytes > end - begin)
            mFile.corrupt("variable '" + printable(variable) + "' declares " +
                          std::to_string(bytes) + " bytes of values from byte " +
                          std::to_string(begin) + ", but the file ends at byte " +
                          std::to_string(end));
    }

    // A list of `tag` items: ABSENT (two zero words) or the tag, a count and the items; each item
    // takes at least 4 bytes, so the count is checked before walking them.
    template <typename Item> void list(std::uint64_t tag, const std::string& what, Item&& item) {
        const std::uint64_t found = mFile.bigEndian(4, what);
        const std::uint64_t items = count(what);
        if (found == 0 && items == 0)
            return;
        if (found != tag)
            mFile.corrupt(what + " has tag " + std::to_string(found) + ", expected " +
                          std::to_string(tag));
        mFile.sized(items, 4, what);
        for (std::uint64_t i = 0; i < items; ++i)
            item();
    }

    void attributes(const std::string& what) {
        list(kAttributeTag, what, [&] {
            name();
            const std::uint64_t type = mFile.bigEndian(4, "an attribute's type");
            const std::uint64_t values = count("an attribute's length");
            mFile.skip(padded(mFile.sized(values, typeSize(type), "an attribute's values")),
                       "an attribute's values");
        });
    }

    // Bytes of one value of an external type (NC_BYTE 1 ... NC_UINT64 11); 1 for an unknown type,
    // which libnetcdf refuses itself.
    static std::uint64_t typeSize(std::uint64_t type) {
        if (type == 3 || type == 8) // short, ushort
            return 2;
        if (type == 4 || type == 5 || type == 9) // int, float, uint
            return 4;
        if (type == 6 || type == 10 || type == 11) // double, int64, uint64
            return 8;
        return 1; // byte, char, ubyte
    }

    DeclaredSizes& mFile;
    int mVersion;
};

} // namespace

void checkNetCdfHeaderSizes(const std::string& path) {
    DeclaredSizes file(path, "truncated or corrupt NetCDF file");
    if (!file.startsWith("CDF"))
        return;
    const std::uint64_t version = file.bigEndian(1, "the format version");
    if (version == 1 || version == 2 || version == 5)
        HeaderWalk(file, int(version)).walk();
}

} // namespace texsplat::volume::detail
