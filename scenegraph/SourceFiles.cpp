#include "scenegraph/SourceFiles.h"

#include <deque>
#include <map>
#include <mutex>

namespace texsplat::sg {
namespace {

// The names of the files read so far; entry i has id i + 1.
struct SourceFileTable {
    std::mutex mutex;
    std::deque<std::string> names;
    std::map<std::string, SourceFileId, std::less<>> ids;
};

SourceFileTable& table() {
    static SourceFileTable table;
    return table;
}

} // namespace

SourceFileId internSourceFile(std::string_view fileName) {
    SourceFileTable& files = table();
    std::lock_guard<std::mutex> lock(files.mutex);
    const auto found = files.ids.find(fileName);
    if (found != files.ids.end()) {
        return found->second;
    }
    files.names.emplace_back(fileName);
    const auto id = static_cast<SourceFileId>(files.names.size());
    files.ids.emplace(files.names.back(), id);
    return id;
}

std::string sourceFileName(SourceFileId file) {
    SourceFileTable& files = table();
    std::lock_guard<std::mutex> lock(files.mutex);
    return file == 0 || file > files.names.size() ? std::string() : files.names[file - 1];
}

} // namespace texsplat::sg
