#include "scenegraph/FileExtension.h"

#include "scenegraph/Error.h"

#include <algorithm>
#include <cctype>

namespace texsplat {

std::string fileExtension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string extension = path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

void requireFileExtension(const std::string& path, const std::vector<std::string>& supported,
                          const std::string& kind) {
    const std::string extension = fileExtension(path);
    if (std::find(supported.begin(), supported.end(), extension) != supported.end())
        return;
    std::string list;
    for (const std::string& each : supported)
        list += (list.empty() ? "" : ", ") + each;
    if (path.empty())
        throw IoError("the " + kind + " file name is empty (supported extensions: " + list + ")");
    const std::string found = extension.empty()
                                  ? "no " + kind + " extension"
                                  : "unknown " + kind + " extension '" + extension + "'";
    throw IoError(path + ": " + found + " (supported: " + list + ")");
}

} // namespace texsplat
