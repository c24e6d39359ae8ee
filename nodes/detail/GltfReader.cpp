#include "nodes/detail/GltfReader.h"

#include "nodes/detail/JsonNesting.h"
#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"

#ifdef TEXSPLAT_WITH_GLTF
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>
#endif

namespace texsplat::nodes::detail {

#ifndef TEXSPLAT_WITH_GLTF

bool isGltfAvailable() { return false; }

TriangleMesh readGltf(const std::string& path, const sg::DataRoots* /*roots*/) {
    throw IoError(path + ": cannot read glTF: texsplat was built without glTF support "
                         "(TEXSPLAT_WITH_GLTF=OFF)");
}

#else

bool isGltfAvailable() { return true; }

namespace {

// Reads one accessor of a model, checking that everything it addresses lies in its buffer.
class AccessorReader {
public:
    AccessorReader(const tinygltf::Model& model, const std::string& path)
        : mModel(model), mPath(path) {}

    std::vector<glm::vec3> vec3s(int accessorIndex, const char* what) const {
        const tinygltf::Accessor& accessor = checkedAccessor(accessorIndex, what);
        if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
            accessor.type != TINYGLTF_TYPE_VEC3) {
            fail(what, accessorIndex, "must hold float VEC3 values");
        }
        const Elements span = elements(accessor, accessorIndex, what);
        std::vector<glm::vec3> values(span.count);
        for (std::size_t i = 0; i < span.count; ++i) {
            std::memcpy(&values[i], span.first + span.stride * i, sizeof(glm::vec3));
            if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) ||
                !std::isfinite(values[i].z)) {
                fail(what, accessorIndex, "holds a non-finite value at element " +
                                              std::to_string(i));
            }
        }
        return values;
    }

    std::vector<std::uint32_t> indices(int accessorIndex) const {
        const char* what = "indices";
        const tinygltf::Accessor& accessor = checkedAccessor(accessorIndex, what);
        if (accessor.type != TINYGLTF_TYPE_SCALAR) {
            fail(what, accessorIndex, "must hold SCALAR values");
        }
        const int type = accessor.componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
            fail(what, accessorIndex, "must hold unsigned byte, short or int values");
        }
        const Elements span = elements(accessor, accessorIndex, what);
        std::vector<std::uint32_t> values(span.count);
        for (std::size_t i = 0; i < span.count; ++i) {
            const unsigned char* p = span.first + span.stride * i;
            if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                values[i] = *p;
            } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                std::uint16_t value = 0;
                std::memcpy(&value, p, sizeof(value));
                values[i] = value;
            } else {
                std::memcpy(&values[i], p, sizeof(std::uint32_t));
            }
        }
        return values;
    }

private:
    [[noreturn]] void fail(const char* what, int accessorIndex, const std::string& why) const {
        throw ParseError(mPath + ": accessor " + std::to_string(accessorIndex) + " (" + what +
                         ") " + why);
    }

    const tinygltf::Accessor& checkedAccessor(int accessorIndex, const char* what) const {
        if (accessorIndex < 0 ||
            static_cast<std::size_t>(accessorIndex) >= mModel.accessors.size()) {
            fail(what, accessorIndex, "does not exist");
        }
        const tinygltf::Accessor& accessor = mModel.accessors[std::size_t(accessorIndex)];
        if (accessor.sparse.isSparse) {
            fail(what, accessorIndex, "is sparse, which texsplat does not read");
        }
        return accessor;
    }

    // Where an accessor's elements lie in its buffer, checked against the buffer view and the
    // buffer before anything is allocated for them: a count comes from the file and may be 10^9
    // over a 36-byte view.
    struct Elements {
        const unsigned char* first = nullptr;
        std::size_t stride = 0;
        std::size_t count = 0;
    };

    Elements elements(const tinygltf::Accessor& accessor, int accessorIndex,
                      const char* what) const {
        if (accessor.count == 0) {
            return {};
        }
        if (accessor.bufferView < 0 ||
            static_cast<std::size_t>(accessor.bufferView) >= mModel.bufferViews.size()) {
            fail(what, accessorIndex, "has no buffer view");
        }
        const tinygltf::BufferView& view = mModel.bufferViews[std::size_t(accessor.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= mModel.buffers.size()) {
            fail(what, accessorIndex, "refers to a missing buffer");
        }
        const std::vector<unsigned char>& data = mModel.buffers[std::size_t(view.buffer)].data;
        const int stride = accessor.ByteStride(view);
        const int elementSize = tinygltf::GetComponentSizeInBytes(
                                    static_cast<std::uint32_t>(accessor.componentType)) *
                                tinygltf::GetNumComponentsInType(
                                    static_cast<std::uint32_t>(accessor.type));
        if (stride <= 0 || elementSize <= 0) {
            fail(what, accessorIndex, "has an invalid component type or byte stride");
        }
        // Each step is checked before the next uses it, so nothing wraps around.
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
            fail(what, accessorIndex,
                 "reaches beyond its buffer view or buffer: buffer view " +
                     std::to_string(accessor.bufferView) + " (bytes " +
                     std::to_string(view.byteOffset) + " to " +
                     std::to_string(std::uint64_t(view.byteOffset) + view.byteLength) +
                     ") lies outside buffer " + std::to_string(view.buffer) + " (" +
                     std::to_string(data.size()) + " bytes)");
        }
        const std::uint64_t available =
            accessor.byteOffset <= view.byteLength ? view.byteLength - accessor.byteOffset : 0;
        const std::uint64_t lastStart = accessor.count - 1;
        if (accessor.byteOffset > view.byteLength || available < std::uint64_t(elementSize) ||
            lastStart > (available - std::uint64_t(elementSize)) / std::uint64_t(stride)) {
            fail(what, accessorIndex,
                 "reaches beyond its buffer view or buffer: " + std::to_string(accessor.count) +
                     " elements of " + std::to_string(elementSize) + " bytes, " +
                     std::to_string(stride) + " apart, from byte " +
                     std::to_string(accessor.byteOffset) + " of buffer view " +
                     std::to_string(accessor.bufferView) + ", which holds " +
                     std::to_string(view.byteLength) + " bytes");
        }
        return {data.data() + view.byteOffset + accessor.byteOffset, std::size_t(stride),
                accessor.count};
    }

    const tinygltf::Model& mModel;
    const std::string& mPath;
};

glm::mat4 localMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 matrix;
        std::memcpy(glm::value_ptr(matrix), node.matrix.data(), sizeof(matrix));
        return glm::mat4(matrix);
    }
    glm::mat4 matrix(1.0f);
    if (node.translation.size() == 3) {
        matrix = glm::translate(matrix, glm::vec3(glm::make_vec3(node.translation.data())));
    }
    if (node.rotation.size() == 4) {
        // glTF stores x, y, z, w; glm's constructor takes w first.
        const glm::quat rotation(float(node.rotation[3]), float(node.rotation[0]),
                                 float(node.rotation[1]), float(node.rotation[2]));
        matrix *= glm::mat4_cast(rotation);
    }
    if (node.scale.size() == 3) {
        matrix = glm::scale(matrix, glm::vec3(glm::make_vec3(node.scale.data())));
    }
    return matrix;
}

glm::vec3 baseColor(const tinygltf::Model& model, int materialIndex) {
    if (materialIndex < 0 || static_cast<std::size_t>(materialIndex) >= model.materials.size()) {
        return glm::vec3(1.0f); // glTF's default base colour
    }
    const std::vector<double>& factor =
        model.materials[std::size_t(materialIndex)].pbrMetallicRoughness.baseColorFactor;
    return factor.size() >= 3 ? glm::vec3(factor[0], factor[1], factor[2]) : glm::vec3(1.0f);
}

TriangleMesh meshTriangles(const tinygltf::Model& model, const AccessorReader& reader,
                           std::size_t meshIndex, const std::string& path) {
    TriangleMesh result;
    const tinygltf::Mesh& mesh = model.meshes[meshIndex];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = mesh.primitives[p];
        const std::string where = path + ": mesh " + std::to_string(meshIndex) + " primitive " +
                                  std::to_string(p);
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
            throw DataError(where + ": mode " + std::to_string(primitive.mode) +
                            " is not supported; texsplat reads triangles (mode 4) only");
        }
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) {
            throw ParseError(where + ": has no POSITION attribute");
        }
        TriangleMesh part;
        part.positions = reader.vec3s(position->second, "POSITION");
        if (primitive.indices >= 0) {
            part.indices = reader.indices(primitive.indices);
        } else {
            for (std::size_t i = 0; i < part.positions.size(); ++i) {
                part.indices.push_back(static_cast<std::uint32_t>(i));
            }
        }
        if (part.indices.size() % 3 != 0) {
            throw ParseError(where + ": " + std::to_string(part.indices.size()) +
                             " indices do not make whole triangles");
        }
        for (const std::uint32_t index : part.indices) {
            if (index >= part.positions.size()) {
                throw ParseError(where + ": index " + std::to_string(index) +
                                 " is out of range (" + std::to_string(part.positions.size()) +
                                 " vertices)");
            }
        }
        const auto normal = primitive.attributes.find("NORMAL");
        if (normal != primitive.attributes.end()) {
            part.normals = reader.vec3s(normal->second, "NORMAL");
        }
        if (part.normals.size() != part.positions.size()) {
            part.computeNormals();
        }
        part.colors.assign(part.positions.size(), baseColor(model, primitive.material));
        result.append(part);
    }
    return result;
}

void applyMatrix(TriangleMesh& mesh, const glm::mat4& matrix) {
    const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(matrix));
    for (glm::vec3& position : mesh.positions) {
        position = glm::vec3(matrix * glm::vec4(position, 1.0f));
    }
    for (glm::vec3& normal : mesh.normals) {
        const glm::vec3 mapped = normalMatrix * normal;
        const float length = glm::length(mapped);
        normal = length > 0.0f ? mapped / length : normal;
    }
    if (glm::determinant(glm::mat3(matrix)) < 0.0f) {
        // A mirroring transform turns the winding; swap two corners to keep fronts in front.
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
        }
    }
}

TriangleMesh sceneTriangles(const tinygltf::Model& model, const std::string& path) {
    const AccessorReader reader(model, path);
    TriangleMesh result;
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size()) {
        for (std::size_t m = 0; m < model.meshes.size(); ++m) {
            result.append(meshTriangles(model, reader, m, path));
        }
        return result;
    }
    // Iterative walk (a deep hierarchy must not exhaust the stack); glTF nodes form a forest, so
    // a node reached twice means a malformed file (and would otherwise loop forever).
    std::vector<bool> visited(model.nodes.size(), false);
    std::vector<std::pair<int, glm::mat4>> pending;
    for (const int root : model.scenes[std::size_t(sceneIndex)].nodes) {
        pending.emplace_back(root, glm::mat4(1.0f));
    }
    while (!pending.empty()) {
        const auto [nodeIndex, parentMatrix] = pending.back();
        pending.pop_back();
        if (nodeIndex < 0 || static_cast<std::size_t>(nodeIndex) >= model.nodes.size()) {
            throw ParseError(path + ": node " + std::to_string(nodeIndex) + " does not exist");
        }
        if (visited[std::size_t(nodeIndex)]) {
            throw ParseError(path + ": node " + std::to_string(nodeIndex) +
                             " is reached twice; the node hierarchy must be a forest");
        }
        visited[std::size_t(nodeIndex)] = true;
        const tinygltf::Node& node = model.nodes[std::size_t(nodeIndex)];
        const glm::mat4 matrix = parentMatrix * localMatrix(node);
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model.meshes.size()) {
                throw ParseError(path + ": node " + std::to_string(nodeIndex) + " refers to mesh " +
                                 std::to_string(node.mesh) + ", which does not exist");
            }
            TriangleMesh part = meshTriangles(model, reader, std::size_t(node.mesh), path);
            applyMatrix(part, matrix);
            result.append(part);
        }
        for (const int child : node.children) {
            pending.emplace_back(child, matrix);
        }
    }
    return result;
}

bool hasBinaryExtension(const std::string& path) {
    const std::string extension = ".glb";
    if (path.size() < extension.size()) {
        return false;
    }
    std::string tail = path.substr(path.size() - extension.size());
    for (char& c : tail) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return tail == extension;
}

// The JSON of a .glb: its first chunk, when the container header and chunk header fit the file
// (glTF 2.0, section 4.4); otherwise tinygltf reports what is wrong.
std::string_view glbJson(const std::vector<unsigned char>& bytes) {
    const auto word = [&bytes](std::size_t offset) {
        return std::uint32_t(bytes[offset]) | std::uint32_t(bytes[offset + 1]) << 8 |
               std::uint32_t(bytes[offset + 2]) << 16 | std::uint32_t(bytes[offset + 3]) << 24;
    };
    constexpr std::uint32_t kJsonChunk = 0x4E4F534A; // "JSON"
    if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0 ||
        word(16) != kJsonChunk || word(12) > bytes.size() - 20) {
        return {};
    }
    return {reinterpret_cast<const char*>(bytes.data()) + 20, word(12)};
}

std::vector<unsigned char> readBytes(const std::string& path, const std::string& what) {
    requireRegularFile(path, what);
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        // tinygltf reports a missing file as a parse failure; say what really happened.
        throw IoError(path + ": cannot open file (" +
                      (errno != 0 ? std::strerror(errno) : "unknown reason") + ")");
    }
    std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in),
                                     std::istreambuf_iterator<char>()};
    if (in.bad()) {
        throw IoError(path + ": cannot read " + what);
    }
    return bytes;
}

// tinygltf's own test opens the file, which blocks on a FIFO: ask the file system instead.
bool fileExists(const std::string& path, void* /*userData*/) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

// tinygltf's file reader for buffers and images that the glTF names by URI, refusing FIFOs and
// devices as readGltf refuses them for the glTF itself, and files outside the data roots
// (`userData`, null for none). The IoError passes through tinygltf.
bool readReferencedFile(std::vector<unsigned char>* out, std::string* error,
                        const std::string& path, void* userData) {
    if (const auto* roots = static_cast<const sg::DataRoots*>(userData)) {
        roots->check(path, "glTF buffer");
    }
    requireRegularFile(path, "glTF buffer");
    return tinygltf::ReadWholeFile(out, error, path, nullptr);
}

} // namespace

TriangleMesh readGltf(const std::string& path, const sg::DataRoots* roots) {
    const bool isBinary = hasBinaryExtension(path);
    const std::vector<unsigned char> bytes =
        readBytes(path, isBinary ? "glTF binary" : "glTF file");
    if (bytes.size() > std::numeric_limits<unsigned>::max()) {
        throw ParseError(path + ": " + std::to_string(bytes.size()) +
                         " bytes; tinygltf reads glTF files of at most 4 GiB");
    }
    if (isBinary) {
        checkJsonNesting(glbJson(bytes), path + " (JSON chunk)");
    } else {
        checkJsonNesting({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, path);
    }
    tinygltf::TinyGLTF loader;
    // tinygltf keeps the user data as a pointer to non-const; readReferencedFile only reads it.
    loader.SetFsCallbacks({&fileExists, &tinygltf::ExpandFilePath, &readReferencedFile,
                           &tinygltf::WriteWholeFile, const_cast<sg::DataRoots*>(roots)});
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const std::string folder = std::filesystem::path(path).parent_path().string();
    bool ok = false;
    try {
        ok = isBinary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                    static_cast<unsigned>(bytes.size()), folder)
                      : loader.LoadASCIIFromString(&model, &error, &warning,
                                                   reinterpret_cast<const char*>(bytes.data()),
                                                   static_cast<unsigned>(bytes.size()), folder);
    } catch (const IoError& failure) {
        throw IoError(path + ": " + failure.what());
    }
    if (!ok) {
        while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) {
            error.pop_back();
        }
        throw ParseError(path + ": not a readable glTF 2.0 file: " +
                         (error.empty() ? std::string("tinygltf gave no reason") : error));
    }
    return sceneTriangles(model, path);
}

#endif

} // namespace texsplat::nodes::detail
