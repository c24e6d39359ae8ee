#pragma once

#include <cstdint>
#include <functional>

namespace texsplat::bench::detail {

/// The number of samples (fragments, without multisampling) that passed the depth test while
/// `draw` ran, counted by a GL_SAMPLES_PASSED occlusion query: every fragment a splat
/// rasterizes, since the splat pass tests depth but writes none and nothing is discarded.
/// The query waits for the GL to finish. Needs a current context; throws GlError on a GL error.
std::uint64_t countSamplesPassed(const std::function<void()>& draw);

} // namespace texsplat::bench::detail
