// Writes the seed files of the fuzz targets whose formats need a library to write (OpenVDB,
// PNG, OpenEXR, binary glTF) into <corpus folder>/<target>/, each a few hundred bytes to a few
// KB. scripts/make-fuzz-corpus.sh runs it and writes the text seeds; the results are committed.
// Usage: make_fuzz_corpus <corpus folder>

#include "nodes/image/Image.h"
#include "nodes/image/ImageIo.h"

#include <openvdb/openvdb.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// Valid files the VDB reader reads (a float and a vector grid with a scale and translation, an
// active tile) and one it refuses after listing it (a rotated transform); each grid within one
// of OpenVDB's top-level nodes, whose masks take 8 KB (uncompressed, even when zipped). Values
// are set through the trees: an accessor registers itself in a TBB hash map whose header trips
// UBSan's alignment check (a false positive of TBB 2021.8's sentinel pointers).
void writeVdbSeeds(const fs::path& folder) {
    openvdb::initialize();
    // Zip-compressed: the internal nodes' tables take kilobytes uncompressed.
    const auto write = [&folder](const std::string& name, const openvdb::GridPtrVec& grids) {
        openvdb::io::File file((folder / name).string());
        file.setCompression(openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
        file.write(grids);
    };
    openvdb::Mat4d matrix = openvdb::Mat4d::identity();
    matrix.preScale(openvdb::Vec3d(0.5, 1.0, 2.0));
    matrix.postTranslate(openvdb::Vec3d(10.0, 20.0, 30.0));

    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setTransform(openvdb::math::Transform::createLinearTransform(matrix));
    for (int i = 0; i < 6; ++i)
        density->tree().setValue({i, i, 2 * i}, 0.5f * float(i));
    write("density.vdb", {density});

    auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    velocity->setName("velocity");
    velocity->tree().setValue({7, 8, 9}, openvdb::Vec3s(1.0f, 2.0f, 3.0f));
    velocity->tree().setValue({8, 8, 9}, openvdb::Vec3s(-1.0f, 0.0f, 0.5f));
    write("velocity.vdb", {velocity});

    auto tile = openvdb::FloatGrid::create(0.0f);
    tile->setName("tile");
    tile->tree().addTile(1, openvdb::Coord(0, 0, 0), 1.0f, true); // one 8^3 tile
    auto rotated = openvdb::FloatGrid::create(0.0f);
    rotated->setName("rotated");
    rotated->transform().postRotate(0.3, openvdb::math::Z_AXIS);
    rotated->tree().setValue({0, 0, 0}, 1.0f);
    write("several.vdb", {tile, rotated});
}

// Small images: opaque, translucent and fully transparent pixels, one row and one column.
void writeImageSeeds(const fs::path& folder, const std::string& extension) {
    texsplat::image::Image gradient(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            gradient.setPixel(x, y, glm::vec4(0.2f * float(x), 0.3f * float(y), 0.1f,
                                              0.25f * float(x % 4)));
    texsplat::image::writeImage(gradient, (folder / ("gradient" + extension)).string());
    texsplat::image::Image row(4, 1);
    row.setPixel(1, 0, glm::vec4(1.0f));
    texsplat::image::writeImage(row, (folder / ("row" + extension)).string());
    texsplat::image::Image column(1, 4);
    column.setPixel(0, 2, glm::vec4(0.5f, 0.25f, 0.0f, 0.5f));
    texsplat::image::writeImage(column, (folder / ("column" + extension)).string());
}

// A triangle as a binary glTF (glTF 2.0, section 4.4): the JSON chunk, padded with spaces, then
// the BIN chunk with three float positions.
void writeGlbSeed(const fs::path& folder) {
    std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
        R"("buffers":[{"byteLength":36}]})";
    while (json.size() % 4 != 0)
        json += ' ';
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string bytes;
    const auto word = [&bytes](std::uint32_t value) {
        for (int i = 0; i < 4; ++i)
            bytes += char((value >> (8 * i)) & 0xFF);
    };
    bytes += "glTF";
    word(2);
    word(std::uint32_t(12 + 8 + json.size() + 8 + sizeof positions));
    word(std::uint32_t(json.size()));
    word(0x4E4F534A); // JSON
    bytes += json;
    word(sizeof positions);
    word(0x004E4942); // BIN
    bytes.append(reinterpret_cast<const char*>(positions), sizeof positions);
    std::ofstream(folder / "triangle.glb", std::ios::binary) << bytes;
}

fs::path targetFolder(const fs::path& corpus, const std::string& target) {
    fs::create_directories(corpus / target);
    return corpus / target;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_fuzz_corpus <corpus folder>\n");
        return 2;
    }
    const fs::path corpus = argv[1];
    writeVdbSeeds(targetFolder(corpus, "fuzz_vdb_reader"));
    writeImageSeeds(targetFolder(corpus, "fuzz_png_reader"), ".png");
    writeImageSeeds(targetFolder(corpus, "fuzz_exr_reader"), ".exr");
    writeGlbSeed(targetFolder(corpus, "fuzz_gltf_reader"));
    return 0;
}
