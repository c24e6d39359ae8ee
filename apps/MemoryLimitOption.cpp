#include "apps/MemoryLimitOption.h"

#include "apps/OptionError.h"
#include "scenegraph/MemoryLimit.h"

#include <CLI/CLI.hpp>

namespace texsplat::apps {

void addMemoryLimitOption(CLI::App& command, std::string& value) {
    command
        .add_option("--memory-limit", value,
                    "The most memory one stage of the work may need (a grid, its classification, "
                    "the octree, the splats, an image), e.g. 512M or 8G; work estimated above it "
                    "is refused before it allocates (default: the memory available at start)")
        ->type_name("BYTES");
}

std::uint64_t memoryLimitOf(const std::string& value) {
    return value.empty() ? availableMemoryBytes()
                         : withOption("--memory-limit", [&] { return parseByteCount(value); });
}

} // namespace texsplat::apps
