// libFuzzer target for image reading as `texsplat compare` reads images (readImage: the regular
// file check, the header's size against the pixel and memory limits, then decoding), built once
// per format with TEXSPLAT_FUZZ_IMAGE_NAME naming the file (its extension picks the decoder): any
// input either decodes or throws a texsplat::Error naming the file, never crashes, trips a
// sanitizer or allocates beyond the memory limit.

#include "nodes/image/ImageIo.h"
#include "tests/fuzz/FuzzFileReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const texsplat::fuzz::FuzzInputFile file(TEXSPLAT_FUZZ_IMAGE_NAME);
    const std::string& path = file.write(data, size);
    texsplat::fuzz::expectReadOrLocatedError(file, [&] { texsplat::image::readImage(path); });
    return 0;
}
