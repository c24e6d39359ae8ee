// libFuzzer target for the glTF reader as Mesh calls it (readGltf: the nesting-depth guard, then
// tinygltf, then our accessor checks): an input starting with "glTF" is read as a .glb, any other
// as a .gltf; either reads or throws a texsplat::Error naming the file, never crashes, trips a
// sanitizer or allocates beyond the memory limit.

#include "nodes/detail/GltfReader.h"
#include "tests/fuzz/FuzzFileReader.h"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const texsplat::fuzz::FuzzInputFile text("fuzz.gltf");
    static const texsplat::fuzz::FuzzInputFile binary("fuzz.glb");
    const bool isBinary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const texsplat::fuzz::FuzzInputFile& file = isBinary ? binary : text;
    const std::string& path = file.write(data, size);
    texsplat::fuzz::expectReadOrLocatedError(file,
                                             [&] { texsplat::nodes::detail::readGltf(path); });
    return 0;
}
