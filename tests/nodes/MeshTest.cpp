#include "nodes/Mesh.h"

#include "SceneNodesTestSupport.h"
#include "nodes/NodeTypes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/io/SceneReader.h"
#include "tests/scenegraph/TestFifo.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#ifdef TEXSPLAT_WITH_GLTF

namespace texsplat::nodes {
namespace {

using test::errorOf;
using test::testPath;

// One triangle (0,0,0), (1,0,0), (0,1,0) as float VEC3 positions (36 bytes) and uint16 indices
// 0 1 2 (6 bytes, padded to 8), base64 in a data URI.
constexpr const char* kBuffer =
    "data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";

std::string triangleGltf(const std::string& mode, const std::string& nodeExtra) {
    return R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0)" + nodeExtra + R"(}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0,
                              "mode": )" + mode + R"(}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.5, 0.75, 1.0]}}],
  "buffers": [{"byteLength": 44, "uri": ")" + kBuffer + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = testPath(name);
    std::ofstream(path) << text;
    return path;
}

TEST(Mesh, readsATriangleWithItsNodeTransformAndBaseColour) {
    const std::string path = writeFile(
        "triangle.gltf", triangleGltf("4", R"(, "translation": [10, 0, 0], "scale": [2, 2, 2])"));
    const auto mesh = Mesh::create();
    mesh->fileName = path;
    EXPECT_FALSE(mesh->isLoaded());
    const std::shared_ptr<const TriangleMesh> triangles = mesh->triangleMesh();
    EXPECT_TRUE(mesh->isLoaded());
    EXPECT_EQ(triangles->positions, (std::vector<glm::vec3>{{10, 0, 0}, {12, 0, 0}, {10, 2, 0}}));
    EXPECT_EQ(triangles->indices, (std::vector<std::uint32_t>{0, 1, 2}));
    // No NORMAL attribute: computed from the triangle.
    EXPECT_EQ(triangles->normals, std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)));
    EXPECT_EQ(triangles->colors, std::vector<glm::vec3>(3, glm::vec3(0.25f, 0.5f, 0.75f)));
    EXPECT_EQ(mesh->triangleMesh(), triangles); // cached

    const auto root = sg::Separator::create();
    root->addChild(mesh);
    sg::BoundingBoxAction action;
    action.apply(*root);
    EXPECT_EQ(action.boundingBox(), sg::Box3(glm::vec3(10, 0, 0), glm::vec3(12, 2, 0)));
}

TEST(Mesh, aRelativeFileNameIsResolvedAgainstTheSceneFilesFolder) {
    registerNodeTypes();
    const std::string name =
        std::filesystem::path(writeFile("relative.gltf", triangleGltf("4", ""))).filename();
    // The scene names the file relative to its own folder, which is not the working directory.
    const std::string scene = writeFile(
        "relative-mesh.iv", "#Inventor V2.1 ascii\nMesh { fileName \"" + name + "\" }\n");
    const sg::Node::Ptr root = sg::SceneReader::readFile(scene);
    const auto& mesh = static_cast<const Mesh&>(*root);
    EXPECT_EQ(mesh.fileName.value(), name);
    EXPECT_EQ(mesh.triangleMesh()->positions.size(), 3u);
}

TEST(Mesh, rereadsWhenTheFileNameChanges) {
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("first.gltf", triangleGltf("4", ""));
    EXPECT_EQ(mesh->triangleMesh()->positions[1], glm::vec3(1, 0, 0));
    mesh->fileName = writeFile("second.gltf", triangleGltf("4", R"(, "translation": [0, 0, 5])"));
    EXPECT_FALSE(mesh->isLoaded());
    EXPECT_EQ(mesh->triangleMesh()->positions[1], glm::vec3(1, 0, 5));
}

TEST(Mesh, reportsUnreadableFiles) {
    const auto mesh = Mesh::create();
    mesh->setName("part");
    EXPECT_EQ(errorOf<DataError>([&] { mesh->triangleMesh(); }),
              "Mesh 'part': fileName is empty; a Mesh reads a glTF file");
    const std::string missing = testPath("missing.gltf");
    mesh->fileName = missing;
    EXPECT_EQ(errorOf<IoError>([&] { mesh->triangleMesh(); }),
              "Mesh 'part': " + missing + ": cannot open file (No such file or directory)");
    const std::string broken = writeFile("broken.gltf", "{ this is not json");
    mesh->fileName = broken;
    const std::string message = errorOf<ParseError>([&] { mesh->triangleMesh(); });
    EXPECT_EQ(message.rfind("Mesh 'part': " + broken + ": not a readable glTF 2.0 file: ", 0), 0u)
        << message;
    EXPECT_NE(message.find("parse error"), std::string::npos) << message; // tinygltf's reason
    mesh->fileName = writeFile("lines.gltf", triangleGltf("1", ""));
    EXPECT_EQ(errorOf<DataError>([&] { mesh->triangleMesh(); }),
              "Mesh 'part': " + testPath("lines.gltf") +
                  ": mesh 0 primitive 0: mode 1 is not supported; texsplat reads triangles "
                  "(mode 4) only");
}

TEST(Mesh, reportsAccessorsOutsideTheirBuffer) {
    std::string text = triangleGltf("4", "");
    const std::string fitting = R"("count": 3, "type": "SCALAR")";
    text.replace(text.find(fitting), fitting.size(), R"("count": 30, "type": "SCALAR")");
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("overrun.gltf", text);
    EXPECT_EQ(errorOf<ParseError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("overrun.gltf") +
                  ": accessor 1 (indices) reaches beyond its buffer view or buffer: 30 elements "
                  "of 2 bytes, 2 apart, from byte 0 of buffer view 1, which holds 6 bytes");
}

TEST(Mesh, refusesAnAccessorBombBeforeAllocatingForIt) {
    // 10^18 positions over the 36-byte view: allocating first would throw std::length_error (at
    // 10^9 it allocated and filled 11 GB before this check).
    std::string text = triangleGltf("4", "");
    const std::string positions = R"("count": 3, "type": "VEC3")";
    text.replace(text.find(positions), positions.size(),
                 R"("count": 1000000000000000000, "type": "VEC3")");
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("bomb.gltf", text);
    EXPECT_EQ(errorOf<ParseError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("bomb.gltf") +
                  ": accessor 0 (POSITION) reaches beyond its buffer view or buffer: "
                  "1000000000000000000 elements of 12 bytes, 12 apart, from byte 0 of buffer "
                  "view 0, which holds 36 bytes");
    // A view that lies outside its buffer.
    text = triangleGltf("4", "");
    const std::string view = R"("byteOffset": 36, "byteLength": 6)";
    text.replace(text.find(view), view.size(), R"("byteOffset": 36, "byteLength": 600)");
    mesh->fileName = writeFile("view.gltf", text);
    EXPECT_EQ(errorOf<ParseError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("view.gltf") +
                  ": accessor 1 (indices) reaches beyond its buffer view or buffer: buffer view "
                  "1 (bytes 36 to 636) lies outside buffer 0 (44 bytes)");
}

TEST(Mesh, refusesJsonNestedDeeperThanTheLimitBeforeTinygltfSeesIt) {
    // 100 000 levels overflowed the stack inside tinygltf; 256 are read.
    const auto nested = [](int levels) {
        std::string extras;
        for (int i = 0; i < levels; ++i) {
            extras += R"({"a":)";
        }
        extras += "1" + std::string(std::size_t(levels), '}');
        return triangleGltf("4", R"(, "extras": )" + extras);
    };
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("deep.gltf", nested(100000));
    // Line 5 holds the node: after `  "nodes": [{"mesh": 0, "extras": ` (34 columns; the file's
    // object, the array and the node are 3 levels) the 254th `{"a":` opens level 257.
    EXPECT_EQ(errorOf<ParseError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("deep.gltf") +
                  ":5:1300: JSON objects and arrays nested deeper than the limit of 256 levels");
    mesh->fileName = writeFile("fits.gltf", nested(250));
    EXPECT_EQ(mesh->triangleMesh()->positions.size(), 3u);
    // Brackets in strings, escaped quotes included, do not count.
    mesh->fileName = writeFile(
        "strings.gltf", triangleGltf("4", R"(, "extras": {"s": "\"[[[[" , "t": ")" +
                                              std::string(1000, '{') + R"("})"));
    EXPECT_EQ(mesh->triangleMesh()->positions.size(), 3u);
}

TEST(Mesh, refusesABufferThatIsAFifo) {
    const texsplat::test::TestFifo pipe(testPath("buffer.bin"));
    const std::string& fifo = pipe.path();
    std::string text = triangleGltf("4", "");
    text.replace(text.find(kBuffer), std::string(kBuffer).size(),
                 std::filesystem::path(fifo).filename().string());
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("fifo.gltf", text);
    EXPECT_EQ(errorOf<IoError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("fifo.gltf") + ": " + fifo +
                  ": cannot read glTF buffer: it is a FIFO, not a regular file");
    mesh->fileName = fifo;
    EXPECT_EQ(errorOf<IoError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + fifo + ": cannot read glTF file: it is a FIFO, not a regular file");
}

// A glTF may name a buffer outside its folder (docs/reliability.md, "Decisions"): a scene file
// names files anywhere already, and models share texture and buffer folders.
TEST(Mesh, readsABufferInTheFolderAboveTheGltfs) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[4] = {0, 1, 2, 0};
    const std::string buffer = testPath("shared-triangle.bin");
    std::ofstream bytes(buffer, std::ios::binary);
    bytes.write(reinterpret_cast<const char*>(positions), sizeof positions);
    bytes.write(reinterpret_cast<const char*>(indices), sizeof indices);
    bytes.close();
    std::filesystem::create_directories(testPath("models"));
    std::string text = triangleGltf("4", "");
    text.replace(text.find(kBuffer), std::string(kBuffer).size(),
                 "../" + std::filesystem::path(buffer).filename().string());
    const auto mesh = Mesh::create();
    mesh->fileName = writeFile("models/above.gltf", text);
    EXPECT_EQ(mesh->triangleMesh()->positions,
              (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));

    // Confined to the models' folder (`--data-root`), the buffer above it is refused before it is
    // read, and so is a glTF outside it; the folder's own files are read.
    const auto roots = std::make_shared<const sg::DataRoots>(
        std::vector<std::string>{std::filesystem::canonical(testPath("models")).string()});
    mesh->setDataRoots(roots);
    mesh->touch();
    const std::string real = std::filesystem::canonical(buffer).string();
    EXPECT_EQ(errorOf<IoError>([&] { mesh->triangleMesh(); }),
              "Mesh: " + testPath("models/above.gltf") + ": " + testPath("models") + "/../" +
                  std::filesystem::path(buffer).filename().string() +
                  ": cannot read glTF buffer: it lies outside the data roots (" +
                  roots->folders().front() + ") (it leads to " + real +
                  "), which --data-root confines the files a scene reads to");
    const auto outside = Mesh::create();
    outside->setDataRoots(roots);
    outside->fileName = writeFile("outside.gltf", text);
    EXPECT_EQ(errorOf<IoError>([&] { outside->triangleMesh(); }).rfind(
                  "Mesh: " + testPath("outside.gltf") + ": cannot read glTF file: it lies outside "
                  "the data roots", 0),
              0u);
}

} // namespace
} // namespace texsplat::nodes

#endif
