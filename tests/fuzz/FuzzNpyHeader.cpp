// libFuzzer target for the NumPy .npy header parser: any input either parses or throws
// texsplat::Error (never crashes, hangs or trips a sanitizer); a header that parses describes a
// grid whose size fits in 64 bits, and written again as numpy writes it, parses back the same.

#include "nodes/volume/NpyHeader.h"
#include "scenegraph/Error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "%s\n", what.c_str());
    std::abort();
}

// The header as numpy.save() writes it (format 1.0, padded to 64 bytes).
std::string rewrite(const texsplat::volume::NpyHeader& header) {
    std::string dict = "{'descr': '" + header.descr + "', 'fortran_order': " +
                       (header.fortranOrder ? "True" : "False") +
                       ", 'shape': " + header.shapeText() + ", }";
    while ((10 + dict.size() + 1) % 64 != 0)
        dict += ' ';
    dict += '\n';
    std::string bytes("\x93NUMPY\x01\x00", 8);
    bytes += static_cast<char>(dict.size() & 0xff);
    bytes += static_cast<char>((dict.size() >> 8) & 0xff);
    return bytes + dict;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using texsplat::volume::NpyHeader;
    NpyHeader header;
    try {
        std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
        header = NpyHeader::parse(in, "fuzz.npy");
    } catch (const texsplat::Error&) {
        return 0;
    }
    if (header.dataOffset > static_cast<std::int64_t>(size))
        fail("data offset beyond the input");
    if (header.layout.dataBytes() <= 0 ||
        (header.layout.components != 1 && header.layout.components != 3))
        fail("parsed header describes no data");
    const std::string again = rewrite(header);
    std::istringstream in(again);
    NpyHeader reread;
    try {
        reread = NpyHeader::parse(in, "rewritten.npy");
    } catch (const texsplat::Error& error) {
        fail(std::string("rewritten header does not parse back: ") + error.what() + "\n" + again);
    }
    if (reread.descr != header.descr || reread.fortranOrder != header.fortranOrder ||
        reread.shape != header.shape || reread.layout.dims != header.layout.dims ||
        reread.layout.type != header.layout.type || reread.layout.endian != header.layout.endian)
        fail("round trip changed the header:\n" + again);
    return 0;
}
