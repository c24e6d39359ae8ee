#pragma once

#include "scenegraph/gl/Context.h"

#include <glm/vec2.hpp>

#include <string>

struct GLFWwindow;

namespace texsplat::apps {

/// @brief A window with an OpenGL 3.3 (or newer) core context made current, through GLFW; GL
/// calls then go through libepoxy as everywhere else in texsplat (epoxy follows GLX and EGL
/// contexts alike).
///
/// It is a gl::Context, so texsplat's GL objects (GlRenderer's framebuffer, programs) can be
/// made in it; destroy them before the window. One window per process: the constructor
/// initializes GLFW, the destructor terminates it. Neither copyable nor movable.
class GlfwWindow final : public gl::Context {
public:
    /// @brief Opens a `size` window titled `title` and makes its context current.
    /// @throws GlError "cannot open a window: …" naming GLFW's reason and the display variables
    /// it looked at, when there is no display or no suitable context.
    GlfwWindow(const glm::ivec2& size, const std::string& title);
    ~GlfwWindow() override;

    /// @brief The GLFW handle (for input callbacks and ImGui).
    GLFWwindow* handle() const { return mWindow; }

    /// @brief True once the user asked to close the window (or requestClose() was called).
    bool shouldClose() const;

    /// @brief Asks the loop to end.
    void requestClose();

    /// @brief Size of the default framebuffer in pixels.
    glm::ivec2 framebufferSize() const;

    /// @brief Shows the frame drawn into the default framebuffer.
    void swapBuffers();

protected:
    void makePlatformCurrent() override;

private:
    GLFWwindow* mWindow = nullptr;
};

} // namespace texsplat::apps
