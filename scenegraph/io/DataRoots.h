#pragma once

#include <string>
#include <vector>

namespace texsplat::sg {

/// @brief The folders that every file a scene reads must lie in: for services that render
/// scenes they did not write (`texsplat render --data-root DIR`, ReadOptions::dataRoots,
/// docs/security.md).
///
/// A scene names files (a volume's `fileName`, a glTF model and the buffers and images its URIs
/// name, a NRRD header's detached data file, a colour map), and by default texsplat reads any
/// file its user can: a scene saying `fileName "../../etc/passwd"` gets that file's bytes read
/// and its histogram printed. With roots, a file is read only when its real path (symbolic links
/// and `..` resolved) lies inside one of them; any other is refused with an IoError before it is
/// opened.
///
/// The check is made when a file is about to be opened; a process that can change the folders
/// between the check and the open (swapping a checked folder for a link) can still escape it.
/// It confines what a scene asks for, not what the machine allows: run untrusted scenes under the
/// system's own confinement as well (a user of their own, a container).
class DataRoots {
public:
    /// @brief No roots: any file may be read.
    DataRoots() = default;

    /// @brief The roots `folders`, each made absolute and resolved (symbolic links, `..`).
    /// @throws IoError "<folder>: cannot use as a data root: <reason>" for a folder that does
    /// not exist or is not a folder.
    explicit DataRoots(const std::vector<std::string>& folders);

    /// @brief Whether any root is set (else every file may be read).
    [[nodiscard]] bool isConfined() const { return !mFolders.empty(); }

    /// @brief The roots, resolved.
    [[nodiscard]] const std::vector<std::string>& folders() const { return mFolders; }

    /// @brief Refuses `path` unless it lies inside a root (or there are none): throws IoError
    /// "<path>: cannot read <what>: it lies outside the data roots (/srv/data), which
    /// --data-root confines the files a scene reads to" (naming where it leads when a link or
    /// `..` takes it there). A path that does not exist yet is judged by the folders it names.
    void check(const std::string& path, const std::string& what) const;

private:
    std::vector<std::string> mFolders;
};

} // namespace texsplat::sg
