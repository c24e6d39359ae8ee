#include "scenegraph/io/SceneReader.h"

#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/detail/SceneLexer.h"
#include "scenegraph/io/detail/SceneParser.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace texsplat::sg {

namespace {

// Enough for the header line and the spaces a writer may leave after it; a longer first line is
// not a header, and the lexer's message quotes only its start.
constexpr std::size_t kHeaderProbeBytes = 256;

} // namespace

std::shared_ptr<Node> SceneReader::readFile(const std::string& path) {
    if (std::filesystem::is_directory(path)) {
        throw IoError(path + ": cannot read scene file: it is a directory");
    }
    requireRegularFile(path, "scene file");
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw IoError(path + ": cannot open scene file: " + std::strerror(errno));
    }
    // The header is checked from the first bytes, so that a large file that is not a scene (a
    // volume, an image) is refused before it is read whole.
    std::string start(kHeaderProbeBytes, '\0');
    file.read(start.data(), static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<std::size_t>(file.gcount()));
    detail::SceneLexer(start, path).readHeader();
    std::ostringstream contents;
    contents << start;
    if (!file.eof()) {
        contents << file.rdbuf();
    }
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
