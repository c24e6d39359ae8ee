#pragma once

#include <tbb/global_control.h>

#include <cstddef>
#include <optional>

namespace texsplat::apps {

/// @brief While it lives, oneTBB runs at most `threads` threads (0: no limit, one per hardware
/// thread). `--threads N` bounds all of a command's CPU work with it, not only the CPU
/// renderer's own arena: the splat emission, the classification and OpenVDB's reads run in
/// oneTBB's default arena.
class ThreadLimit {
public:
    explicit ThreadLimit(int threads) {
        if (threads > 0) {
            mControl.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<std::size_t>(threads));
        }
    }

private:
    std::optional<tbb::global_control> mControl;
};

} // namespace texsplat::apps
