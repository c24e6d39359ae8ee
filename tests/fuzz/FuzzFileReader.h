#pragma once

/// @file
/// @brief What the fuzz targets of file readers share: readers that take a path get the input as
/// a file, under a memory limit low enough that a refusal happens before the fuzzer's RSS limit,
/// and every error they throw must be a texsplat::Error that names that file.

#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace texsplat::fuzz {

/// @brief The memory limit of every file reader target: readers must refuse what would need more,
/// well below the 2 GiB that scripts/fuzz.sh gives libFuzzer (-rss_limit_mb) under ASan.
constexpr std::uint64_t kFuzzMemoryLimit = std::uint64_t{256} << 20;

/// @brief A folder of this process's own that holds the input as one file, replaced by each run
/// and removed at exit.
class FuzzInputFile {
public:
    /// @brief `name` is the file's name, whose extension tells the reader the format.
    explicit FuzzInputFile(const std::string& name) {
        setMemoryLimit(kFuzzMemoryLimit);
        std::string folder =
            (std::filesystem::temp_directory_path() / "texsplat-fuzz-XXXXXX").string();
        if (mkdtemp(folder.data()) == nullptr) {
            std::perror("mkdtemp");
            std::abort();
        }
        mFolder = folder;
        mPath = (mFolder / name).string();
    }
    FuzzInputFile(const FuzzInputFile&) = delete;
    FuzzInputFile& operator=(const FuzzInputFile&) = delete;
    ~FuzzInputFile() {
        std::error_code ignored;
        std::filesystem::remove_all(mFolder, ignored);
    }

    /// @brief Writes `data` as the file and answers its path.
    const std::string& write(const std::uint8_t* data, std::size_t size) const {
        std::ofstream(mPath, std::ios::binary | std::ios::trunc)
            .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        return mPath;
    }

    const std::string& path() const { return mPath; }

private:
    std::filesystem::path mFolder;
    std::string mPath;
};

/// @brief Runs `read` (a reader on `file`): it may succeed or throw a texsplat::Error whose
/// message names the file; anything else (another exception, a message that does not say which
/// file) is a finding, reported with the message and aborted on.
template <typename Read> void expectReadOrLocatedError(const FuzzInputFile& file, Read&& read) {
    try {
        read();
    } catch (const texsplat::Error& error) {
        const std::string message = error.what();
        if (message.find(file.path()) == std::string::npos) {
            std::fprintf(stderr, "error does not name the file %s: %s\n", file.path().c_str(),
                         message.c_str());
            std::abort();
        }
    }
}

} // namespace texsplat::fuzz
