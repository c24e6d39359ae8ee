#include "apps/viewer/Viewer.h"

#include "apps/WorkProgressPrinter.h"
#include "apps/viewer/FramePresenter.h"
#include "apps/viewer/GlfwWindow.h"
#include "apps/viewer/OrbitController.h"
#include "apps/viewer/ProgressiveRefinement.h"
#include "apps/viewer/TransferFunctionEditor.h"
#include "apps/viewer/ViewerFrames.h"
#include "apps/viewer/ViewerPanel.h"
#include "nodes/Camera.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/engines/AnimationSpeed.h"
#include "scenegraph/engines/TimeInputs.h"
#include "scenegraph/sensors/IdleSensor.h"
#include "scenegraph/sensors/NodeSensor.h"
#include "scenegraph/sensors/RealTimeClock.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/TimerSensor.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace texsplat::apps {
namespace {

using Clock = std::chrono::steady_clock;

// Mouse and key state between frames. The wheel, the button presses and the pause key arrive
// through callbacks: a frame may take longer than a whole gesture on a software rasterizer, and a
// drag then starts where the button went down, not where the next frame finds the cursor; a
// short key press between two frames must not be lost either.
struct Pointer {
    glm::dvec2 last{0.0};
    bool wasDragging = false;
    double scroll = 0.0;
    std::optional<glm::dvec2> pressedAt;
    int pauseToggles = 0; ///< space presses since the last frame
};

// How often the scene's time advances while engines follow it: a display's rate. The timer only
// wakes the loop; the queue sets the time field at every processing.
constexpr double kAnimationInterval = 1.0 / 60.0;

// One line of `texsplat view --time-report` on stderr: what a frame drew and where its time went,
// and when it was shown, counted from the start of the viewer.
void reportFrame(int frame, double sinceStart, const ProgressiveRefinement& refinement,
                 const sg::RenderStatistics& statistics) {
    std::string phases;
    for (std::size_t phase = 0; phase < sg::kRenderPhaseCount; ++phase) {
        const auto which = static_cast<sg::RenderPhase>(phase);
        if (statistics.time(which) >= 0.0005) {
            char text[64];
            std::snprintf(text, sizeof text, "%s%.*s %.3f", phases.empty() ? "" : ", ",
                          static_cast<int>(sg::toString(which).size()), sg::toString(which).data(),
                          statistics.time(which));
            phases += text;
        }
    }
    std::string budget;
    if (refinement.budget() > 0) {
        budget = ", budget " + std::to_string(refinement.budget());
    }
    const char* preview = statistics.previewed > 0 ? " (a preview of the edit)" : "";
    std::fprintf(stderr, "frame %d at %.2f s: %s%s, %zu splats%s; %s s\n", frame, sinceStart,
                 ProgressiveRefinement::toString(refinement.stage()), budget.c_str(),
                 static_cast<std::size_t>(statistics.splats), preview, phases.c_str());
}

void onScroll(GLFWwindow* window, double /*x*/, double y) {
    static_cast<Pointer*>(glfwGetWindowUserPointer(window))->scroll += y;
}

void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
    if (key == GLFW_KEY_SPACE && action == GLFW_PRESS) {
        ++static_cast<Pointer*>(glfwGetWindowUserPointer(window))->pauseToggles;
    }
}

void onMouseButton(GLFWwindow* window, int /*button*/, int action, int /*mods*/) {
    auto* pointer = static_cast<Pointer*>(glfwGetWindowUserPointer(window));
    if (action == GLFW_PRESS && !pointer->pressedAt) {
        glm::dvec2 cursor(0.0);
        glfwGetCursorPos(window, &cursor.x, &cursor.y);
        pointer->pressedAt = cursor;
    }
}

nodes::Camera& cameraOf(sg::Node& root) {
    sg::SearchAction search;
    search.setType(nodes::Camera::classType());
    search.apply(root);
    TEXSPLAT_ASSERT(!search.paths().empty(), "Viewer: withCamera() gives every scene a camera");
    return static_cast<nodes::Camera&>(*search.paths().front().tail());
}

std::string title(const ViewerOptions& options) {
    return "texsplat view: " +
           (options.scene.empty() ? std::string("default scene") : options.scene);
}

} // namespace

Viewer::Viewer(ViewerOptions options) : mOptions(std::move(options)) {
    mScene = loadScene(mOptions.scene);
    if (!mOptions.screenshot.empty()) {
        // Refuse a bad file name before the window opens.
        image::imageFormatOf(mOptions.screenshot);
    }
}

void Viewer::run() {
    const Clock::time_point started = Clock::now();
    GlfwWindow window(mOptions.size, title(mOptions));
    Pointer pointer;
    glfwSetWindowUserPointer(window.handle(), &pointer);
    glfwSetScrollCallback(window.handle(), onScroll); // before ImGui, which chains to them
    glfwSetMouseButtonCallback(window.handle(), onMouseButton);
    glfwSetKeyCallback(window.handle(), onKey);
    // A long step (reading a volume file, classifying, building the octree) shows on stderr and
    // keeps the window's events flowing, and Esc or q cancels it (and quits, as it does between
    // frames).
    const sg::WorkProgress progress = [printer = WorkProgressPrinter(),
                                       handle = window.handle()](std::string_view step,
                                                                 double fraction) mutable {
        printer(step, fraction);
        glfwPollEvents();
        return glfwGetKey(handle, GLFW_KEY_ESCAPE) != GLFW_PRESS &&
               glfwGetKey(handle, GLFW_KEY_Q) != GLFW_PRESS;
    };

    // The window is open before the volumes load (framing a scene without a camera reads them),
    // so that a long load can be cancelled.
    sg::Node::Ptr scene;
    sg::BoundingBoxAction boxAction;
    boxAction.setWorkProgress(progress);
    try {
        const glm::ivec2 size = mOptions.size;
        scene = withCamera(mScene, mOptions.framing,
                           static_cast<float>(size.x) / static_cast<float>(size.y), progress);
        boxAction.apply(*scene);
    } catch (const sg::Cancelled& error) {
        std::fprintf(stderr, "texsplat view: %s\n", error.what());
        return;
    }
    sg::Node& root = *scene;
    OrbitController controller(cameraOf(root), boxAction.boundingBox());
    ProgressiveRefinement refinement(root, mOptions.interactiveBudget);
    // The first frame is coarse as well, then refines while idle: a big volume shows within about
    // a second of its load instead of after a full-resolution frame (the 1024^3 cloud: 3.5 s).
    refinement.beginInteraction();
    TransferFunctionEditor transfer(root);
    bool editingTransfer = false; // a panel control of the transfer function held last frame

    sg::RealTimeClock clock;
    sg::SensorQueue queue(clock);
    const bool isAnimated = sg::connectTimeInputs(root, queue.timeField()) > 0;
    // The paper's speed slider on the timer, and a pause: every ElapsedTime of the scene.
    sg::AnimationSpeed animation(root);
    // Without a timer the loop would sleep between events and the engines' time would advance
    // only then; while the scene follows time and is not paused, it wakes the loop.
    sg::TimerSensor animationTick(queue);
    animationTick.setInterval(kAnimationInterval);
    bool needsRender = true;
    sg::NodeSensor changed(queue, [&] { needsRender = true; });
    changed.attach(root);
    std::size_t lastSplats = 0;
    double lastFrameSeconds = 0.0;
    // One refinement step per idle moment after a coarse frame was drawn (scheduled below).
    sg::IdleSensor refineStep(queue);
    refineStep.setCallback([&] {
        if (!refinement.refine(lastSplats, lastFrameSeconds) &&
            refinement.endedWithoutRedraw() && mOptions.timeReport) {
            std::fprintf(stderr, "at %.2f s: full quality, the last frame's %zu splats\n",
                         std::chrono::duration<double>(Clock::now() - started).count(),
                         lastSplats);
        }
    });

    FramePresenter presenter;
    ViewerPanel panel(window.handle());
    ViewerFrames frames(mOptions.backend, window.info().summary(), mOptions.background,
                        mOptions.threads);
    frames.setWorkProgress(progress);
    PanelReport report;
    report.renderer = frames.description();

    for (int frame = 0; !window.shouldClose(); ++frame) {
        if (mOptions.frames > 0 && frame >= mOptions.frames) {
            break;
        }
        // The pause (key or panel) decides whether the time ticks; a paused viewer sleeps.
        if (isAnimated && animation.isPaused() == animationTick.isScheduled()) {
            if (animation.isPaused()) {
                animationTick.unschedule();
            } else {
                animationTick.schedule();
            }
        }
        const bool busy = needsRender || queue.hasDelaySensors() || queue.hasIdleSensors();
        if (mOptions.frames > 0 || busy) {
            glfwPollEvents();
        } else {
            // Nothing to do until an event or the next timer (animation).
            const auto next = queue.nextTimerTime();
            glfwWaitEventsTimeout(next ? std::clamp(*next - queue.time(), 0.0, 0.5) : 0.5);
        }

        // Input: keys, then the pointer (unless the panel has it).
        GLFWwindow* handle = window.handle();
        if (glfwGetKey(handle, GLFW_KEY_ESCAPE) == GLFW_PRESS ||
            glfwGetKey(handle, GLFW_KEY_Q) == GLFW_PRESS) {
            window.requestClose();
        }
        if (glfwGetKey(handle, GLFW_KEY_R) == GLFW_PRESS) {
            controller.reset();
        }
        if (pointer.pauseToggles % 2 == 1 && !animation.isEmpty() && !panel.wantsKeyboard()) {
            animation.setPaused(!animation.isPaused());
        }
        pointer.pauseToggles = 0;
        glm::dvec2 cursor(0.0);
        glfwGetCursorPos(handle, &cursor.x, &cursor.y);
        const bool orbiting = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        const bool panning = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                             glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
        const bool dragging = (orbiting || panning) && (pointer.wasDragging || !panel.wantsMouse());
        const glm::ivec2 size = window.framebufferSize();
        if (dragging && !pointer.wasDragging && pointer.pressedAt) {
            pointer.last = *pointer.pressedAt; // the drag so far counts from the press
            pointer.wasDragging = true;
        }
        pointer.pressedAt.reset();
        if (dragging && pointer.wasDragging && cursor != pointer.last) {
            refinement.beginInteraction();
            refineStep.unschedule();
            const glm::vec2 delta(cursor - pointer.last);
            if (orbiting) {
                controller.orbit(delta, static_cast<float>(size.y));
            } else {
                controller.pan(delta, static_cast<float>(size.y));
            }
        }
        if (pointer.wasDragging && !dragging &&
            refinement.stage() != ProgressiveRefinement::Stage::FullQuality) {
            refineStep.schedule(); // the last coarse frame is drawn: refine from it
        }
        if (pointer.scroll != 0.0 && !panel.wantsMouse()) {
            refinement.beginInteraction();
            refineStep.unschedule();
            controller.zoom(static_cast<float>(pointer.scroll));
        }
        pointer.scroll = 0.0;
        pointer.wasDragging = dragging;
        pointer.last = cursor;

        queue.process(); // timers (animation), then the change sensor, then a refinement step

        if (size.x <= 0 || size.y <= 0) {
            continue; // minimized
        }
        needsRender = frames.resize(size) || needsRender;
        if (needsRender) {
            needsRender = false;
            const Clock::time_point start = Clock::now();
            const sg::RenderStatistics* rendered = nullptr;
            try {
                // Coarse frames preview a transfer-function edit from the blocks' value
                // histograms; the refinement steps after it classify exactly.
                rendered = &frames.render(
                    root, refinement.stage() == ProgressiveRefinement::Stage::Interactive);
            } catch (const sg::Cancelled& error) {
                std::fprintf(stderr, "texsplat view: %s\n", error.what());
                window.requestClose();
                continue;
            }
            const sg::RenderStatistics& statistics = *rendered;
            report.frameSeconds = std::chrono::duration<double>(Clock::now() - start).count();
            if (mOptions.timeReport) {
                reportFrame(frame,
                            std::chrono::duration<double>(Clock::now() - started).count(),
                            refinement, statistics);
            }
            report.renderer = frames.description();
            lastSplats = statistics.splats;
            // What the next frames repeat: not the load and classification done once.
            lastFrameSeconds = report.frameSeconds - statistics.time(sg::RenderPhase::Load) -
                               statistics.time(sg::RenderPhase::Classify);
            report.splats = lastSplats;
            report.triangles = statistics.triangles;
            if (!dragging && !editingTransfer &&
                refinement.stage() != ProgressiveRefinement::Stage::FullQuality) {
                refineStep.schedule(); // the next step once the queue is idle
            }
        }
        report.stage = refinement.stage();
        report.budget = refinement.budget();
        frames.present(presenter, mOptions.background, size);
        // A transfer-function edit redraws coarse while its control is held, then refines, as
        // a drag of the view does.
        const bool wasEditingTransfer = editingTransfer;
        editingTransfer = panel.draw(report, refinement, animation, transfer);
        if (editingTransfer) {
            refinement.beginInteraction();
            refineStep.unschedule();
        } else if (wasEditingTransfer &&
                   refinement.stage() != ProgressiveRefinement::Stage::FullQuality) {
            refineStep.schedule();
        }
        window.swapBuffers();
    }

    if (!mOptions.screenshot.empty() && frames.hasFrame()) {
        // The window's last frame without the panel: drawn again into its back buffer (not
        // shown) and read back, so the file holds the bytes the window showed.
        const glm::ivec2 size = window.framebufferSize();
        if (size.x <= 0 || size.y <= 0) {
            throw GlError(mOptions.screenshot + ": the window is minimized, nothing to read back");
        }
        frames.present(presenter, mOptions.background, size);
        image::writeImage(FramePresenter::readBack(size), mOptions.screenshot);
    }
}

} // namespace texsplat::apps
