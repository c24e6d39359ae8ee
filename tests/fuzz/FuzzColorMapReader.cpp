// libFuzzer target for the reader of ParaView colour-map JSON files (TransferFunction's
// colorMapFile): any input either parses or throws texsplat::Error (never crashes, overflows the
// stack on deep nesting, hangs or trips a sanitizer); a map that parses has as many colours as
// positions, at least one, positions in [0, 1] that do not decrease, and colour components in
// [0, 1].

#include "nodes/colormap/ParaViewColorMap.h"
#include "scenegraph/Error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void fail(const char* what, const std::string& text) {
    std::fprintf(stderr, "%s:\n%s\n", what, text.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    texsplat::colormap::ParaViewColorMap map;
    try {
        map = texsplat::colormap::parseParaViewColorMap(text, "fuzz.json");
    } catch (const texsplat::Error&) {
        return 0;
    }
    if (map.positions.empty() || map.positions.size() != map.colors.size())
        fail("a parsed map has no points, or positions and colours differ in number", text);
    for (std::size_t i = 0; i < map.positions.size(); ++i) {
        const float t = map.positions[i];
        if (!(t >= 0.0f && t <= 1.0f) || (i > 0 && t < map.positions[i - 1]))
            fail("a position outside [0, 1] or decreasing", text);
        for (int c = 0; c < 3; ++c)
            if (!(map.colors[i][c] >= 0.0f && map.colors[i][c] <= 1.0f))
                fail("a colour component outside [0, 1]", text);
    }
    return 0;
}
