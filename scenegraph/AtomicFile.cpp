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

std::atomic<unsigned> sTemporaryCounter{0};

/// Gives a file a fresh name next to `path` (".NAME.tmpPID-N") with `make(name)`, which answers
/// false, with errno, when it could not; returns the name. `doing` starts the message of a
/// failure other than a name that is taken.
template <class Make>
std::string claimTemporaryName(const std::string& path, const std::string& doing, Make&& make) {
    const auto slash = path.find_last_of('/');
    const std::string prefix = slash == std::string::npos ? std::string()
                                                          : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string candidate = prefix + "." + name + ".tmp" + std::to_string(getpid()) + "-" +
                                std::to_string(sTemporaryCounter++);
        if (make(candidate))
            return candidate;
        if (errno != EEXIST)
            throw IoError(path + ": " + doing + " in directory " + directoryOf(path) + ": " +
                          std::strerror(errno));
    }
    throw IoError(path + ": cannot find an unused temporary name in " + directoryOf(path));
}

/// Creates a new, empty file next to `path` and returns its name. O_EXCL makes the name ours
/// alone; mode 0666 lets the umask decide the final permissions, as for any new file.
std::string createTemporarySibling(const std::string& path) {
    return claimTemporaryName(path, "cannot create a file", [](const std::string& candidate) {
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0)
            return false;
        ::close(fd);
        return true;
    });
}

/// The file being written: while it is written it has a name only when the folder's file system
/// cannot make a file without one (O_TMPFILE), so that a process killed while writing (Ctrl-C,
/// a timeout's SIGKILL, the OOM killer) leaves nothing behind; it gets a name only to be renamed
/// over the destination at once.
class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& path) : mPath(path) {
        mDescriptor = ::open(directoryOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
        if (mDescriptor >= 0) {
            // The same file through /proc: what the stream opens, and what linkat() names.
            mWritePath = "/proc/self/fd/" + std::to_string(mDescriptor);
            if (::access(mWritePath.c_str(), W_OK) == 0)
                return;
            ::close(mDescriptor); // no /proc: a named file after all
            mDescriptor = -1;
        }
        mWritePath = createTemporarySibling(path);
        mName = mWritePath;
    }
    ~TemporaryFile() {
        if (mDescriptor >= 0)
            ::close(mDescriptor);
        if (!mName.empty())
            std::remove(mName.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    /// Where the contents are written.
    const std::string& writePath() const { return mWritePath; }

    /// Flushes the written file to the device and renames it over the destination.
    void replaceDestination() {
        if (!syncToDisk(mWritePath))
            throw IoError(mPath + ": cannot flush to disk: " + std::strerror(errno));
        if (mName.empty()) {
            // linkat() cannot replace a file: link a fresh name, then rename it over.
            mName = claimTemporaryName(mPath, "cannot name the written file",
                                       [this](const std::string& candidate) {
                                           return ::linkat(AT_FDCWD, mWritePath.c_str(), AT_FDCWD,
                                                           candidate.c_str(),
                                                           AT_SYMLINK_FOLLOW) == 0;
                                       });
        }
        if (std::rename(mName.c_str(), mPath.c_str()) != 0)
            throw IoError(mPath + ": cannot replace the file: " + std::strerror(errno));
        mName.clear();
    }

private:
    std::string mPath;
    int mDescriptor = -1;
    std::string mWritePath;
    std::string mName; // a name the file has in the folder, removed unless renamed
};

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
    TemporaryFile temporary(path);
    try {
        std::ofstream stream(temporary.writePath(), std::ios::binary | std::ios::trunc);
        if (!stream)
            throw IoError(path + ": cannot open " + temporary.writePath() + " for writing");
        write(stream);
        stream.close();
        if (!stream)
            throw IoError(path + ": write failed (disk full?)");
        temporary.replaceDestination();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
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
