// Splat batches of different nodes composite in one depth order (docs/design.md: figure 8 puts a
// cloudiness volume and wind vectors in the same space), whatever their order in the graph.
#include "SplatTestSupport.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/Transform.h"
#include "nodes/volume/DenseGrid.h"

namespace texsplat::nodes {
namespace {

// A Separator holding an opaque one-voxel-thick 4x4 layer at height z in `color`.
sg::Separator::Ptr layer(const VolumeData::Ptr& volume, float z, const glm::vec3& color) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->colors.setValue({color});
    transfer->colorValues.setValue({0.0f});
    transfer->opacities.setValue({40.0f, 40.0f});
    Transform::Ptr place = Transform::create();
    place->translation.setValue(glm::vec3(0.0f, 0.0f, z));
    sg::Separator::Ptr separator = sg::Separator::create();
    separator->addChild(place);
    separator->addChild(transfer);
    separator->addChild(volume);
    separator->addChild(TextureSplat::create());
    return separator;
}

struct Layer {
    float z;
    glm::vec3 color;
};

// The colour at the centre of the image, seen from above, of `layers` (drawn as nodes in that
// graph order), each `thickness` voxels thick (voxels 1 apart along z).
glm::vec4 centrePixel(const std::vector<Layer>& layers, std::int64_t thickness) {
    test::sharedContext();
    volume::DenseGrid<float> ones{volume::GridGeometry({4, 4, thickness}), 1.0f};
    const VolumeData::Ptr volume = test::fileVolume(
        VolumeSource::FileRaw, test::writeTestVolume("slab" + std::to_string(thickness), ones));
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    camera->position.setValue(glm::vec3(1.5f, 1.5f, 10.0f));
    camera->height.setValue(4.0f);
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    for (const Layer& spec : layers) {
        root->addChild(layer(volume, spec.z, spec.color));
    }
    const image::Image image = test::renderScene(*root, 32, 32);
    return image.pixel(16, 16);
}

const glm::vec3 kRed(1.0f, 0.0f, 0.0f);
const glm::vec3 kBlue(0.0f, 0.0f, 1.0f);

TEST(DepthOrderAcrossNodes, theNearerVolumeCoversTheFartherOneWhateverTheGraphOrder) {
    const Layer nearLayer{2.0f, kRed};
    const Layer farLayer{-2.0f, kBlue};
    for (const bool nearFirst : {true, false}) {
        const glm::vec4 pixel = nearFirst ? centrePixel({nearLayer, farLayer}, 1)
                                          : centrePixel({farLayer, nearLayer}, 1);
        EXPECT_GT(pixel.r, 0.9f) << (nearFirst ? "near layer first" : "far layer first");
        EXPECT_LT(pixel.b, 0.05f) << (nearFirst ? "near layer first" : "far layer first");
    }
}

TEST(DepthOrderAcrossNodes, volumesInTheSameSpaceInterleave) {
    // Two voxel layers each, at z = 0, 1 (red) and z = 0.5, 1.5 (blue): the nearest layer is
    // blue, so the pixel is mostly blue in either graph order (drawn one node after the other it
    // would be the last node's colour).
    const Layer red{0.0f, kRed};
    const Layer blue{0.5f, kBlue};
    for (const bool redFirst : {true, false}) {
        const glm::vec4 pixel =
            redFirst ? centrePixel({red, blue}, 2) : centrePixel({blue, red}, 2);
        EXPECT_GT(pixel.b, 0.6f) << (redFirst ? "red first" : "blue first");
        EXPECT_LT(pixel.r, 0.4f) << (redFirst ? "red first" : "blue first");
    }
}

} // namespace
} // namespace texsplat::nodes
