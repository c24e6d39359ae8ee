#include "nodes/render/gl/MeshBatch.h"

#include "nodes/TriangleMesh.h"
#include "nodes/elements/LightElement.h"
#include "scenegraph/Assert.h"
#include "scenegraph/gl/LightScale.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <limits>
#include <string>

namespace texsplat::render {
namespace {

constexpr const char* kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 localToClip;
uniform mat3 normalToRoot;
out vec3 rootNormal;
out vec3 vertexColor;
void main() {
    gl_Position = localToClip * vec4(position, 1.0);
    rootNormal = normalToRoot * normal;
    vertexColor = color;
}
)";

constexpr const char* kMeshFragmentShader = R"(#version 330 core
const int kMaxLights = 8;
in vec3 rootNormal;
in vec3 vertexColor;
uniform int lightCount;
uniform vec3 lightDirections[kMaxLights];
uniform vec3 lightColors[kMaxLights];
uniform vec3 emissiveColor;
out vec4 fragColor;
void main() {
    float length2 = dot(rootNormal, rootNormal);
    vec3 n = length2 > 0.0 ? rootNormal / sqrt(length2) : vec3(0.0);
    vec3 lit = emissiveColor;
    for (int i = 0; i < lightCount; ++i) {
        lit += vertexColor * lightColors[i] * abs(dot(n, lightDirections[i]));
    }
    // Light is drawn scaled (gl/LightScale.h), beyond FLT_MAX as FLT_MAX.
    fragColor = vec4(min(lit, vec3(3.4028235e38)) * lightScale, 1.0);
}
)";

// Interleaved position, normal, color: 9 floats per vertex.
std::vector<float> interleave(const nodes::TriangleMesh& mesh) {
    TEXSPLAT_ASSERT(mesh.normals.size() == mesh.positions.size() &&
                        mesh.colors.size() == mesh.positions.size(),
                    "MeshBatch::MeshBatch(): positions, normals and colors must be parallel");
    std::vector<float> vertices;
    vertices.reserve(mesh.positions.size() * 9);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        for (const glm::vec3& value : {mesh.positions[i], mesh.normals[i], mesh.colors[i]}) {
            vertices.insert(vertices.end(), {value.x, value.y, value.z});
        }
    }
    return vertices;
}

} // namespace

MeshBatch::MeshBatch(const nodes::TriangleMesh& mesh)
    : mProgram("mesh", kMeshVertexShader, gl::withLightScale(kMeshFragmentShader)),
      mIndexCount(mesh.indices.size()) {
    TEXSPLAT_ASSERT(mIndexCount <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                    "MeshBatch::MeshBatch(): more indices than one draw can take");
    mVertices.setData(interleave(mesh));
    mIndices.setData(mesh.indices);
    constexpr std::size_t kStride = 9 * sizeof(float);
    mVertexArray.setAttribute(0, mVertices, 3, kStride, 0);
    mVertexArray.setAttribute(1, mVertices, 3, kStride, 3 * sizeof(float));
    mVertexArray.setAttribute(2, mVertices, 3, kStride, 6 * sizeof(float));
    mVertexArray.setIndexBuffer(mIndices);
}

void MeshBatch::draw(const MeshLighting& lighting) {
    if (mIndexCount == 0) {
        return;
    }
    mProgram.use();
    mProgram.setUniform("localToClip", lighting.localToClip);
    mProgram.setUniform("normalToRoot", glm::inverseTranspose(glm::mat3(lighting.model)));
    mProgram.setUniform("emissiveColor", lighting.emissiveColor);
    const std::vector<nodes::DirectionalLightSource> lights = lighting.effectiveLights();
    const auto count = static_cast<int>(lights.size());
    mProgram.setUniform("lightCount", count);
    for (int i = 0; i < count; ++i) {
        const std::string index = "[" + std::to_string(i) + "]";
        // The shader wants the direction toward the light.
        mProgram.setUniform("lightDirections" + index,
                            -lights[static_cast<std::size_t>(i)].direction);
        mProgram.setUniform("lightColors" + index, lights[static_cast<std::size_t>(i)].color);
    }
    mVertexArray.drawElements(GL_TRIANGLES, static_cast<int>(mIndexCount));
}

} // namespace texsplat::render
