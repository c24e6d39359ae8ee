#pragma once

#include "scenegraph/gl/ObjectName.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <epoxy/gl.h>

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace texsplat::gl {

/// @brief A linked GLSL program from vertex, optional geometry, and fragment shader sources.
///
/// Uniforms are set by name; each name's location is looked up once and cached. A name the
/// program does not have (misspelt, or optimized away by the compiler) is logged once as a
/// warning and then ignored, as GL ignores location -1. The setters make the program current
/// (glUseProgram), since OpenGL 3.3 has no per-program uniform calls. Move-only; a moved-from
/// program is empty (`id() == 0`). Created only with a current context.
class Program {
public:
    /// @brief Compiles and links.
    /// @param name names the program in error messages and logs ("splat" or a file name).
    /// @param geometrySource empty: no geometry stage.
    /// @throws GlError "<name>: <stage> shader does not compile:\n<driver log>" or
    /// "<name>: program does not link:\n<driver log>"; also when no context is current.
    Program(std::string name, std::string_view vertexSource, std::string_view fragmentSource,
            std::string_view geometrySource = {});

    /// @brief Makes the program current for drawing.
    void use() const;

    /// @brief The cached location of uniform `uniform`; -1 (logged once) if there is none.
    GLint uniformLocation(std::string_view uniform);

    /// @brief Sets a `float` uniform.
    void setUniform(std::string_view uniform, float value);
    /// @brief Sets an `int` uniform (also sampler units).
    void setUniform(std::string_view uniform, int value);
    /// @brief Sets a `vec2` uniform.
    void setUniform(std::string_view uniform, const glm::vec2& value);
    /// @brief Sets a `vec3` uniform.
    void setUniform(std::string_view uniform, const glm::vec3& value);
    /// @brief Sets a `vec4` uniform.
    void setUniform(std::string_view uniform, const glm::vec4& value);
    /// @brief Sets a `mat3` uniform.
    void setUniform(std::string_view uniform, const glm::mat3& value);
    /// @brief Sets a `mat4` uniform.
    void setUniform(std::string_view uniform, const glm::mat4& value);

    /// @brief The name given at creation.
    const std::string& name() const { return mLabel; }

    /// @brief The GL name; 0 for an empty (moved-from) program.
    GLuint id() const { return mName.id(); }

private:
    ObjectName mName;
    std::string mLabel;
    std::map<std::string, GLint, std::less<>> mUniformLocations;
};

} // namespace texsplat::gl
