// libFuzzer target for the NetCDF reader as texsplat calls it (listNetCdfVariables, then
// readNetCdfVariable for each volume listed): any input either reads or throws a texsplat::Error
// naming the file, never crashes, trips a sanitizer or allocates beyond the memory limit.

#include "nodes/volume/NetCdfVolume.h"
#include "tests/fuzz/FuzzFileReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace texsplat::volume;
    static const texsplat::fuzz::FuzzInputFile file("fuzz.nc");
    const std::string& path = file.write(data, size);
    texsplat::fuzz::expectReadOrLocatedError(file, [&] {
        for (const NetCdfVariableInfo& variable : listNetCdfVariables(path)) {
            if (variable.isVolume())
                texsplat::fuzz::expectReadOrLocatedError(
                    file, [&] { readNetCdfVariable(path, variable.name); });
        }
    });
    return 0;
}
