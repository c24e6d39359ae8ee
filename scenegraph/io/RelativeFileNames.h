#pragma once

#include "scenegraph/io/DataRoots.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

namespace texsplat::sg {

/// @brief For nodes whose fields name files (`fileName`): relative names are resolved against the
/// folder of the scene file the node was read from, as Inventor readers do, so a scene and its
/// data can move together and be read from any working directory.
///
/// SceneReader::readFile() sets baseDirectory() on every node of such a type that it creates (the
/// absolute folder of the scene file); the field keeps the name as written, so a scene written
/// back stays relative. A node made in C++ (or read with SceneReader::readString()) has no base
/// directory and resolves against the working directory. Absolute names are used as they are.
/// Set the base directory before the node is used: nodes that cache what they read do not drop
/// the cache when it changes.
///
/// The files a node opens may be confined to folders (dataRoots(), `--data-root`): the reader
/// gives every node the roots of its ReadOptions, and the node opens what readablePath() answers.
class RelativeFileNames {
public:
    virtual ~RelativeFileNames() = default;

    /// @brief The folder relative file names are resolved against; empty for the working
    /// directory.
    const std::string& baseDirectory() const { return mBaseDirectory; }

    /// @brief Sets the folder relative file names are resolved against (empty: the working
    /// directory).
    void setBaseDirectory(std::string directory) { mBaseDirectory = std::move(directory); }

    /// @brief The path a file name means: `fileName` itself when it is absolute, empty or there
    /// is no base directory, otherwise `baseDirectory()/fileName`.
    std::string resolvedPath(const std::string& fileName) const {
        const std::filesystem::path name(fileName);
        if (fileName.empty() || mBaseDirectory.empty() || name.is_absolute())
            return fileName;
        return (std::filesystem::path(mBaseDirectory) / name).string();
    }

    /// @brief The folders the node's files must lie in; null or empty: any file may be read.
    const std::shared_ptr<const DataRoots>& dataRoots() const { return mDataRoots; }

    /// @brief Confines the node's files to `roots` (null: no confinement). Set it, like the base
    /// directory, before the node is used.
    void setDataRoots(std::shared_ptr<const DataRoots> roots) { mDataRoots = std::move(roots); }

    /// @brief resolvedPath(fileName), when it lies inside the data roots: the path a node opens.
    /// @throws IoError as DataRoots::check(), `what` naming the file ("file", "colour map").
    std::string readablePath(const std::string& fileName, const std::string& what) const {
        std::string path = resolvedPath(fileName);
        if (mDataRoots)
            mDataRoots->check(path, what);
        return path;
    }

protected:
    RelativeFileNames() = default;
    RelativeFileNames(const RelativeFileNames&) = default;
    RelativeFileNames& operator=(const RelativeFileNames&) = default;

private:
    std::string mBaseDirectory;
    std::shared_ptr<const DataRoots> mDataRoots;
};

} // namespace texsplat::sg
