#include "scenegraph/gl/Program.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <glm/gtc/type_ptr.hpp>

#include <utility>
#include <vector>

namespace texsplat::gl {
namespace {

GLuint createProgram() { return glCreateProgram(); }

void deleteProgram(GLuint id) { glDeleteProgram(id); }

void deleteShader(GLuint id) { glDeleteShader(id); }

const char* stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    default: return "fragment";
    }
}

// Reads a shader's or a program's info log; the two differ only in their query functions.
template <class GetParameter, class GetLog>
std::string infoLog(GLuint id, GetParameter getParameter, GetLog getLog) {
    GLint length = 0;
    getParameter(id, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) {
        return "(the driver gave no log)";
    }
    std::vector<GLchar> text(static_cast<std::size_t>(length));
    getLog(id, length, nullptr, text.data());
    std::string log(text.data());
    while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) {
        log.pop_back();
    }
    return log;
}

ObjectName::Create shaderCreator(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return [] { return glCreateShader(GL_VERTEX_SHADER); };
    case GL_GEOMETRY_SHADER: return [] { return glCreateShader(GL_GEOMETRY_SHADER); };
    default: return [] { return glCreateShader(GL_FRAGMENT_SHADER); };
    }
}

ObjectName compileShader(const std::string& programName, GLenum stage, std::string_view source) {
    ObjectName shader("Program", shaderCreator(stage), deleteShader);
    const GLchar* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    glShaderSource(shader.id(), 1, &text, &length);
    glCompileShader(shader.id());
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        throw GlError(programName + ": " + stageName(stage) + " shader does not compile:\n" +
                      infoLog(shader.id(), glGetShaderiv, glGetShaderInfoLog));
    }
    return shader;
}

} // namespace

Program::Program(std::string name, std::string_view vertexSource,
                 std::string_view fragmentSource, std::string_view geometrySource)
    : mName("Program", createProgram, deleteProgram), mLabel(std::move(name)) {
    std::vector<ObjectName> shaders;
    shaders.push_back(compileShader(mLabel, GL_VERTEX_SHADER, vertexSource));
    if (!geometrySource.empty()) {
        shaders.push_back(compileShader(mLabel, GL_GEOMETRY_SHADER, geometrySource));
    }
    shaders.push_back(compileShader(mLabel, GL_FRAGMENT_SHADER, fragmentSource));
    for (const ObjectName& shader : shaders) {
        glAttachShader(id(), shader.id());
    }
    glLinkProgram(id());
    // Detached, the shaders are deleted with `shaders`; the linked program keeps its code.
    for (const ObjectName& shader : shaders) {
        glDetachShader(id(), shader.id());
    }
    GLint linked = GL_FALSE;
    glGetProgramiv(id(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        throw GlError(mLabel + ": program does not link:\n" +
                      infoLog(id(), glGetProgramiv, glGetProgramInfoLog));
    }
}

void Program::use() const {
    TEXSPLAT_ASSERT(id() != 0, "Program::use(): empty (moved-from) program");
    glUseProgram(id());
}

GLint Program::uniformLocation(std::string_view uniform) {
    const auto found = mUniformLocations.find(uniform);
    if (found != mUniformLocations.end()) {
        return found->second;
    }
    std::string key(uniform);
    const GLint location = glGetUniformLocation(id(), key.c_str());
    if (location < 0) {
        log(LogLevel::Warning,
            mLabel + ": no active uniform '" + key + "' (setting it has no effect)");
    }
    mUniformLocations.emplace(std::move(key), location);
    return location;
}

void Program::setUniform(std::string_view uniform, float value) {
    use();
    glUniform1f(uniformLocation(uniform), value);
}

void Program::setUniform(std::string_view uniform, int value) {
    use();
    glUniform1i(uniformLocation(uniform), value);
}

void Program::setUniform(std::string_view uniform, const glm::vec2& value) {
    use();
    glUniform2fv(uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view uniform, const glm::vec3& value) {
    use();
    glUniform3fv(uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view uniform, const glm::vec4& value) {
    use();
    glUniform4fv(uniformLocation(uniform), 1, glm::value_ptr(value));
}

void Program::setUniform(std::string_view uniform, const glm::mat3& value) {
    use();
    glUniformMatrix3fv(uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::setUniform(std::string_view uniform, const glm::mat4& value) {
    use();
    glUniformMatrix4fv(uniformLocation(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

} // namespace texsplat::gl
