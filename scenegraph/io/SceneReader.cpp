#include "scenegraph/io/SceneReader.h"

#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/detail/SceneParser.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace texsplat::sg {

std::shared_ptr<Node> SceneReader::readFile(const std::string& path) {
    if (std::filesystem::is_directory(path)) {
        throw IoError(path + ": cannot read scene file: it is a directory");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw IoError(path + ": cannot open scene file: " + std::strerror(errno));
    }
    std::ostringstream contents;
    contents << file.rdbuf();
    if (file.bad()) {
        throw IoError(path + ": cannot read scene file");
    }
    // Relative file names in the scene (VolumeData's fileName) mean files beside it.
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::string text = contents.str(); // the parser views it
    detail::SceneParser parser(text, path, error ? std::string() : absolute.parent_path().string());
    return parser.parseFile();
}

std::shared_ptr<Node> SceneReader::readString(std::string_view text, const std::string& fileName) {
    detail::SceneParser parser(text, fileName);
    return parser.parseFile();
}

} // namespace texsplat::sg
