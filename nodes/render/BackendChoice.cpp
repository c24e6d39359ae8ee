#include "nodes/render/BackendChoice.h"

#include "scenegraph/Error.h"

#ifdef TEXSPLAT_WITH_GL
#include "scenegraph/gl/EglContext.h"
#include "scenegraph/actions/Seconds.h"
#endif

#include <chrono>
#include <cstddef>

namespace texsplat::render {
#ifdef TEXSPLAT_WITH_GL
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

} // namespace
#endif

BackendRequest parseBackendRequest(std::string_view text) {
    if (text == "auto") {
        return BackendRequest::Auto;
    }
    if (text == "cpu") {
        return BackendRequest::Cpu;
    }
    if (text == "gl") {
        return BackendRequest::Gl;
    }
    throw DataError("--backend: expected cpu, gl or auto, got '" + std::string(text) + "'");
}

bool isSoftwareRenderer(std::string_view renderer) {
    for (const std::string_view name : {"llvmpipe", "softpipe", "swrast"}) {
        if (renderer.find(name) != std::string_view::npos) {
            return true;
        }
    }
    return false;
}

#ifdef TEXSPLAT_WITH_GL
BackendChoice BackendChoice::resolve(BackendRequest request) {
    BackendChoice choice;
    if (request == BackendRequest::Cpu) {
        choice.reason = "asked for";
        return choice;
    }
    const Clock::time_point start = Clock::now();
    if (request == BackendRequest::Gl) {
        choice.context = std::make_shared<gl::EglContext>();
        choice.contextSeconds = secondsSince(start);
        choice.backend = Backend::Gl;
        choice.reason = "asked for";
        return choice;
    }
    // Where EGL lists no GPU, GL could only be a software rasterizer: the CPU, without
    // loading one to ask its name.
    if (gl::EglContext::gpuDeviceCount() == std::size_t{0}) {
        choice.contextSeconds = secondsSince(start);
        choice.reason = "auto: no GPU among EGL's devices";
        return choice;
    }
    try {
        auto context = std::make_shared<gl::EglContext>();
        choice.contextSeconds = secondsSince(start);
        const std::string renderer = context->info().renderer;
        if (isSoftwareRenderer(renderer)) {
            choice.reason = "auto: GL is a software rasterizer (" + renderer + ")";
            return choice;
        }
        choice.context = std::move(context);
        choice.backend = Backend::Gl;
        choice.reason = "auto: GL device " + renderer;
    } catch (const GlError& error) {
        choice.contextSeconds = secondsSince(start);
        choice.reason = std::string("auto: no GL context (") + error.what() + ")";
    }
    return choice;
}
#else
namespace {

[[noreturn]] void refuseGl(const std::string& why) {
    throw Error(why + ": this texsplat was built without GL (TEXSPLAT_WITH_GL=OFF); only "
                      "--backend cpu draws");
}

} // namespace

BackendChoice BackendChoice::resolve(BackendRequest request) {
    if (request == BackendRequest::Gl) {
        refuseGl("--backend gl");
    }
    BackendChoice choice;
    choice.reason = request == BackendRequest::Cpu ? "asked for" : "auto: built without GL";
    return choice;
}

#endif

} // namespace texsplat::render
