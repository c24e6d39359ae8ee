#include "scenegraph/LoaderPages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

namespace texsplat {
namespace {

// The resident KiB of the mappings releaseLoaderPages() may release: read-only, private, at
// offset 0 of a file.
std::uint64_t loaderSegmentsResidentKiB() {
    std::ifstream smaps("/proc/self/smaps");
    std::uint64_t total = 0;
    bool inLoaderSegment = false;
    std::string line;
    while (std::getline(smaps, line)) {
        std::istringstream in(line);
        std::string first, permissions, offset, device, path;
        std::uint64_t inode = 0;
        if (line.rfind("Rss:", 0) == 0) {
            if (inLoaderSegment)
                total += std::stoull(line.substr(4));
        } else if (first = line.substr(0, line.find(' ')); first.find('-') != std::string::npos &&
                   (in >> first >> permissions >> offset >> device >> inode)) {
            in >> path;
            inLoaderSegment = permissions == "r--p" && offset.find_first_not_of('0') ==
                                                           std::string::npos &&
                              inode != 0 && !path.empty() && path.front() == '/';
        }
    }
    return total;
}

TEST(LoaderPages, releasesWhatTheLoaderReadAndTheProcessGoesOn) {
    // Whatever the loader read (this test's libraries: libstdc++, libc, gtest) is resident first.
    const std::uint64_t before = loaderSegmentsResidentKiB();
    ASSERT_GT(before, 0U);
    const std::uint64_t released = releaseLoaderPages();
    EXPECT_GT(released, 0U);
    EXPECT_LE(released, before * 1024);
    EXPECT_LT(loaderSegmentsResidentKiB(), before / 2);

    // What reads those pages again finds them: symbols looked up by name, a library loaded, an
    // exception unwound (the unwinder reads the program headers from the first segment).
    EXPECT_NE(dlsym(RTLD_DEFAULT, "malloc"), nullptr);
    void* zlib = dlopen("libz.so.1", RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(zlib, nullptr) << dlerror();
    EXPECT_NE(dlsym(zlib, "zlibVersion"), nullptr);
    dlclose(zlib);
    EXPECT_THROW(throw std::runtime_error("unwound"), std::runtime_error);
}

} // namespace
} // namespace texsplat
