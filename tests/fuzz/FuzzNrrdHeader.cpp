// libFuzzer target for the NRRD header parser: any input either parses or throws texsplat::Error
// (never crashes, hangs or trips a sanitizer); a header that parses describes a grid whose size
// fits in 64 bits, and written again as teem writes it (space directions in their order and
// sign, the origin at the first sample), parses back to the same layout.

#include "nodes/volume/NrrdHeader.h"
#include "nodes/volume/detail/Format.h"
#include "scenegraph/Error.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cmath>
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

// The file's first sample, where `space origin` puts it: the grid's origin moved back along the
// reversed axes.
glm::dvec3 firstSample(const NrrdHeader& header) {
    const bool vectors = header.layout.components == 3;
    glm::dvec3 origin = header.layout.origin;
    for (std::size_t axis = 0; axis + (vectors ? 1 : 0) < header.sizes.size(); ++axis) {
        const int world = header.gridAxis[int(axis)];
        if (header.reversed[int(axis)])
            origin[world] += double(header.sizes[axis + (vectors ? 1 : 0)] - 1) *
                             header.layout.spacing[world];
    }
    return origin;
}

// The header with its geometry as space directions and origin, as `unu make -dirs -orig` does.
std::string rewrite(const NrrdHeader& header, const glm::dvec3& origin) {
    const auto& layout = header.layout;
    const bool vectors = layout.components == 3;
    std::string directions = vectors ? "none" : "";
    const std::size_t spatialAxes = header.sizes.size() - (vectors ? 1 : 0);
    for (std::size_t axis = 0; axis < spatialAxes; ++axis) {
        const int along = header.gridAxis[int(axis)];
        const double length = (header.reversed[int(axis)] ? -1.0 : 1.0) * layout.spacing[along];
        std::string vector = "(";
        for (int world = 0; world < 3; ++world)
            vector += (world == 0 ? "" : ",") + formatNumber(world == along ? length : 0.0);
        directions += (directions.empty() ? "" : " ") + vector + ")";
    }
    return "NRRD0005\ntype: " + header.typeName +
           "\ndimension: " + std::to_string(header.sizes.size()) +
           "\nsizes: " + header.sizesText() + "\nendian: " +
           (layout.endian == texsplat::volume::RawEndian::Little ? "little" : "big") +
           "\nencoding: " + header.encodingName() + "\nspace dimension: 3\nspace directions: " +
           directions + "\nspace origin: (" + formatNumber(origin.x) + "," +
           formatNumber(origin.y) + "," + formatNumber(origin.z) + ")" +
           "\nbyte skip: " + std::to_string(header.byteSkip) +
           "\nline skip: " + std::to_string(header.lineSkip) +
           (header.dataFile.empty() ? std::string() : "\ndata file: " + header.dataFile) +
           "\n\n";
}

// Equal but for the rounding of moving an origin along reversed axes and back.
bool nearlyEqual(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& scale) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(std::abs(a[axis] - b[axis]) <= 1e-12 * scale[axis]))
            return false;
    return true;
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
    const glm::dvec3 origin = firstSample(header);
    if (!(std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(origin.z)))
        return 0; // a reversed axis at the edge of the double range; nothing to write back
    const std::string again = rewrite(header, origin);
    NrrdHeader reread;
    try {
        std::istringstream in(again);
        reread = NrrdHeader::parse(in, "rewritten.nrrd");
    } catch (const texsplat::Error& error) {
        fail(std::string("rewritten header does not parse back: ") + error.what(), again);
    }
    const auto& a = header.layout;
    const auto& b = reread.layout;
    const glm::dvec3 scale = glm::max(glm::max(glm::abs(a.origin), glm::abs(origin)),
                                      glm::dvec3(a.dims) * a.spacing) + 1.0;
    if (a.dims != b.dims || a.type != b.type || a.components != b.components ||
        a.endian != b.endian || a.spacing != b.spacing || !nearlyEqual(a.origin, b.origin, scale) ||
        header.gridAxis != reread.gridAxis || header.reversed != reread.reversed ||
        header.encoding != reread.encoding || header.byteSkip != reread.byteSkip ||
        header.lineSkip != reread.lineSkip || header.dataFile != reread.dataFile ||
        header.sizes != reread.sizes)
        fail("round trip changed the header", again);
    return 0;
}
