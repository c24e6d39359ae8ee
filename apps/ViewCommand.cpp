#include "apps/Commands.h"

#include "apps/MemoryLimitOption.h"
#include "apps/SceneSetup.h"
#include "apps/ThreadLimit.h"
#include "apps/viewer/Viewer.h"
#include "scenegraph/MemoryLimit.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace texsplat::apps {
namespace {

struct ViewArguments {
    ViewerOptions options;
    std::string size = "960x720";
    std::string backend = "auto";
    std::string memoryLimit;
};

} // namespace

void addViewCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto arguments = std::make_shared<ViewArguments>();
    ViewerOptions& options = arguments->options;
    CLI::App* command = app.add_subcommand(
        "view", "Explore a scene (or the built-in tornado scene) in a window: drag to orbit, "
                "right-drag to pan, wheel to zoom; coarse while moving, refined while idle");
    command->add_option("scene", options.scene,
                        "Inventor scene file (.iv); none: the built-in tornado with fibers");
    command->add_option("--size", arguments->size, "Window size WxH")->capture_default_str();
    addViewOptions(*command, options.framing);
    command->add_option("--interactive-splats", options.interactiveBudget,
                        "Splat budget per splat node while the view moves")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 30));
    command->add_option("--frames", options.frames,
                        "Close after this many frames (batch use and tests; 0: when closed)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1 << 30));
    command->add_option("--backend", arguments->backend,
                        "cpu|gl|auto: what draws the frames (auto: the CPU when the window's GL "
                        "is a software rasterizer such as llvmpipe, else GL)")
        ->capture_default_str();
    command->add_option("--threads", options.threads,
                        "Threads of the CPU backend (0: one per hardware thread)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
    command->add_option("--screenshot", options.screenshot,
                        "At the end, write the last rendered view (without the panel) as PNG "
                        "or EXR");
    command->add_flag("--time-report", options.timeReport,
                      "Print a line per rendered frame on stderr: when it was shown, its "
                      "refinement stage, splats and where its time went");
    addMemoryLimitOption(*command, arguments->memoryLimit);
    command->callback([arguments, mode, &exitCode] {
        const std::uint64_t memoryLimit = memoryLimitOf(arguments->memoryLimit);
        ViewerOptions viewerOptions = arguments->options;
        viewerOptions.framing.sceneName = viewerOptions.scene;
        viewerOptions.size = parseSize(arguments->size);
        viewerOptions.backend = render::parseBackendRequest(arguments->backend);
        if (mode == CommandMode::Run) {
            setMemoryLimit(memoryLimit);
            const ThreadLimit threadLimit(viewerOptions.threads);
            Viewer(viewerOptions).run();
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
