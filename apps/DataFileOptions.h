#pragma once

/// @file
/// @brief The options that say how to read a data file given in place of a scene (`texsplat info
/// ct.raw --dims 256,256,180 --type uint8`, `texsplat render ct.nrrd -o ct.png`), and
/// `--data-root`, which confines the files a scene reads.

#include "nodes/volume/VolumeFileInfo.h"
#include "scenegraph/io/DataRoots.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief The layout of a headerless raw file, as given on the command line.
struct HeaderlessOptions {
    std::string dims;           ///< "X,Y,Z": whole numbers from 1 to 1e9; empty: not headerless
    std::string type = "float32";
    std::string byteOrder = "little";
    std::string headerBytes = "0";
    std::string components = "1";
};

/// @brief Adds --dims, --type, --byte-order, --header-bytes and --components to `command`.
void addHeaderlessOptions(CLI::App& command, HeaderlessOptions& options);

/// @brief The layout the options describe when --dims is given; nullopt when it is not.
/// @throws DataError naming the option for a value it does not read, or a layout option given
/// without --dims.
std::optional<volume::HeaderlessRawLayout> headerlessLayout(const HeaderlessOptions& options);

/// @brief The options again, as a command line takes them (" --dims 256,256,180 --type uint8"),
/// for a message that says which command prints a data file's scene; empty without --dims.
std::string headerlessArguments(const HeaderlessOptions& options);

/// @brief Adds `--data-root DIR` (repeatable) to `command`, filling `folders`.
void addDataRootOption(CLI::App& command, std::vector<std::string>& folders);

/// @brief The roots `folders` name; null when there are none.
/// @throws IoError naming --data-root for a folder that does not exist or is not a folder.
std::shared_ptr<const sg::DataRoots> dataRootsOf(const std::vector<std::string>& folders);

} // namespace texsplat::apps
