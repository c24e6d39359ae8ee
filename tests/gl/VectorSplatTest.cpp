// VectorSplat and CombinedSplat on both backends (Crawfis & Max 1993, "Combined Vector and
// Scalar Textures"): marks that follow the flow at every zoom and point downstream, the
// animation phase, the operators, masks, colour by position, opacity and density that follow the
// medium, octree cuts, extreme vectors, and the combined splat's scalar part. Fields are small
// (at most 32³ voxels, images of at most 576² pixels) so that llvmpipe draws each in a blink.
#include "nodes/VectorSplat.h"
#include "SplatTestSupport.h"
#include "nodes/CombinedSplat.h"
#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/bench/LegibilityBench.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

namespace texsplat::nodes {
namespace {

using render::Backend;
using render::MarkType;

constexpr std::array<Backend, 2> kBackends{Backend::Cpu, Backend::Gl};
constexpr std::array<MarkType, 2> kMarkTypes{MarkType::Scratches, MarkType::Particles};

const char* nameOf(Backend backend) {
    return backend == Backend::Gl ? "gl" : "cpu";
}
const char* nameOf(MarkType type) {
    return type == MarkType::Scratches ? "scratches" : "particles";
}

// `root` collected and drawn by `backend`, with what was counted.
test::RenderedFrame drawWith(Backend backend, sg::Node& root, int width, int height) {
    test::sharedContext();
    if (backend == Backend::Gl) {
        return test::renderFrame(root, width, height);
    }
    registerNodeTypes();
    render::FrameAction action(width, height);
    image::Image image =
        render::cpu::CpuRenderer(2).draw(action.collect(root), action.statistics(), true);
    return {std::move(image), action.statistics()};
}

// A scene of `nodes` in order.
sg::Separator::Ptr sceneOf(const std::vector<sg::Node::Ptr>& nodes) {
    sg::Separator::Ptr root = sg::Separator::create();
    for (const sg::Node::Ptr& node : nodes) {
        root->addChild(node);
    }
    return root;
}

// Looking down -z at the square of `size` voxels centred on (x, y).
OrthographicCamera::Ptr topCamera(float x, float y, float size) {
    OrthographicCamera::Ptr camera = OrthographicCamera::create();
    camera->position.setValue(glm::vec3(x, y, 50.0f));
    camera->height.setValue(size);
    camera->nearDistance.setValue(1.0f);
    camera->farDistance.setValue(100.0f);
    return camera;
}

// A VolumeData holding `dims` voxels (spacing 1, voxel (0, 0, 0) at the origin) of
// vectorAt(i, j, k).
VolumeData::Ptr vectorVolume(glm::i64vec3 dims,
                             const std::function<glm::vec3(int, int, int)>& vectorAt) {
    auto grid = std::make_shared<volume::DenseVectorGrid>(volume::GridGeometry(dims));
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                grid->setValue({i, j, k}, vectorAt(i, j, k));
            }
        }
    }
    VolumeData::Ptr volume = VolumeData::create();
    volume->setGrid(grid);
    return volume;
}

VolumeData::Ptr uniformField(glm::i64vec3 dims, glm::vec3 vector) {
    return vectorVolume(dims, [vector](int, int, int) { return vector; });
}

// Extinction `tau` for every magnitude in [0, 2]; a gray colour map.
TransferFunction::Ptr constantOpacity(float tau) {
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 2.0f));
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({tau, tau});
    return transfer;
}

VectorSplat::Ptr constantMarks(glm::vec3 color, MarkType type = MarkType::Scratches) {
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->markType.setValue(type);
    splat->colorMode.setValue(VectorColorMode::Constant);
    splat->color.setValue(color);
    return splat;
}

// Pixels whose alpha is above `level`.
double coverage(const image::Image& image, float level = 0.1f) {
    std::size_t covered = 0;
    for (const glm::vec4& pixel : image.pixels()) {
        covered += pixel.a > level ? 1 : 0;
    }
    return static_cast<double>(covered) / static_cast<double>(image.pixelCount());
}

double meanAlpha(const image::Image& image) {
    double sum = 0.0;
    for (const glm::vec4& pixel : image.pixels()) {
        sum += pixel.a;
    }
    return sum / static_cast<double>(image.pixelCount());
}

double angleBetweenLines(double a, double b) {
    const double difference = std::fmod(std::abs(a - b), 180.0);
    return std::min(difference, 180.0 - difference);
}

bench::LegibilityResult legibility(bench::LegibilityField field, float angle, MarkType type,
                                   Backend backend, float pixelsPerVoxel) {
    test::sharedContext();
    bench::LegibilityCase what;
    what.field = field;
    what.angle = angle;
    what.type = type;
    what.backend = backend;
    what.pixelsPerVoxel = pixelsPerVoxel;
    bench::LegibilityOptions options;
    options.repeat = 0;
    options.reference = false;
    return bench::measureLegibility(what, options);
}

TEST(VectorSplat, marksRunAlongUniformFlowsAtEveryZoom) {
    // The uniform-field check: the image's streaks (the structure tensor of central differences
    // over the whole field) within 5° of the flow, for the angles where marks used to lock onto
    // the lattice's axes and diagonals, down to 4 pixels a voxel.
    for (const Backend backend : kBackends) {
        for (const MarkType type : kMarkTypes) {
            for (const float angle : {0.0f, 30.0f, 60.0f, 90.0f, 135.0f}) {
                for (const float zoom : {4.0f, 6.0f, 10.0f, 16.0f}) {
                    const bench::LegibilityResult result =
                        legibility(bench::LegibilityField::Uniform, angle, type, backend, zoom);
                    EXPECT_LT(angleBetweenLines(result.orientation, angle), 5.0)
                        << nameOf(backend) << ", " << nameOf(type) << ", " << angle << "°, " << zoom
                        << " pixels per voxel: streaks at " << result.orientation << "°";
                }
            }
        }
    }
}

TEST(VectorSplat, marksFollowCurvedFlowsAtEveryZoomAsALineIntegralConvolutionDoes) {
    // Median angle between the streaks and the flow, smoothed over half a voxel: a line integral
    // convolution of the same flow scores about 8° on this measure (texsplat bench --legibility).
    for (const Backend backend : kBackends) {
        for (const MarkType type : kMarkTypes) {
            for (const auto field :
                 {bench::LegibilityField::Vortex, bench::LegibilityField::Saddle}) {
                for (const float zoom : {4.0f, 6.0f, 10.0f, 16.0f}) {
                    const bench::LegibilityResult result =
                        legibility(field, 0.0f, type, backend, zoom);
                    const std::string what =
                        std::string(nameOf(backend)) + ", " + nameOf(type) +
                        (field == bench::LegibilityField::Vortex ? ", vortex" : ", saddle") + ", " +
                        std::to_string(zoom) + " pixels per voxel";
                    EXPECT_GT(result.marks.pixels, 10000u) << what;
                    EXPECT_LT(result.marks.median, 10.0) << what;
                    EXPECT_LT(result.marks.percentile90, 25.0) << what;
                }
            }
        }
    }
}

TEST(VectorSplat, marksPointDownstream) {
    // Along the flow the marks' intensity rises slowly and falls at their head: the derivative
    // along the flow is skewed negative, and the image's skew along the opposite way is the
    // negative of that.
    for (const Backend backend : kBackends) {
        for (const MarkType type : kMarkTypes) {
            for (const float angle : {0.0f, 30.0f, 135.0f, 250.0f}) {
                for (const float zoom : {4.0f, 16.0f}) {
                    const bench::LegibilityResult result =
                        legibility(bench::LegibilityField::Uniform, angle, type, backend, zoom);
                    EXPECT_GT(result.skew, 0.25) << nameOf(backend) << ", " << nameOf(type) << ", "
                                                 << angle << "°, " << zoom << " pixels per voxel";
                }
            }
            const bench::LegibilityResult vortex =
                legibility(bench::LegibilityField::Vortex, 0.0f, type, backend, 6.0f);
            EXPECT_GT(vortex.skew, 0.25) << nameOf(backend) << ", " << nameOf(type) << ", vortex";
        }
    }
}

// The shift (pixels, within [0, `reach`]) along x that best matches `moved` to `base`, by the
// cross-correlation of their alpha.
int shiftAlongX(const image::Image& base, const image::Image& moved, int reach) {
    int best = 0;
    double bestScore = -1.0;
    for (int shift = 0; shift <= reach; ++shift) {
        double score = 0.0;
        for (int y = 0; y < base.height(); ++y) {
            for (int x = reach; x + reach < base.width(); ++x) {
                score += double(base.pixel(x, y).a) * double(moved.pixel(x + shift, y).a);
            }
        }
        if (score > bestScore) {
            bestScore = score;
            best = shift;
        }
    }
    return best;
}

TEST(VectorSplat, thePhaseMovesTheMarksAlongTheirVectorAndAWholeCycleLoops) {
    // A 16 x 8 x 1 field along +x seen at 8 pixels per voxel: in a tenth of a cycle each mark moves
    // a tenth of its length, 2.5 voxels, along x: 2 pixels.
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr splat = constantMarks(glm::vec3(1.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(7.5f, 3.5f, 20.0f), uniformField({16, 8, 1}, {1.0f, 0.0f, 0.0f}),
                     constantOpacity(8.0f), splat});
        const auto at = [&](float phase) {
            splat->phase.setValue(phase);
            return drawWith(backend, *root, 160, 160).image;
        };
        const image::Image start = at(0.0f);
        const image::Image tenth = at(0.1f);
        EXPECT_EQ(shiftAlongX(start, tenth, 6), 2) << nameOf(backend);
        // Whole cycles draw the same image (bit for bit on the CPU backend).
        const image::ImageComparison::ChannelError again =
            image::ImageComparison(start, at(3.0f)).rgb();
        if (backend == Backend::Cpu) {
            EXPECT_EQ(again.rmse, 0.0);
        } else {
            EXPECT_LT(again.rmse, 1e-6);
        }
        EXPECT_GT(image::ImageComparison(start, at(0.5f)).rgb().rmse, 0.01);
        // Negative phases run the cycle the other way.
        EXPECT_LT(image::ImageComparison(at(-0.25f), at(0.75f)).rgb().rmse, 1e-6);
    }
}

TEST(VectorSplat, modulateDrawsTheSplatsColourAndBlendMixesTowardsTheBlendColour) {
    // Red marks over black: MODULATE keeps red (the premultiplied pixels are α·red); BLEND mixes
    // towards blue by the marks' profile, so every pixel is a mix of the two, blue at the cores.
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr splat = constantMarks(glm::vec3(1.0f, 0.0f, 0.0f));
        splat->blendColor.setValue(glm::vec3(0.0f, 0.0f, 1.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(3.5f, 3.5f, 10.0f), uniformField({8, 8, 2}, {1.0f, 1.0f, 0.0f}),
                     constantOpacity(8.0f), splat});
        const image::Image modulated = drawWith(backend, *root, 100, 100).image;
        splat->textureOperator.setValue(render::MarkOperator::Blend);
        const image::Image blended = drawWith(backend, *root, 100, 100).image;
        double blueShare = 0.0;
        std::size_t marked = 0;
        for (std::size_t i = 0; i < modulated.pixelCount(); ++i) {
            const glm::vec4 red = modulated.pixels()[i];
            const glm::vec4 mix = blended.pixels()[i];
            EXPECT_EQ(red.g + red.b, 0.0f) << nameOf(backend);
            EXPECT_NEAR(red.r, red.a, 1e-5f) << nameOf(backend);
            EXPECT_NEAR(mix.r + mix.b, mix.a, 1e-5f) << nameOf(backend);
            if (mix.a > 0.5f) {
                blueShare += mix.b / mix.a;
                ++marked;
            }
        }
        ASSERT_GT(marked, 500u) << nameOf(backend);
        EXPECT_GT(blueShare / static_cast<double>(marked), 0.3) << nameOf(backend);
    }
}

TEST(VectorSplat, marksKeepTheirColourOverAWhiteBackground) {
    // Dark blue marks on a white page: every pixel is the page mixed with dark blue (no gray
    // mud), many are mostly dark blue, and the cores are as dark as the marks' colour.
    const glm::vec3 navy(0.05f, 0.05f, 0.4f);
    const glm::vec3 towardsNavy = glm::normalize(glm::vec3(1.0f) - navy);
    for (const Backend backend : kBackends) {
        sg::Separator::Ptr root =
            sceneOf({topCamera(7.5f, 7.5f, 18.0f), uniformField({16, 16, 4}, {1.0f, 0.3f, 0.0f}),
                     constantOpacity(20.0f), constantMarks(navy)});
        const image::Image image = drawWith(backend, *root, 180, 180).image;
        std::size_t strong = 0;
        double darkest = 1.0;
        for (const glm::vec4& pixel : image.pixels()) {
            const glm::vec3 onWhite = glm::vec3(pixel) + (1.0f - pixel.a) * glm::vec3(1.0f);
            darkest = std::min(
                darkest, double(0.2126f * onWhite.r + 0.7152f * onWhite.g + 0.0722f * onWhite.b));
            if (pixel.a > 0.05f) {
                const glm::vec3 shade = glm::vec3(1.0f) - onWhite;
                EXPECT_GT(glm::dot(glm::normalize(shade), towardsNavy), 0.999f) << nameOf(backend);
            }
            strong += pixel.a > 0.5f ? 1 : 0;
        }
        EXPECT_GT(static_cast<double>(strong) / static_cast<double>(image.pixelCount()), 0.15)
            << nameOf(backend);
        EXPECT_LT(darkest, 0.1) << nameOf(backend);
    }
}

TEST(VectorSplat, theImageIsAboutAsOpaqueAsTheMediumItStandsFor) {
    // A thin medium (column optical depth 0.1 and 0.3 through 8 voxels): the marks' mean opacity
    // is near the medium's, 1 − e^(−τ·8), and grows with τ.
    const VolumeData::Ptr field = uniformField({20, 20, 8}, {1.0f, 0.2f, 0.0f});
    for (const Backend backend : kBackends) {
        double previous = 0.0;
        for (const float columnDepth : {0.1f, 0.3f}) {
            sg::Separator::Ptr root =
                sceneOf({topCamera(9.5f, 9.5f, 14.0f), field, constantOpacity(columnDepth / 8.0f),
                         constantMarks(glm::vec3(1.0f))});
            const double alpha = meanAlpha(drawWith(backend, *root, 140, 140).image);
            const double medium = 1.0 - std::exp(-double(columnDepth));
            EXPECT_NEAR(alpha, medium, 0.35 * medium) << nameOf(backend) << ", " << columnDepth;
            EXPECT_GT(alpha, previous) << nameOf(backend);
            previous = alpha;
        }
    }
}

TEST(VectorSplat, theMarksCoverTheImageAsDenselyWhateverTheDepthOfTheData) {
    // A slab 2 voxels deep and one 32 deep, both opaque enough to draw opaque marks: the marks
    // per voxel follow the voxels behind a pixel, so both cover about the same part of the image,
    // and markDensity sets how much.
    for (const Backend backend : kBackends) {
        std::vector<double> covered;
        for (const int depth : {2, 32}) {
            VectorSplat::Ptr splat = constantMarks(glm::vec3(1.0f));
            sg::Separator::Ptr root = sceneOf({topCamera(7.5f, 7.5f, 16.0f),
                                               uniformField({16, 16, depth}, {1.0f, 0.5f, 0.0f}),
                                               constantOpacity(4.0f), splat});
            covered.push_back(coverage(drawWith(backend, *root, 128, 128).image));
            splat->markDensity.setValue(0.3f);
            const double sparse = coverage(drawWith(backend, *root, 128, 128).image);
            EXPECT_LT(sparse, 0.8 * covered.back()) << nameOf(backend) << ", depth " << depth;
        }
        EXPECT_GT(covered[0], 0.25) << nameOf(backend);
        EXPECT_NEAR(covered[1], covered[0], 0.25 * covered[0]) << nameOf(backend);
    }
}

TEST(VectorSplat, voxelsOutsideTheMaskRangeDrawNothing) {
    // Eight voxels along x whose mask value is their index: only 2 to 4 draw, and their marks
    // reach at most a cell corner, a mark length and half a width (at 20 pixels a voxel the
    // least sizes in pixels are below the voxels') from their centres.
    const VolumeData::Ptr field = uniformField({8, 1, 1}, glm::vec3(0.0f, 1.0f, 0.0f));
    auto cloudiness = std::make_shared<volume::DenseGrid<float>>(volume::GridGeometry({8, 1, 1}));
    for (int i = 0; i < 8; ++i) {
        cloudiness->setValue({i, 0, 0}, static_cast<float>(i));
    }
    VolumeData::Ptr mask = VolumeData::create();
    mask->setGrid(cloudiness);
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr splat = constantMarks(glm::vec3(1.0f));
        splat->maskData.setValue(mask);
        splat->maskRange.setValue(glm::vec2(2.0f, 4.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(3.5f, 0.0f, 16.0f), field, constantOpacity(40.0f), splat});
        const test::RenderedFrame frame = drawWith(backend, *root, 320, 320);
        test::expectFiniteAndNotEmpty(frame.image, "masked marks");
        // Pixel x covers world x from x / 20 − 4.5: left of voxel 2's reach, right of voxel 4's.
        const double reach = splat->markReach();
        for (int y = 0; y < 320; ++y) {
            for (int x = 0; x < 320; ++x) {
                const double world = (x + 0.5) / 20.0 - 4.5;
                if (world < 2.0 - reach || world > 4.0 + reach) {
                    ASSERT_EQ(frame.image.pixel(x, y).a, 0.0f) << nameOf(backend) << " at " << x;
                }
            }
        }
    }
}

TEST(VectorSplat, marksAreCutAtTheEdgeOfTheData) {
    // A field along a diagonal in an 8 x 8 x 2 box seen at 20 pixels a voxel, at phases that
    // carry marks out of it: nothing is drawn beyond the box's cells but the marks' half-width
    // (2.5 pixels).
    const VolumeData::Ptr field = uniformField({8, 8, 2}, glm::vec3(1.0f, 0.6f, 0.0f));
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr splat = constantMarks(glm::vec3(1.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(3.5f, 3.5f, 12.0f), field, constantOpacity(20.0f), splat});
        for (const float phase : {0.0f, 0.3f, 0.7f}) {
            splat->phase.setValue(phase);
            const image::Image image = drawWith(backend, *root, 240, 240).image;
            test::expectFiniteAndNotEmpty(image, "cut marks");
            // Pixel (x, y) covers world x from x / 20 − 2.5, y from 9.5 − y / 20.
            for (int y = 0; y < 240; ++y) {
                for (int x = 0; x < 240; ++x) {
                    const float worldX = (x + 0.5f) / 20.0f - 2.5f;
                    const float worldY = 9.5f - (y + 0.5f) / 20.0f;
                    const float outside =
                        std::max({-0.5f - worldX, worldX - 7.5f, -0.5f - worldY, worldY - 7.5f});
                    if (outside > 3.0f / 20.0f) {
                        ASSERT_EQ(image.pixel(x, y).a, 0.0f)
                            << nameOf(backend) << ", phase " << phase << " at " << x << ", " << y;
                    }
                }
            }
        }
    }
}

TEST(VectorSplat, colourByPositionFollowsTheAxis) {
    // Marks of voxels along x coloured by their x through a gray map: the colour of each voxel's
    // column of pixels (over its opacity) grows from black to white.
    const VolumeData::Ptr field = uniformField({8, 4, 1}, glm::vec3(0.0f, 1.0f, 0.0f));
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr splat = VectorSplat::create();
        splat->colorMode.setValue(VectorColorMode::Position);
        splat->positionAxis.setValue(Axis::X);
        splat->positionRange.setValue(glm::vec2(0.0f, 7.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(3.5f, 1.5f, 8.0f), field, constantOpacity(40.0f), splat});
        const image::Image image = drawWith(backend, *root, 256, 256).image;
        double previous = -1.0;
        for (int voxel = 1; voxel < 7; ++voxel) {
            double colour = 0.0;
            double alpha = 0.0;
            for (int y = 0; y < image.height(); ++y) {
                for (int x = voxel * 32 + 8; x < voxel * 32 + 24; ++x) {
                    colour += image.pixel(x, y).r;
                    alpha += image.pixel(x, y).a;
                }
            }
            ASSERT_GT(alpha, 0.0) << nameOf(backend) << ", voxel " << voxel;
            const double gray = colour / alpha;
            EXPECT_GT(gray, previous) << nameOf(backend) << ", voxel " << voxel;
            EXPECT_NEAR(gray, voxel / 7.0, 0.1) << nameOf(backend) << ", voxel " << voxel;
            previous = gray;
        }
    }
}

TEST(VectorSplat, zeroNanHugeAndDenormalVectorsGiveFiniteImages) {
    const float huge = std::numeric_limits<float>::max();
    const std::array<glm::vec3, 5> vectors{
        glm::vec3(0.0f), glm::vec3(std::nanf(""), 0.0f, 0.0f), glm::vec3(huge, huge, huge),
        glm::vec3(1e-40f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    const VolumeData::Ptr field = vectorVolume(
        {5, 1, 1}, [&](int i, int, int) { return vectors[static_cast<std::size_t>(i)]; });
    for (const Backend backend : kBackends) {
        for (const bool combined : {false, true}) {
            sg::Node::Ptr splat = combined ? sg::Node::Ptr(CombinedSplat::create())
                                           : sg::Node::Ptr(VectorSplat::create());
            sg::Separator::Ptr root =
                sceneOf({topCamera(2.0f, 0.0f, 8.0f), field, constantOpacity(4.0f), splat});
            const test::RenderedFrame frame = drawWith(backend, *root, 128, 128);
            test::expectFiniteWithAlphaInRange(frame.image, combined ? "combined" : "vector");
            // Combined splats draw the zero vector's scalar part: 4 splats (the NaN voxel is
            // empty). A vector splat's count is its marks'.
            if (combined) {
                EXPECT_EQ(frame.statistics.splats, 4u) << nameOf(backend);
            }
        }
    }
}

TEST(VectorSplat, octreeCutsLeaveTheMarksAsTheyAreAndTheyFollowTheFlowInTheData) {
    // A vortex filling a disc of radius 12 voxels in a 32³ box. Marks do not depend on a cut: a
    // vector splat's budget changes nothing, and a combined splat's cut of a few hundred scalar
    // splats draws the same marks, which show the swirl and lie within the disc.
    const float centre = 15.5f;
    const VolumeData::Ptr field = vectorVolume({32, 32, 32}, [&](int i, int j, int) {
        const glm::vec2 at(static_cast<float>(i) - centre, static_cast<float>(j) - centre);
        return glm::length(at) < 12.0f ? glm::vec3(-at.y, at.x, 0.0f) : glm::vec3(std::nanf(""));
    });
    for (const Backend backend : kBackends) {
        VectorSplat::Ptr vectors = constantMarks(glm::vec3(1.0f));
        sg::Separator::Ptr root =
            sceneOf({topCamera(centre, centre, 36.0f), field, TransferFunction::create(), vectors});
        const test::RenderedFrame full = drawWith(backend, *root, 216, 216);
        vectors->maxSplats.setValue(400);
        const test::RenderedFrame budgeted = drawWith(backend, *root, 216, 216);
        EXPECT_EQ(budgeted.statistics.splats, full.statistics.splats) << nameOf(backend);
        EXPECT_EQ(budgeted.image.pixels(), full.image.pixels()) << nameOf(backend);

        CombinedSplat::Ptr combined = CombinedSplat::create();
        combined->maxSplats.setValue(400);
        root = sceneOf({topCamera(centre, centre, 36.0f), field, constantOpacity(0.05f), combined});
        const test::RenderedFrame cut = drawWith(backend, *root, 216, 216);
        EXPECT_LE(cut.statistics.splats, 400u) << nameOf(backend);
        test::expectFiniteWithAlphaInRange(cut.image, "octree cut");
        // 6 pixels a voxel; a coarse splat of the cut reaches at most 4 times a voxel's.
        const double reach = 4.0 * combined->markReach();
        for (int y = 0; y < 216; ++y) {
            for (int x = 0; x < 216; ++x) {
                const glm::vec2 at((x + 0.5f) / 6.0f - 18.0f, 18.0f - (y + 0.5f) / 6.0f);
                if (glm::length(at) > 12.0 + reach) {
                    ASSERT_EQ(cut.image.pixel(x, y).a, 0.0f) << nameOf(backend);
                }
            }
        }
        // The swirl: the streaks follow the vortex within the disc, over the cut's medium too.
        const auto flowAt = [](float x, float y) {
            return glm::vec2(18.0f - y / 6.0f, x / 6.0f - 18.0f);
        };
        const auto inRing = [](int x, int y) {
            const float r =
                glm::length(glm::vec2((x + 0.5f) / 6.0f - 18.0f, 18.0f - (y + 0.5f) / 6.0f));
            return r > 3.0f && r < 10.0f;
        };
        for (const test::RenderedFrame* frame : {&full, &cut}) {
            const bench::StreakAngles angles =
                bench::streakAngles(bench::displayedLuminance(frame->image), flowAt, 3.0, inRing);
            EXPECT_LT(angles.median, 15.0)
                << nameOf(backend) << (frame == &cut ? ", combined cut" : ", vector");
        }
    }
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
    for (const Backend backend : kBackends) {
        const image::Image scalar =
            drawWith(backend, *sceneOf({camera, tornado, transfer, TextureSplat::create()}), 96, 96)
                .image;
        CombinedSplat::Ptr combined = CombinedSplat::create();
        combined->markContrast.setValue(0.0f);
        sg::Separator::Ptr root = sceneOf({camera, tornado, transfer, combined});
        test::expectFiniteAndNotEmpty(scalar, "texture splats");
        EXPECT_LT(
            image::ImageComparison(scalar, drawWith(backend, *root, 96, 96).image).maxPixelError(),
            1e-5)
            << nameOf(backend);
        combined->markContrast.setValue(1.0f);
        EXPECT_GT(
            image::ImageComparison(scalar, drawWith(backend, *root, 96, 96).image).maxPixelError(),
            0.05)
            << nameOf(backend);
    }
}

TEST(VectorSplat, bothBackendsDrawTheSameMarks) {
    // Vector and combined splats, orthographic and in perspective with the eye close: the CPU
    // backend draws what the GL backend draws, up to float rounding.
    const VolumeData::Ptr tornado = VolumeData::create();
    tornado->source.setValue(VolumeSource::Tornado);
    tornado->resolution.setValue(glm::vec3(16.0f));
    TransferFunction::Ptr transfer = TransferFunction::create();
    transfer->range.setValue(glm::vec2(0.0f, 0.32f));
    transfer->opacities.setValue({0.0f, 30.0f});
    PerspectiveCamera::Ptr perspective = PerspectiveCamera::create();
    perspective->position.setValue(glm::vec3(0.5f, -0.9f, 1.2f));
    perspective->orientation.setValue(sg::Rotation(glm::vec3(1.0f, 0.0f, 0.0f), 0.9f));
    for (const Camera::Ptr& camera :
         {Camera::Ptr(topCamera(0.5f, 0.5f, 1.2f)), Camera::Ptr(perspective)}) {
        for (const bool combined : {false, true}) {
            const sg::Node::Ptr splat = combined ? sg::Node::Ptr(CombinedSplat::create())
                                                 : sg::Node::Ptr(VectorSplat::create());
            sg::Separator::Ptr root = sceneOf({camera, tornado, transfer, splat});
            const image::Image gl = drawWith(Backend::Gl, *root, 128, 128).image;
            const image::Image cpu = drawWith(Backend::Cpu, *root, 128, 128).image;
            test::expectFiniteAndNotEmpty(cpu, "marks");
            EXPECT_GT(image::ImageComparison(gl, cpu).rgb().psnr, 50.0)
                << (combined ? "combined" : "vector");
        }
    }
}

TEST(VectorSplat, badFieldsAndScalarDataAreReportedByName) {
    const auto message = [](const std::vector<sg::Node::Ptr>& nodes) {
        try {
            drawWith(Backend::Cpu, *sceneOf(nodes), 8, 8);
        } catch (const DataError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    const VolumeData::Ptr field = uniformField({2, 2, 2}, glm::vec3(1.0f, 0.0f, 0.0f));
    VectorSplat::Ptr splat = VectorSplat::create();
    splat->setName("winds");
    const auto expectError = [&](const std::string& expected) {
        EXPECT_EQ(message({topCamera(0.0f, 0.0f, 4.0f), field, constantOpacity(1.0f), splat}),
                  "VectorSplat 'winds': " + expected);
    };
    splat->markDensity.setValue(0.0f);
    expectError("markDensity must be finite and in (0, 4], got 0");
    splat->markDensity.setValue(5.0f);
    expectError("markDensity must be finite and in (0, 4], got 5");
    splat->markDensity.setValue(0.6f);
    splat->markLength.setValue(std::nanf(""));
    expectError("markLength must be finite and in (0, 64], got nan");
    splat->markLength.setValue(2.5f);
    splat->markWidth.setValue(9.0f);
    expectError("markWidth must be finite and in (0, 8], got 9");
    splat->markWidth.setValue(0.08f);
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
    splat->maskData.setValue(uniformField({3, 2, 2}, glm::vec3(1.0f)));
    EXPECT_EQ(message({topCamera(0.0f, 0.0f, 4.0f), field, constantOpacity(1.0f), splat})
                  .rfind("VectorSplat 'winds': maskData VolumeData has 3x2x2 voxels but the "
                         "vectors have 2x2x2",
                         0),
              0u);
    splat->maskData.setValue(nullptr);
    VolumeData::Ptr scalars = VolumeData::create();
    scalars->source.setValue(VolumeSource::Blob);
    scalars->resolution.setValue(glm::vec3(2.0f));
    EXPECT_EQ(message({topCamera(0.0f, 0.0f, 4.0f), scalars, constantOpacity(1.0f), splat}),
              "VectorSplat 'winds': VolumeData holds scalars; vector splats need a vector field (a "
              "raw file with 3 components, an OpenVDB vec3s grid, or TORNADO, JET_STREAM, "
              "AEROGEL)");
}

} // namespace
} // namespace texsplat::nodes
