#include "apps/viewer/GlfwWindow.h"

#include "scenegraph/Error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

#include <dlfcn.h>
#include <link.h>

namespace texsplat::apps {
namespace {

// GLFW reports errors through a callback; the constructor turns the last one into a message.
std::string sLastGlfwError;

void rememberGlfwError(int /*code*/, const char* description) {
    sLastGlfwError = description ? description : "unknown GLFW error";
}

std::string displayVariables() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if (!display && !wayland) {
        return "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
    }
    return std::string("DISPLAY=") + (display ? display : "(unset)") +
           ", WAYLAND_DISPLAY=" + (wayland ? wayland : "(unset)");
}

// GLFW and the GL driver unload the libraries they opened (the DRI driver, X extensions) when
// the window closes, and their per-process caches then show up as leaks from an unknown
// module. Keeping every library that is loaded once the context exists mapped until the process
// ends lets leak checkers attribute those caches (tests/sanitizers/lsan.supp) and costs nothing.
void keepLoadedLibrariesMapped() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void*) {
            if (info->dlpi_name && info->dlpi_name[0] != '\0') {
                dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
}

[[noreturn]] void fail(const std::string& what) {
    throw GlError("cannot open a window: " + what + "; " + displayVariables() +
                  "; 'texsplat render' makes images without a display");
}

} // namespace

GlfwWindow::GlfwWindow(const glm::ivec2& size, const std::string& title) {
    glfwSetErrorCallback(rememberGlfwError);
    if (!glfwInit()) {
        fail(sLastGlfwError);
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    mWindow = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        const std::string reason = sLastGlfwError;
        glfwTerminate();
        fail(reason + " (asked for an OpenGL 3.3 core context)");
    }
    // Keys are read by polling (glfwGetKey) between frames and during long steps: a key pressed
    // and released while a frame renders arrives with its release in one poll and would read as
    // released. Sticky keys keep the press until it is read, so a quick Esc still quits.
    glfwSetInputMode(mWindow, GLFW_STICKY_KEYS, GLFW_TRUE);
    makeCurrent();
    keepLoadedLibrariesMapped();
    glfwSwapInterval(1);
    queryInfo("GLFW window");
}

GlfwWindow::~GlfwWindow() {
    glfwMakeContextCurrent(nullptr);
    clearCurrent();
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

void GlfwWindow::makePlatformCurrent() { glfwMakeContextCurrent(mWindow); }

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(mWindow) != 0; }

void GlfwWindow::requestClose() { glfwSetWindowShouldClose(mWindow, GLFW_TRUE); }

glm::ivec2 GlfwWindow::framebufferSize() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(mWindow, &size.x, &size.y);
    return size;
}

void GlfwWindow::swapBuffers() { glfwSwapBuffers(mWindow); }

} // namespace texsplat::apps
