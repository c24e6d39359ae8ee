// libFuzzer target for the NRRD header parser: any input either parses or throws texsplat::Error
// (never crashes, hangs or trips a sanitizer); a header that parses describes a grid whose size
// fits in 64 bits, and written again as teem writes it, parses back to the same layout.

#include "nodes/volume/NrrdHeader.h"
#include "nodes/volume/detail/Format.h"
#include "scenegraph/Error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

using texsplat::volume::NrrdHeader;
using texsplat::volume::detail::formatNumber;

[[noreturn]] void fail(const std::string& what, const std::string& text) {
    std::fprintf(stderr, "%s:\n%s\n", what.c_str(), text.c_str());
    std::abort();
}

// The header with its geometry as space directions and origin, as `unu make -dirs -orig` does.
std::string rewrite(const NrrdHeader& header) {
    const auto& layout = header.layout;
    const bool vectors = layout.components == 3;
    std::string directions = vectors ? "none" : "";
    const std::size_t spatialAxes = header.sizes.size() - (vectors ? 1 : 0);
    for (std::size_t axis = 0; axis < spatialAxes; ++axis) {
        std::string vector = "(";
        for (std::size_t world = 0; world < 3; ++world)
            vector += (world == 0 ? "" : ",") +
                      formatNumber(world == axis ? layout.spacing[int(axis)] : 0.0);
        directions += (directions.empty() ? "" : " ") + vector + ")";
    }
    return "NRRD0005\ntype: " + header.typeName +
           "\ndimension: " + std::to_string(header.sizes.size()) +
           "\nsizes: " + header.sizesText() +
           "\nendian: " +
           (layout.endian == texsplat::volume::RawEndian::Little ? "little" : "big") +
           "\nencoding: " + header.encodingName() + "\nspace dimension: 3\nspace directions: " +
           directions + "\nspace origin: (" + formatNumber(layout.origin.x) + "," +
           formatNumber(layout.origin.y) + "," + formatNumber(layout.origin.z) + ")" +
           "\nbyte skip: " + std::to_string(header.byteSkip) +
           "\nline skip: " + std::to_string(header.lineSkip) +
           (header.dataFile.empty() ? std::string() : "\ndata file: " + header.dataFile) +
           "\n\n";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    NrrdHeader header;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(text);
        header = NrrdHeader::parse(in, "fuzz.nrrd");
    } catch (const texsplat::Error&) {
        return 0;
    }
    if (header.dataOffset > static_cast<std::int64_t>(size))
        fail("data offset beyond the input", text);
    if (header.layout.dataBytes() <= 0 ||
        (header.layout.components != 1 && header.layout.components != 3))
        fail("parsed header describes no data", text);
    const std::string again = rewrite(header);
    NrrdHeader reread;
    try {
        std::istringstream in(again);
        reread = NrrdHeader::parse(in, "rewritten.nrrd");
    } catch (const texsplat::Error& error) {
        fail(std::string("rewritten header does not parse back: ") + error.what(), again);
    }
    const auto& a = header.layout;
    const auto& b = reread.layout;
    if (a.dims != b.dims || a.type != b.type || a.components != b.components ||
        a.endian != b.endian || a.spacing != b.spacing || a.origin != b.origin ||
        header.encoding != reread.encoding || header.byteSkip != reread.byteSkip ||
        header.lineSkip != reread.lineSkip || header.dataFile != reread.dataFile ||
        header.sizes != reread.sizes)
        fail("round trip changed the header", again);
    return 0;
}
