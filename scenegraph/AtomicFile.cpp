#include "scenegraph/AtomicFile.h"

#include "scenegraph/Error.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace texsplat {
namespace {

std::string directoryOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

/// Creates a new, empty file next to `path` and returns its name. O_EXCL makes the name ours
/// alone; mode 0666 lets the umask decide the final permissions, as for any new file.
std::string createTemporarySibling(const std::string& path) {
    static std::atomic<unsigned> sCounter{0};
    const auto slash = path.find_last_of('/');
    const std::string prefix = slash == std::string::npos ? std::string()
                                                          : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string candidate = prefix + "." + name + ".tmp" + std::to_string(getpid()) +
                                      "-" + std::to_string(sCounter++);
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return candidate;
        }
        if (errno != EEXIST)
            throw IoError(path + ": cannot create a file in directory " + directoryOf(path) +
                          ": " + std::strerror(errno));
    }
    throw IoError(path + ": cannot find an unused temporary name in " + directoryOf(path));
}

/// Flushes the file's data to the device before the rename, so that after a crash the name
/// points either at the old contents or at the complete new ones.
bool syncToDisk(const std::string& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    const bool synced = ::fsync(fd) == 0;
    ::close(fd);
    return synced;
}

/// The file a write to `path` means: `path` itself, or for a symbolic link the file it points
/// to (through every link), which need not exist yet. Renaming over the link itself would
/// replace it with a plain file.
std::string throughLinks(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path file = path;
    std::error_code error;
    // As many links as the system follows (a loop fails there, and so then in open()).
    for (int hop = 0; hop < 40 && fs::is_symlink(file, error); ++hop) {
        const fs::path target = fs::read_symlink(file, error);
        if (error)
            break;
        file = target.is_absolute() ? target : file.parent_path() / target;
    }
    return file.string();
}

} // namespace

void writeFileAtomically(const std::string& givenPath,
                         const std::function<void(std::ofstream& stream)>& write) {
    const std::string path = throughLinks(givenPath);
    const std::string temporary = createTemporarySibling(path);
    try {
        std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
        if (!stream)
            throw IoError(path + ": cannot open " + temporary + " for writing");
        write(stream);
        stream.close();
        if (!stream)
            throw IoError(path + ": write failed (disk full?)");
        if (!syncToDisk(temporary))
            throw IoError(path + ": cannot flush to disk: " + std::strerror(errno));
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            throw IoError(path + ": cannot replace the file: " + std::strerror(errno));
    } catch (const Error&) {
        std::remove(temporary.c_str());
        throw;
    } catch (const std::exception& e) {
        std::remove(temporary.c_str());
        throw IoError(path + ": " + e.what());
    }
}

void requireWritableFile(const std::string& givenPath, const std::string& what) {
    namespace fs = std::filesystem;
    const std::string path = throughLinks(givenPath);
    const std::string folder = directoryOf(path);
    const auto refuse = [&](const std::string& reason) {
        throw IoError(givenPath + ": cannot write " + what + ": " + reason);
    };
    std::error_code error;
    if (fs::is_directory(path, error))
        refuse("it is a folder");
    const fs::file_status folderStatus = fs::status(folder, error);
    if (folderStatus.type() == fs::file_type::not_found)
        refuse("folder '" + folder + "' does not exist");
    if (folderStatus.type() != fs::file_type::directory)
        refuse("'" + folder + "' is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        refuse("folder '" + folder + "' is not writable (" + std::strerror(errno) + ")");
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
    writeFileAtomically(path, [&](std::ofstream& stream) {
        stream.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    });
}

} // namespace texsplat
