// The splat images against the CPU reference (sg::RayCastAction) where splatting is exact:
// emission only (no absorption), so each splat adds C·f(r) and the reference integrates
// Σ Cᵢ h(x − xᵢ) along the same rays; what remains is the footprint texture's sampling.

#include "SplatTestSupport.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/RayCastImage.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/RayCastAction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace texsplat::nodes {
namespace {

// A 10³ blob classified to emission only: color ramps with the value, extinction 0.
sg::Separator::Ptr emissionScene(const Camera::Ptr& camera, const TextureSplat::Ptr& splat) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 1.0f));
    transfer->colorValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->colors.setValue({glm::vec3(0.0f), glm::vec3(1.0f, 0.5f, 0.0f), glm::vec3(0.2f, 0.4f, 1.0f)});
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f});
    transfer->emission.setValue(1.0f);
    VolumeData::Ptr volume = VolumeData::create();
    volume->source.setValue(VolumeSource::Blob);
    volume->resolution.setValue(glm::vec3(10.0f));
    return test::framedScene(camera, {transfer, volume, splat});
}

// RMSE over all channels, relative to the reference's largest value.
double relativeRmse(const image::Image& image, const image::Image& reference) {
    double sum = 0.0;
    double largest = 0.0;
    for (int y = 0; y < reference.height(); ++y) {
        for (int x = 0; x < reference.width(); ++x) {
            const glm::vec4 a = image.pixel(x, y);
            const glm::vec4 b = reference.pixel(x, y);
            for (int c = 0; c < 4; ++c) {
                sum += (a[c] - b[c]) * (a[c] - b[c]);
                largest = std::max(largest, static_cast<double>(std::abs(b[c])));
            }
        }
    }
    return std::sqrt(sum / (reference.width() * reference.height() * 4.0)) / largest;
}

image::Image rayCastScene(sg::Node& root, int size) {
    registerNodeTypes();
    sg::RayCastAction action(size, size);
    action.render(root);
    return render::rayCastImage(action);
}

TEST(RayCastReference, emissionOnlySplatsConvergeToTheReferenceWithTextureResolution) {
    test::sharedContext();
    constexpr int kSize = 48;
    for (bool perspective : {false, true}) {
        Camera::Ptr camera;
        if (perspective) {
            camera = PerspectiveCamera::create();
        } else {
            camera = OrthographicCamera::create();
        }
        camera->orientation.setValue(render::rotationLookingAlong(glm::vec3(-0.6f, -0.3f, -1.0f)));
        std::vector<double> errors;
        image::Image reference(1, 1);
        for (int resolution : {16, 64, 256}) {
            TextureSplat::Ptr splat = TextureSplat::create();
            splat->textureResolution.setValue(resolution);
            sg::Separator::Ptr root = emissionScene(camera, splat);
            if (resolution == 16) {
                reference = rayCastScene(*root, kSize);
                test::expectFiniteAndNotEmpty(reference, "reference");
            }
            errors.push_back(relativeRmse(test::renderScene(*root, kSize, kSize), reference));
            RecordProperty(std::string(perspective ? "perspective" : "orthographic") +
                               "_relative_rmse_texture_" + std::to_string(resolution),
                           std::to_string(errors.back()));
        }
        const char* view = perspective ? "perspective" : "orthographic";
        EXPECT_LT(errors[1], errors[0]) << view;
        EXPECT_LE(errors[2], errors[1]) << view;
        // Measured (relative RMSE, textures 16 / 64 / 256): orthographic 1.1e-3 / 3.6e-5 / 4e-6,
        // exact up to the texture; perspective 7.9e-4 / 2.4e-4 / 2.2e-4, where a flat splat
        // facing the eye only approximates the kernel's integral along diverging rays.
        if (perspective) {
            EXPECT_LT(errors[2], 5e-4) << view;
        } else {
            EXPECT_LT(errors[1], 1e-4) << view;
            EXPECT_LT(errors[2], 2e-5) << view;
        }
    }
}

} // namespace
} // namespace texsplat::nodes
