#include "scenegraph/gl/Program.h"

#include "GlTestSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"
#include "scenegraph/gl/Framebuffer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace texsplat::gl {
namespace {

// The message of the GlError that creating `name` from these sources throws.
std::string creationError(const char* name, const char* vertex, const char* fragment,
                          const char* geometry = "") {
    try {
        Program program(name, vertex, fragment, geometry);
    } catch (const GlError& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(Program, fragmentCompileErrorNamesStageAndDriverLog) {
    test::sharedContext();
    const std::string message = creationError("broken", test::kPositionVertexShader,
                                              R"(#version 330 core
out vec4 fragColor;
void main() { fragColor = undeclaredThing; }
)");
    const std::string prefix = "broken: fragment shader does not compile:\n";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    // The driver's own log follows: it names the offending identifier and line.
    EXPECT_NE(message.find("undeclaredThing", prefix.size()), std::string::npos) << message;
    EXPECT_NE(message.find("0:3", prefix.size()), std::string::npos) << message;
}

TEST(Program, vertexAndGeometryCompileErrorsNameTheirStage) {
    test::sharedContext();
    const std::string vertex = creationError("v", "#version 330 core\nvoid main() { oops; }\n",
                                             test::kUniformColorFragmentShader);
    EXPECT_EQ(vertex.rfind("v: vertex shader does not compile:\n", 0), 0u) << vertex;
    const std::string geometry =
        creationError("g", test::kPositionVertexShader, test::kUniformColorFragmentShader,
                      "#version 330 core\nvoid main() { oops; }\n");
    EXPECT_EQ(geometry.rfind("g: geometry shader does not compile:\n", 0), 0u) << geometry;
}

TEST(Program, linkErrorCarriesTheDriverLog) {
    test::sharedContext();
    const std::string message = creationError("unresolved", test::kPositionVertexShader,
                                              R"(#version 330 core
vec4 declaredNeverDefined();
out vec4 fragColor;
void main() { fragColor = declaredNeverDefined(); }
)");
    const std::string prefix = "unresolved: program does not link:\n";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_NE(message.find("declaredNeverDefined", prefix.size()), std::string::npos) << message;
}

TEST(Program, uniformSettersReachTheShader) {
    test::sharedContext();
    Framebuffer framebuffer(1, 1);
    framebuffer.clear(glm::vec4(0.0f));
    Program program("uniforms", test::kPositionVertexShader, R"(#version 330 core
uniform float scale;
uniform int count;
uniform vec2 pair;
uniform vec3 triple;
uniform vec4 quad;
uniform mat3 rotation;
uniform mat4 transform;
out vec4 fragColor;
void main() {
    vec4 moved = transform * vec4(1.0, 2.0, 3.0, 1.0);
    vec3 turned = rotation * vec3(1.0, 0.0, 0.0);
    fragColor = vec4(scale * float(count) + pair.x * pair.y, dot(triple, quad.xyz) + quad.w,
                     moved.x + moved.y + moved.z, turned.y);
}
)");
    program.setUniform("scale", 1.5f);
    program.setUniform("count", 4);
    program.setUniform("pair", glm::vec2(2.0f, 3.0f));
    program.setUniform("triple", glm::vec3(1.0f, 2.0f, 3.0f));
    program.setUniform("quad", glm::vec4(4.0f, 5.0f, 6.0f, 0.5f));
    program.setUniform("rotation", glm::mat3(glm::vec3(0.0f, 1.0f, 0.0f),
                                             glm::vec3(-1.0f, 0.0f, 0.0f),
                                             glm::vec3(0.0f, 0.0f, 1.0f)));
    program.setUniform("transform", glm::translate(glm::mat4(1.0f), glm::vec3(10.0f, 20.0f,
                                                                              30.0f)));
    test::makeRectangle(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f).draw();
    const std::vector<float> pixel = framebuffer.readColor();
    EXPECT_EQ(pixel[0], 1.5f * 4.0f + 6.0f);
    EXPECT_EQ(pixel[1], 4.0f + 10.0f + 18.0f + 0.5f);
    EXPECT_EQ(pixel[2], 11.0f + 22.0f + 33.0f);
    EXPECT_EQ(pixel[3], 1.0f);
}

TEST(Program, unknownUniformIsLoggedOnceAndIgnored) {
    test::sharedContext();
    std::vector<std::string> warnings;
    LogSink previous = setLogSink([&](LogLevel level, std::string_view message) {
        if (level == LogLevel::Warning) {
            warnings.emplace_back(message);
        }
    });
    Program program("splat", test::kPositionVertexShader, test::kUniformColorFragmentShader);
    program.setUniform("colour", glm::vec4(1.0f));
    program.setUniform("colour", glm::vec4(2.0f));
    const GLint location = program.uniformLocation("color");
    setLogSink(previous);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "splat: no active uniform 'colour' (setting it has no effect)");
    EXPECT_EQ(program.uniformLocation("colour"), -1);
    EXPECT_GE(location, 0);
}

TEST(Program, geometryStageRunsBetweenVertexAndFragment) {
    test::sharedContext();
    Framebuffer framebuffer(2, 1);
    framebuffer.clear(glm::vec4(0.0f));
    // The geometry stage mirrors the triangle it gets, so a left-half triangle fills the right.
    Program program("mirror", test::kPositionVertexShader, test::kUniformColorFragmentShader,
                    R"(#version 330 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = vec4(-gl_in[i].gl_Position.x, gl_in[i].gl_Position.yzw);
        EmitVertex();
    }
    EndPrimitive();
}
)");
    program.setUniform("color", glm::vec4(1.0f));
    test::makeRectangle(-1.0f, -1.0f, 0.0f, 1.0f, 0.0f).draw();
    const std::vector<float> pixels = framebuffer.readColor();
    EXPECT_EQ(pixels[0], 0.0f);
    EXPECT_EQ(pixels[4], 1.0f);
}

TEST(Program, needsACurrentContext) {
    std::string message;
    // A fresh thread has no current context.
    std::thread([&] {
        try {
            Program program("p", test::kPositionVertexShader, test::kUniformColorFragmentShader);
        } catch (const GlError& error) {
            message = error.what();
        }
    }).join();
    EXPECT_EQ(message, "Program: no current OpenGL context (create a gl::Context and make it "
                       "current)");
}

TEST(Program, moveLeavesTheSourceEmpty) {
    static_assert(!std::is_copy_constructible_v<Program> &&
                  !std::is_copy_assignable_v<Program>);
    static_assert(std::is_nothrow_move_constructible_v<Program> &&
                  std::is_nothrow_move_assignable_v<Program>);
    test::sharedContext();
    Program source("p", test::kPositionVertexShader, test::kUniformColorFragmentShader);
    const GLuint id = source.id();
    Program target(std::move(source));
    EXPECT_EQ(source.id(), 0u);
    EXPECT_EQ(target.id(), id);
    EXPECT_EQ(target.name(), "p");
    EXPECT_EQ(glIsProgram(id), GL_TRUE);
    {
        Program dropped(std::move(target));
    }
    EXPECT_EQ(glIsProgram(id), GL_FALSE);
}

} // namespace
} // namespace texsplat::gl
