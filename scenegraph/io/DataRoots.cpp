#include "scenegraph/io/DataRoots.h"

#include "scenegraph/Error.h"

#include <filesystem>
#include <system_error>

namespace texsplat::sg {
namespace {

namespace fs = std::filesystem;

// `path` absolute, with every symbolic link and `..` of its existing part resolved.
fs::path realPath(const std::string& path, std::error_code& error) {
    const fs::path absolute = fs::absolute(path, error);
    return error ? fs::path() : fs::weakly_canonical(absolute, error);
}

bool isInside(const fs::path& path, const fs::path& folder) {
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

} // namespace

DataRoots::DataRoots(const std::vector<std::string>& folders) {
    for (const std::string& folder : folders) {
        std::error_code error;
        const fs::path real = realPath(folder, error);
        const fs::file_type type = error ? fs::file_type::none : fs::status(real, error).type();
        if (!error && type == fs::file_type::not_found)
            error = std::make_error_code(std::errc::no_such_file_or_directory);
        else if (!error && type != fs::file_type::directory)
            error = std::make_error_code(std::errc::not_a_directory);
        if (error)
            throw IoError(folder + ": cannot use as a data root: " + error.message());
        mFolders.push_back(real.string());
    }
}

void DataRoots::check(const std::string& path, const std::string& what) const {
    if (mFolders.empty())
        return;
    std::error_code error;
    const fs::path real = realPath(path, error);
    if (error)
        throw IoError(path + ": cannot read " + what + ": " + error.message());
    for (const std::string& folder : mFolders)
        if (isInside(real, folder))
            return;
    std::string roots;
    for (const std::string& folder : mFolders)
        roots += (roots.empty() ? "" : ", ") + folder;
    const std::string leads = fs::absolute(path, error) == real
                                  ? std::string()
                                  : " (it leads to " + real.string() + ")";
    throw IoError(path + ": cannot read " + what + ": it lies outside the data roots (" + roots +
                  ")" + leads + ", which --data-root confines the files a scene reads to");
}

} // namespace texsplat::sg
