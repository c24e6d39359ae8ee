#include "nodes/kernel/detail/AtomicFile.h"

#include "scenegraph/Error.h"

#include <cstdio>
#include <fstream>

namespace texsplat::kernel::detail {

void writeFileAtomically(const std::string& path, const std::string& contents) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream file(temporary, std::ios::binary);
        if (!file)
            throw IoError(path + ": cannot open for writing");
        file.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        if (!file.flush()) {
            file.close();
            std::remove(temporary.c_str());
            throw IoError(path + ": write failed");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw IoError(path + ": cannot rename the temporary file into place");
    }
}

} // namespace texsplat::kernel::detail
