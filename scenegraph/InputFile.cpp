#include "scenegraph/InputFile.h"

#include "scenegraph/Error.h"

#include <filesystem>
#include <system_error>

namespace texsplat {

void requireRegularFile(const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_type type = fs::status(path, error).type();
    if (error && error != std::errc::no_such_file_or_directory) {
        // A loop of symbolic links, a path through a file, a folder that may not be searched:
        // opening would fail for the same reason, which the reader's own message would bury.
        throw IoError(path + ": cannot read " + what + ": " + error.message());
    }
    const char* kind = nullptr;
    switch (type) {
    case fs::file_type::directory:
        kind = "a folder";
        break;
    case fs::file_type::fifo:
        kind = "a FIFO";
        break;
    case fs::file_type::character:
        kind = "a character device";
        break;
    case fs::file_type::block:
        kind = "a block device";
        break;
    case fs::file_type::socket:
        kind = "a socket";
        break;
    default: // regular, missing or unknown: opening it says what is wrong
        return;
    }
    throw IoError(path + ": cannot read " + what + ": it is " + kind + ", not a regular file");
}

} // namespace texsplat
