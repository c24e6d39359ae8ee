#include "scenegraph/io/SceneReader.h"

#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/detail/SceneLexer.h"
#include "scenegraph/io/detail/SceneParser.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace texsplat::sg {

namespace {

// Enough for the header line and the spaces a writer may leave after it; a longer first line is
// not a header, and the lexer's message quotes only its start.
constexpr std::size_t kHeaderProbeBytes = 256;

} // namespace

std::shared_ptr<Node> SceneReader::readFile(const std::string& path, const ReadOptions& options) {
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
    // The rest read straight into one string: a stream of the contents and its copy held the
    // text three times over.
    std::string text = std::move(start);
    if (!file.eof()) {
        std::error_code sizeError;
        const std::uintmax_t size = std::filesystem::file_size(path, sizeError);
        if (!sizeError && size > text.size()) {
            checkMemory(path + ": the scene file's text", size,
                        "use a smaller scene file, or a larger --memory-limit");
            const std::size_t read = text.size();
            text.resize(static_cast<std::size_t>(size));
            file.read(text.data() + read, static_cast<std::streamsize>(size - read));
            text.resize(read + static_cast<std::size_t>(file.gcount()));
        }
        if (file) { // what a file that grew since holds more, or all when its size is unknown
            text.append(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
        }
    }
    if (file.bad()) {
        throw IoError(path + ": cannot read scene file");
    }
    // Relative file names in the scene (VolumeData's fileName) mean files beside it.
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    detail::SceneParser parser(text, path, error ? std::string() : absolute.parent_path().string(),
                               options.dataRoots);
    return parser.parseFile();
}

std::shared_ptr<Node> SceneReader::readString(std::string_view text, const std::string& fileName,
                                              const ReadOptions& options) {
    detail::SceneParser parser(text, fileName, {}, options.dataRoots);
    return parser.parseFile();
}

} // namespace texsplat::sg
