// libFuzzer target for the OpenVDB reader as texsplat calls it (listVdbGrids, then readVdbGrid
// for each grid listed): any input either reads or throws a texsplat::Error naming the file,
// never crashes, trips a sanitizer or allocates beyond the memory limit (kFuzzMemoryLimit).

#include "nodes/volume/VdbVolume.h"
#include "tests/fuzz/FuzzFileReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace texsplat::volume;
    static const texsplat::fuzz::FuzzInputFile file("fuzz.vdb");
    const std::string& path = file.write(data, size);
    texsplat::fuzz::expectReadOrLocatedError(file, [&] {
        for (const VdbGridInfo& grid : listVdbGrids(path))
            texsplat::fuzz::expectReadOrLocatedError(file,
                                                     [&] { readVdbGrid(path, grid.name); });
    });
    return 0;
}
