// VectorSplat and CombinedSplat through the GL backend (Crawfis & Max 1993, "Combined Vector and
// Scalar Textures"): marks along the projected vector, the animation phase, the paper's texture
// operators, stretch, mask, colour by position, extreme vectors, and the combined splat's scalar
// part. Fields are uniform or tiny (at most 8x8 voxels) so that llvmpipe draws each in a blink.
#include "SplatTestSupport.h"
#include "nodes/CombinedSplat.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VectorSplat.h"
#include "nodes/kernel/VectorSplatTable.h"
#include "nodes/volume/DenseGrid.h"

#include <glm/gtc/constants.hpp>

#include <array>
#include <fstream>

namespace texsplat::nodes {
namespace {

constexpr int kPixelsPerVoxel = 32;

// A texsplat-raw file of `dims` voxels (spacing 1, voxel (0,0,0) at the origin) holding
// vectorAt(i, j, k), written here rather than by volume::writeRawVolume, which writes empty
// (NaN) voxels as zero.
template <class VectorAt>
VolumeData::Ptr vectorVolume(const std::string& name, glm::i64vec3 dims, VectorAt vectorAt) {
    const std::string path = ::testing::TempDir() + "texsplat_vectors_" + name + ".raw";
    std::ofstream file(path, std::ios::binary);
    file << "texsplat-raw 1\ndims " << dims.x << " " << dims.y << " " << dims.z
         << "\ntype float32\ncomponents 3\nspacing 1 1 1\norigin 0 0 0\nendian little\ndata\n";
    static_assert(sizeof(glm::vec3) == 12, "three packed floats");
    for (std::int64_t k = 0; k < dims.z; ++k) {
        for (std::int64_t j = 0; j < dims.y; ++j) {
            for (std::int64_t i = 0; i < dims.x; ++i) {
                const glm::vec3 vector = vectorAt(i, j, k);
                file.write(reinterpret_cast<const char*>(&vector), sizeof(vector)); // x86: little
            }
        }
    }
    file.close();
    EXPECT_TRUE(file) << path;
    return test::fileVolume(VolumeSource::FileRaw, path);
}

VolumeData::Ptr uniformField(const std::string& name, glm::i64vec3 dims, glm::vec3 vector) {
    return vectorVolume(name, dims, [vector](auto, auto, auto) { return vector; });
}

// Extinction `tau` for every magnitude in [0, 2]; a gray colour map.
TransferFunction::Ptr constantOpacity(float tau) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 2.0f));
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({tau, tau});
    return transfer;
}

// Looking down -z at the square of `size` voxels centred on (x, y).
OrthographicCamera::Ptr topCamera(float x, float y, float size) {
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    camera->position.setValue(glm::vec3(x, y, 10.0f));
    camera->height.setValue(size);
    camera->nearDistance.setValue(1.0f);
    camera->farDistance.setValue(20.0f);
    return camera;
}

image::Image render(const Camera::Ptr& camera, const std::vector<sg::Node::Ptr>& nodes,
                    int pixels) {
    test::sharedContext();
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    for (const sg::Node::Ptr& node : nodes) {
        root->addChild(node);
    }
    return test::renderScene(*root, pixels, pixels);
}

VectorSplat::Ptr whiteScratches() {
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->markType.setValue(kernel::MarkType::Scratches);
    splat->colorMode.setValue(VectorColorMode::Constant);
    return splat;
}

// The largest difference of any channel of any pixel.
double maxDifference(const image::Image& a, const image::Image& b) {
    double largest = 0.0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const glm::vec4 d = glm::abs(a.pixel(x, y) - b.pixel(x, y));
            largest = std::max({largest, double(d.r), double(d.g), double(d.b), double(d.a)});
        }
    }
    return largest;
}

// The structure tensor (xx, yy, xy sums of gradient products) of the alpha of `region`, with y
// up.
glm::dvec3 structureTensor(const image::Image& image, const image::ImageRegion& region) {
    glm::dvec3 tensor(0.0);
    for (int y = region.y + 1; y + 1 < region.y + region.height; ++y) {
        for (int x = region.x + 1; x + 1 < region.x + region.width; ++x) {
            const double gx = image.pixel(x + 1, y).a - image.pixel(x - 1, y).a;
            const double gy = image.pixel(x, y - 1).a - image.pixel(x, y + 1).a; // rows go down
            tensor += glm::dvec3(gx * gx, gy * gy, gx * gy);
        }
    }
    return tensor;
}

// The orientation, in degrees in [0, 180) counter-clockwise from +x, of the lines whose
// structure tensor is `tensor`: its weakest direction.
double lineOrientation(const glm::dvec3& tensor) {
    const double gradient = 0.5 * std::atan2(2.0 * tensor.z, tensor.x - tensor.y);
    return std::fmod(glm::degrees(gradient) + 90.0 + 180.0, 180.0);
}

double angleBetweenLines(double a, double b) {
    const double difference = std::fmod(std::abs(a - b), 180.0);
    return std::min(difference, 180.0 - difference);
}

TEST(VectorSplat, marksRunAlongTheProjectedVector) {
    for (const double degrees : {0.0, 30.0, 60.0, 90.0, 135.0}) {
        const auto angle = static_cast<float>(glm::radians(degrees));
        const VolumeData::Ptr field = uniformField(
            "angle" + std::to_string(static_cast<int>(degrees)), {6, 6, 1},
            glm::vec3(std::cos(angle), std::sin(angle), 0.0f));
        const image::Image image =
            render(topCamera(2.5f, 2.5f, 7.0f), {field, constantOpacity(8.0f), whiteScratches()},
                   7 * kPixelsPerVoxel);
        test::expectFiniteWithAlphaInRange(image, "uniform field");
        const int inner = 5 * kPixelsPerVoxel;
        const double measured = lineOrientation(
            structureTensor(image, {kPixelsPerVoxel, kPixelsPerVoxel, inner, inner}));
        EXPECT_LT(angleBetweenLines(measured, degrees), 5.0)
            << "field at " << degrees << " degrees, marks at " << measured;
    }
}

TEST(VectorSplat, marksRunAlongTheProjectedVectorNearThePerspectiveImageBorder) {
    for (const double degrees : {0.0, 60.0, 135.0}) {
        const auto angle = static_cast<float>(glm::radians(degrees));
        // 6x6 voxels in the plane z = 0 reaching past the right border of a 60-degree camera,
        // 20 to 30 degrees off its axis where the marks are measured.
        const VolumeData::Ptr field = uniformField(
            "border" + std::to_string(static_cast<int>(degrees)), {6, 6, 1},
            glm::vec3(std::cos(angle), std::sin(angle), 0.0f));
        PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
        camera->position.setValue(glm::vec3(-1.0f, 2.5f, 6.0f));
        camera->heightAngle.setValue(glm::radians(60.0f));
        camera->nearDistance.setValue(0.5f);
        camera->farDistance.setValue(30.0f);
        const int pixels = 320;
        // Few marks fall in the region: the tensors of four seeds' marks together.
        glm::dvec3 tensor(0.0);
        for (const int seed : {1, 2, 3, 4}) {
            VectorSplat::Ptr splat = whiteScratches();
            splat->markDensity.setValue(4.0f);
            splat->seed.setValue(seed);
            const image::Image image =
                render(camera, {field, constantOpacity(8.0f), splat}, pixels);
            test::expectFiniteWithAlphaInRange(image, "near the border");
            // Image x from 0.6 to 0.95 of the half-width (world x 1.1 to 2.3), y within 0.3 of
            // the centre.
            tensor += structureTensor(image, {pixels * 8 / 10, pixels * 7 / 20, pixels * 7 / 40,
                                              pixels * 3 / 10});
        }
        const double measured = lineOrientation(tensor);
        EXPECT_LT(angleBetweenLines(measured, degrees), 5.0)
            << "field at " << degrees << " degrees, marks at " << measured;
    }
}

// The shift (pixels, within ±`reach`) that best matches `moved` to `base` along x, by the
// cross-correlation of their alpha.
int bestShiftAlongX(const image::Image& base, const image::Image& moved, int reach) {
    int best = 0;
    double bestScore = -1.0;
    for (int shift = -reach; shift <= reach; ++shift) {
        double score = 0.0;
        for (int y = 0; y < base.height(); ++y) {
            for (int x = reach; x + reach < base.width(); ++x) {
                score += double(base.pixel(x, y).a) * moved.pixel(x + shift, y).a;
            }
        }
        if (score > bestScore) {
            bestScore = score;
            best = shift;
        }
    }
    return best;
}

TEST(VectorSplat, onePhaseStepMovesTheMarksOneTableRowAlongTheVectorAndACycleRepeats) {
    const VolumeData::Ptr field = uniformField("phase", {4, 4, 1}, glm::vec3(1.0f, 0.0f, 0.0f));
    const TransferFunction::Ptr transfer = constantOpacity(8.0f);
    VectorSplat::Ptr splat = VectorSplat::create();
    const auto draw = [&](float phase) {
        splat->phase.setValue(phase);
        return render(topCamera(1.5f, 1.5f, 6.0f), {field, transfer, splat}, 6 * kPixelsPerVoxel);
    };
    const image::Image start = draw(0.0f);
    const image::Image step = draw(1.0f / 16.0f);
    // One row moves the marks by the period 2 E over 16 rows: E = 1.15 x 1.6 voxels.
    const double expected = 2.0 * 1.15 * 1.6 / 16.0 * kPixelsPerVoxel;
    EXPECT_NEAR(bestShiftAlongX(start, step, 12), expected, 1.0);
    EXPECT_EQ(bestShiftAlongX(start, draw(-1.0f / 16.0f), 12), -bestShiftAlongX(start, step, 12));
    const image::Image cycle = draw(1.0f);
    EXPECT_EQ(maxDifference(start, cycle), 0.0);
}

// The pixel of `image` (kPixelsPerVoxel per voxel, centred on the origin) at voxel offset (x, y).
glm::vec4 pixelAt(const image::Image& image, float x, float y) {
    const int column = static_cast<int>(std::floor(x * kPixelsPerVoxel)) + image.width() / 2;
    const int row = image.height() / 2 - 1 - static_cast<int>(std::floor(y * kPixelsPerVoxel));
    return image.pixel(column, row);
}

TEST(VectorSplat, modulateAndBlendGiveThePapersFormulas) {
    // One splat at the origin pointing along +x: its square's x is the table's x and its y the
    // table's -y (the square's second axis is view axis x first axis).
    const VolumeData::Ptr field = uniformField("operators", {1, 1, 1}, glm::vec3(1.0f, 0.0f, 0.0f));
    const float tau = 2.0f;
    const glm::vec3 rgb(0.8f, 0.6f, 0.4f);
    const glm::vec3 constant(0.1f, 0.9f, 0.3f);
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->colorMode.setValue(VectorColorMode::Constant);
    splat->color.setValue(rgb);
    splat->markDensity.setValue(4.0f);
    splat->blendColor.setValue(constant);
    const auto camera = topCamera(0.0f, 0.0f, 4.0f);
    const image::Image modulate =
        render(camera, {field, constantOpacity(tau), splat}, 4 * kPixelsPerVoxel);
    splat->textureOperator.setValue(render::MarkOperator::Blend);
    const image::Image blend =
        render(camera, {field, constantOpacity(tau), splat}, 4 * kPixelsPerVoxel);

    octree::VectorEmission emission;
    const int row = octree::vectorSplat(emission, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, 0).row;
    const kernel::VectorSplatTable& table = *splat->table();
    const float polygonAlpha = 1.0f - std::exp(-tau); // one voxel of depth
    int marked = 0;
    for (float y = -1.5f; y <= 1.5f; y += 0.0625f) {
        for (float x = -1.5f; x <= 1.5f; x += 0.0625f) {
            // At the pixel centre.
            const float px = (std::floor(x * kPixelsPerVoxel) + 0.5f) / kPixelsPerVoxel;
            const float py = (std::floor(y * kPixelsPerVoxel) + 0.5f) / kPixelsPerVoxel;
            const glm::vec2 texel = table.sample(row, 0, px, -py);
            const float alpha = polygonAlpha * texel.y;
            const glm::vec3 modulated = rgb * texel.x * alpha;
            const glm::vec3 blended = (rgb * (1.0f - texel.x) + constant * texel.x) * alpha;
            const glm::vec4 m = pixelAt(modulate, x, y);
            const glm::vec4 b = pixelAt(blend, x, y);
            ASSERT_NEAR(m.a, alpha, 0.01f) << x << ", " << y;
            ASSERT_NEAR(b.a, alpha, 0.01f) << x << ", " << y;
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(m[c], modulated[c], 0.01f) << x << ", " << y << " channel " << c;
                ASSERT_NEAR(b[c], blended[c], 0.01f) << x << ", " << y << " channel " << c;
            }
            marked += texel.x > 0.5f;
        }
    }
    EXPECT_GT(marked, 20); // the comparison saw marks, not only the empty background
}

// Second moments of the alpha about the image centre, along x and y.
glm::dvec2 alphaSpread(const image::Image& image) {
    glm::dvec2 moment(0.0);
    double total = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const double a = image.pixel(x, y).a;
            const glm::dvec2 d(x + 0.5 - image.width() / 2.0, y + 0.5 - image.height() / 2.0);
            moment += a * d * d;
            total += a;
        }
    }
    return glm::sqrt(moment / total);
}

TEST(VectorSplat, stretchElongatesTheSplatAlongTheVectorByThatFactor) {
    const VolumeData::Ptr field = uniformField("stretch", {1, 1, 1}, glm::vec3(0.0f, 1.0f, 0.0f));
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->markDensity.setValue(8.0f); // many marks: the spread is the window's
    const auto camera = topCamera(0.0f, 0.0f, 8.0f);
    const glm::dvec2 plain = alphaSpread(render(camera, {field, constantOpacity(2.0f), splat}, 256));
    splat->stretch.setValue(2.0f);
    const glm::dvec2 stretched =
        alphaSpread(render(camera, {field, constantOpacity(2.0f), splat}, 256));
    EXPECT_NEAR(stretched.y / plain.y, 2.0, 0.04); // along the vector (+y)
    EXPECT_NEAR(stretched.x / plain.x, 1.0, 0.02);
}

TEST(VectorSplat, voxelsOutsideTheMaskRangeDrawNothing) {
    const VolumeData::Ptr field = uniformField("masked", {8, 1, 1}, glm::vec3(1.0f, 0.0f, 0.0f));
    volume::DenseGrid<float> cloudiness{volume::GridGeometry({8, 1, 1})};
    for (std::int64_t i = 0; i < 8; ++i) {
        cloudiness.setValue({i, 0, 0}, static_cast<float>(i));
    }
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->maskData.setValue(test::fileVolume(
        VolumeSource::FileRaw, test::writeTestVolume("mask_cloudiness", cloudiness)));
    splat->maskRange.setValue(glm::vec2(2.0f, 4.0f));
    sg::Separator::Ptr root = sg::Separator::create();
    for (const sg::Node::Ptr& node :
         std::vector<sg::Node::Ptr>{topCamera(3.5f, 0.0f, 10.0f), field, constantOpacity(4.0f),
                                    splat}) {
        root->addChild(node);
    }
    test::sharedContext();
    const test::RenderedFrame frame = test::renderFrame(*root, 320, 320);
    EXPECT_EQ(frame.statistics.splats, 3u);
    // Nothing left of voxel 2's square (x < 2 - 1.84) or right of voxel 4's (x > 4 + 1.84).
    for (int y = 0; y < 320; ++y) {
        EXPECT_EQ(frame.image.pixel(5, y).a, 0.0f);
        EXPECT_EQ(frame.image.pixel(314, y).a, 0.0f);
    }
}

TEST(VectorSplat, colourByPositionFollowsTheAxis) {
    const VolumeData::Ptr field = uniformField("position", {8, 1, 1}, glm::vec3(0.0f, 1.0f, 0.0f));
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->positionAxis.setValue(Axis::X);
    splat->positionRange.setValue(glm::vec2(0.0f, 7.0f));
    const auto draw = [&](VectorColorMode mode) {
        splat->colorMode.setValue(mode);
        return render(topCamera(3.5f, 0.0f, 8.0f), {field, constantOpacity(4.0f), splat},
                      8 * kPixelsPerVoxel);
    };
    // The same marks in white and coloured by x: their ratio is the colour, whatever the marks.
    const image::Image white = draw(VectorColorMode::Constant);
    const image::Image byPosition = draw(VectorColorMode::Position);
    // Over each voxel's column of pixels (splats overlap, so a mean of the neighbours' colours
    // too), the gray map from black at x = 0 to white at x = 7 grows with x.
    double previous = -1.0;
    for (int voxel = 0; voxel < 8; ++voxel) {
        double coloured = 0.0;
        double reference = 0.0;
        for (int y = 0; y < white.height(); ++y) {
            for (int x = voxel * kPixelsPerVoxel; x < (voxel + 1) * kPixelsPerVoxel; ++x) {
                coloured += byPosition.pixel(x, y).r;
                reference += white.pixel(x, y).r;
            }
        }
        ASSERT_GT(reference, 0.0) << "voxel " << voxel;
        const double gray = coloured / reference;
        EXPECT_GT(gray, previous + 0.05) << "voxel " << voxel;
        EXPECT_NEAR(gray, voxel / 7.0, 0.15) << "voxel " << voxel;
        previous = gray;
    }
}

TEST(VectorSplat, zeroNanHugeAndDenormalVectorsGiveFiniteImages) {
    const float huge = std::numeric_limits<float>::max();
    const std::array<glm::vec3, 5> vectors{
        glm::vec3(0.0f), glm::vec3(std::nanf(""), 0.0f, 0.0f), glm::vec3(huge, huge, huge),
        glm::vec3(1e-40f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    const VolumeData::Ptr field = vectorVolume("extreme", {5, 1, 1}, [&](auto i, auto, auto) {
        return vectors[static_cast<std::size_t>(i)];
    });
    for (const bool combined : {false, true}) {
        sg::Node::Ptr splat = combined ? sg::Node::Ptr(CombinedSplat::create())
                                       : sg::Node::Ptr(VectorSplat::create());
        sg::Separator::Ptr root = sg::Separator::create();
        for (const sg::Node::Ptr& node : std::vector<sg::Node::Ptr>{
                 topCamera(2.0f, 0.0f, 8.0f), field, constantOpacity(4.0f), splat}) {
            root->addChild(node);
        }
        test::sharedContext();
        const test::RenderedFrame frame = test::renderFrame(*root, 128, 128);
        test::expectFiniteWithAlphaInRange(frame.image, combined ? "combined" : "vector");
        // Vector splats: the zero and the NaN vector draw nothing (4 and 3 of 5 are left);
        // combined splats draw the zero vector's scalar part.
        EXPECT_EQ(frame.statistics.splats, combined ? 4u : 3u);
    }
}

TEST(VectorSplat, octreeCutsDrawTheMeanVectorsOfCoarserNodes) {
    const VolumeData::Ptr tornado = VolumeData::create();
    tornado->source.setValue(VolumeSource::Tornado);
    tornado->resolution.setValue(glm::vec3(16.0f));
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 0.32f));
    transfer->opacities.setValue({0.0f, 30.0f});
    VectorSplat::Ptr splat = VectorSplat::create();
    sg::Separator::Ptr root = sg::Separator::create();
    for (const sg::Node::Ptr& node :
         std::vector<sg::Node::Ptr>{topCamera(0.5f, 0.5f, 1.2f), tornado, transfer, splat}) {
        root->addChild(node);
    }
    test::sharedContext();
    const test::RenderedFrame full = test::renderFrame(*root, 96, 96);
    splat->maxSplats.setValue(200);
    const test::RenderedFrame cut = test::renderFrame(*root, 96, 96);
    EXPECT_GT(full.statistics.splats, 1000u);
    EXPECT_LE(cut.statistics.splats, 200u);
    EXPECT_GT(cut.statistics.splats, 100u);
    test::expectFiniteWithAlphaInRange(cut.image, "octree cut");
    test::expectFiniteAndNotEmpty(cut.image, "octree cut");
}

TEST(CombinedSplat, withZeroContrastMarksItIsTheTextureSplatImage) {
    const VolumeData::Ptr tornado = VolumeData::create();
    tornado->source.setValue(VolumeSource::Tornado);
    tornado->resolution.setValue(glm::vec3(12.0f));
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 0.32f));
    transfer->opacities.setValue({0.0f, 30.0f});
    PerspectiveCamera::Ptr camera = PerspectiveCamera::create();
    camera->position.setValue(glm::vec3(0.4f, 0.7f, 2.2f));
    const image::Image scalar = render(camera, {tornado, transfer, TextureSplat::create()}, 96);
    CombinedSplat::Ptr combined = CombinedSplat::create();
    combined->markContrast.setValue(0.0f);
    const image::Image marked = render(camera, {tornado, transfer, combined}, 96);
    test::expectFiniteAndNotEmpty(scalar, "texture splats");
    EXPECT_LT(maxDifference(scalar, marked), 1e-5);
    combined->markContrast.setValue(1.0f);
    EXPECT_GT(maxDifference(scalar, render(camera, {tornado, transfer, combined}, 96)), 0.05);
}

TEST(VectorSplat, badFieldsAndScalarDataAreReportedByName) {
    const auto message = [](const std::vector<sg::Node::Ptr>& nodes) {
        try {
            render(topCamera(0.0f, 0.0f, 4.0f), nodes, 8);
        } catch (const DataError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    const VolumeData::Ptr field = uniformField("fields", {2, 2, 2}, glm::vec3(1.0f, 0.0f, 0.0f));
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->setName("winds");
    const auto expectError = [&](const std::string& expected) {
        EXPECT_EQ(message({field, constantOpacity(1.0f), splat}), "VectorSplat 'winds': " + expected);
    };
    splat->tableRows.setValue(0);
    expectError("tableRows must be in 1..256, got 0");
    splat->tableRows.setValue(16);
    splat->tableColumns.setValue(65);
    expectError("tableColumns must be in 1..64, got 65");
    splat->tableColumns.setValue(8);
    splat->size.setValue(9.0f);
    expectError("size must be at most 8 for vector splats, got 9");
    splat->size.setValue(1.6f);
    splat->stretch.setValue(0.5f);
    expectError("stretch must be finite and >= 1, got 0.5");
    splat->stretch.setValue(1.0f);
    splat->phase.setValue(std::numeric_limits<float>::infinity());
    expectError("phase must be finite, got inf");
    splat->phase.setValue(0.0f);
    splat->colorMode.setValue(VectorColorMode::Scalar);
    expectError("colorMode SCALAR needs colorData, a scalar VolumeData");
    splat->colorData.setValue(constantOpacity(1.0f));
    expectError("colorData must be a VolumeData, got TransferFunction");
    splat->colorMode.setValue(VectorColorMode::Magnitude);
    splat->colorData.setValue(nullptr);
    splat->maskRange.setValue(glm::vec2(2.0f, 1.0f));
    expectError("maskRange must be finite with maskRange[0] <= maskRange[1], got 2 1");
    splat->maskRange.setValue(glm::vec2(0.0f, 1.0f));
    splat->maskData.setValue(uniformField("mask", {3, 2, 2}, glm::vec3(1.0f)));
    EXPECT_EQ(message({field, constantOpacity(1.0f), splat}).rfind(
                  "VectorSplat 'winds': maskData VolumeData has 3x2x2 voxels but the vectors have "
                  "2x2x2",
                  0),
              0u);
    splat->maskData.setValue(nullptr);
    VolumeData::Ptr scalars = VolumeData::create();
    scalars->source.setValue(VolumeSource::Blob);
    scalars->resolution.setValue(glm::vec3(2.0f));
    EXPECT_EQ(message({scalars, constantOpacity(1.0f), splat}),
              "VectorSplat 'winds': VolumeData holds scalars; vector splats need a vector field (a "
              "raw file with 3 components, an OpenVDB vec3s grid, or TORNADO, JET_STREAM, "
              "AEROGEL)");
}

TEST(VectorSplat, aSceneWithoutVectorSplatsMakesNoVectorTable) {
    ASSERT_EQ(kernel::VectorSplatTable::liveTables(), 0u) << "an earlier test leaked a table";
    const VolumeData::Ptr field = uniformField("tables", {2, 2, 2}, glm::vec3(1.0f, 0.0f, 0.0f));
    render(topCamera(0.5f, 0.5f, 4.0f), {field, constantOpacity(2.0f), TextureSplat::create()},
           32);
    EXPECT_EQ(kernel::VectorSplatTable::liveTables(), 0u);
    VectorSplat::Ptr first = VectorSplat::create();
    VectorSplat::Ptr second = VectorSplat::create();
    render(topCamera(0.5f, 0.5f, 4.0f), {field, constantOpacity(2.0f), first, second}, 32);
    EXPECT_EQ(kernel::VectorSplatTable::liveTables(), 1u); // one table for equal parameters
    EXPECT_EQ(first->table(), second->table());
}

} // namespace
} // namespace texsplat::nodes
