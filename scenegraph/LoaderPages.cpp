#include "scenegraph/LoaderPages.h"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/mman.h>

namespace texsplat {
namespace {

struct Mapping {
    std::uintptr_t begin = 0;
    std::uintptr_t end = 0;
    bool isLoaderSegment = false; // read-only, private, at offset 0 of a file
    std::uint64_t residentKiB = 0;
    std::uint64_t privateDirtyKiB = 0;
    std::uint64_t anonymousKiB = 0;
};

// The header line of a mapping in /proc/self/smaps:
// "7f6f0ae00000-7f6f0c710000 r--p 00000000 fe:00 15632542   /usr/lib/x86_64-linux-gnu/libx.so"
bool parseHeader(const std::string& line, Mapping& mapping) {
    std::istringstream in(line);
    std::string range, permissions, offset, device, path;
    std::uint64_t inode = 0;
    if (!(in >> range >> permissions >> offset >> device >> inode)) {
        return false;
    }
    const std::size_t dash = range.find('-');
    if (dash == std::string::npos || permissions.size() != 4) {
        return false;
    }
    in >> path;
    mapping.begin = std::stoull(range.substr(0, dash), nullptr, 16);
    mapping.end = std::stoull(range.substr(dash + 1), nullptr, 16);
    mapping.isLoaderSegment = permissions == "r--p" && std::stoull(offset, nullptr, 16) == 0 &&
                              inode != 0 && !path.empty() && path.front() == '/';
    return true;
}

// "Rss:                 364 kB" -> 364 when `line` starts with `key`.
bool readKiB(const std::string& line, const char* key, std::uint64_t& value) {
    const std::string prefix = std::string(key) + ':';
    if (line.compare(0, prefix.size(), prefix) != 0) {
        return false;
    }
    value = std::stoull(line.substr(prefix.size()));
    return true;
}

std::vector<Mapping> readMappings() {
    std::ifstream smaps("/proc/self/smaps");
    std::vector<Mapping> mappings;
    std::string line;
    while (std::getline(smaps, line)) {
        Mapping mapping;
        if (parseHeader(line, mapping)) {
            mappings.push_back(mapping);
        } else if (!mappings.empty()) {
            Mapping& last = mappings.back();
            readKiB(line, "Rss", last.residentKiB) ||
                readKiB(line, "Private_Dirty", last.privateDirtyKiB) ||
                readKiB(line, "Anonymous", last.anonymousKiB);
        }
    }
    return mappings;
}

} // namespace

std::uint64_t releaseLoaderPages() {
    std::uint64_t released = 0;
    for (const Mapping& mapping : readMappings()) {
        // A page the loader wrote is no copy of the file: dropping it would lose the write.
        if (!mapping.isLoaderSegment || mapping.privateDirtyKiB != 0 ||
            mapping.anonymousKiB != 0 || mapping.residentKiB == 0) {
            continue;
        }
        if (madvise(reinterpret_cast<void*>(mapping.begin), mapping.end - mapping.begin,
                    MADV_DONTNEED) == 0) {
            released += mapping.residentKiB * 1024;
        }
    }
    return released;
}

} // namespace texsplat
