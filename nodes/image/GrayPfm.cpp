#include "nodes/image/GrayPfm.h"

#include "scenegraph/AtomicFile.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace texsplat::image {

void writeGrayPfm(const std::string& path, int width, int height, const std::vector<float>& gray) {
    // A negative scale declares little-endian floats.
    std::string contents =
        "Pf\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    contents.reserve(contents.size() + gray.size() * sizeof(float));
    for (const float value : gray) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &value, sizeof(bits));
        for (int shift = 0; shift < 32; shift += 8) {
            contents.push_back(static_cast<char>((bits >> shift) & 0xffu));
        }
    }
    writeFileAtomically(path, contents);
}

} // namespace texsplat::image
