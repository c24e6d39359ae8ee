#include "DistributedTesting.h"

#include "nodes/Camera.h"
#include "nodes/render/SceneFraming.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace texsplat::test {
namespace {

// A smooth blob over an uneven grid, its range from the data (the whole grid's, gathered).
const std::string kBlob = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT opacityValues [ 0, 0.25, 1 ] opacities [ 0, 0, 9 ] }
    VolumeData { source BLOB resolution 30 34 38 }
    TextureSplat { }
})";

// The eight octants' viewing directions, none along a diagonal.
const glm::vec3 kOctants[] = {{1.0f, 0.8f, 0.6f},   {-1.0f, 0.8f, 0.6f},  {1.0f, -0.8f, 0.6f},
                              {-1.0f, -0.8f, 0.6f}, {1.0f, 0.8f, -0.6f},  {-1.0f, 0.8f, -0.6f},
                              {1.0f, -0.8f, -0.6f}, {-1.0f, -0.8f, -0.6f}};

class OctantTest : public ::testing::TestWithParam<int> {};

TEST_P(OctantTest, givesTheOneProcessPictureInPerspective) {
    View view;
    view.direction = kOctants[GetParam()];
    const double psnr = psnrAgainstOneProcess(kBlob, view);
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST_P(OctantTest, givesTheOneProcessPictureOrthographically) {
    View view;
    view.direction = kOctants[GetParam()] * glm::vec3(0.7f, 1.0f, 1.3f);
    view.camera = render::FramingCamera::Orthographic;
    const double psnr = psnrAgainstOneProcess(kBlob, view);
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

INSTANTIATE_TEST_SUITE_P(Octants, OctantTest, ::testing::Range(0, 8));

TEST(DistributedRender, givesTheOneProcessPictureAlongAnAxis) {
    // Planes along the view would order the two sides' overlapping splats otherwise than one
    // process: the bricks are cut across it.
    for (const glm::vec3 direction :
         {glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}) {
        View view;
        view.direction = direction;
        const double psnr = psnrAgainstOneProcess(kBlob, view);
        if (rank() == 0) {
            EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
        }
    }
}

TEST(DistributedRender, givesTheOneProcessPictureWithTheEyeInsideTheVolume) {
    View view;
    view.direction = {-0.8f, -0.5f, -1.0f};
    view.adjust = [](sg::Node& root) {
        nodes::Camera* camera = render::findCamera(root);
        camera->position.setValue({0.15f, -0.1f, 0.3f});
        camera->nearDistance.setValue(0.01f);
    };
    const double psnr = psnrAgainstOneProcess(kBlob, view);
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, givesTheOneProcessPictureWithEitherCompositing) {
    const View view;
    const double radixK = psnrAgainstOneProcess(kBlob, view, distributed::Compositing::RadixK);
    const double reduce = psnrAgainstOneProcess(kBlob, view, distributed::Compositing::Reduce);
    if (rank() == 0) {
        EXPECT_GE(radixK, kMinimumPsnr);
        EXPECT_GE(reduce, kMinimumPsnr);
    }
}

TEST(DistributedRender, drawsRanksWithoutVoxels) {
    // Two voxels for up to five ranks: the others' bricks are empty.
    const std::string tiny = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT range 0 1 opacities [ 4, 4 ] }
    VolumeData { source BLOB resolution 2 1 1 }
    TextureSplat { }
})";
    const double psnr = psnrAgainstOneProcess(tiny, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, drawsRanksWhoseVoxelsAreAllTransparent) {
    // Only the blob's core is opaque: the outer bricks classify to nothing.
    const std::string core = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT opacityValues [ 0, 0.8, 1 ] opacities [ 0, 0, 20 ] }
    VolumeData { source BLOB resolution 40 24 24 }
    TextureSplat { }
})";
    const double psnr = psnrAgainstOneProcess(core, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, takesPercentileRangesFromTheWholeData) {
    const std::string percentiles = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset VIRIDIS rangeMode PERCENTILE percentiles 5 95
                       opacityValues [ 0, 0.3, 1 ] opacities [ 0, 0, 8 ] }
    VolumeData { source MARSCHNER_LOBB resolution 33 33 33 }
    TextureSplat { }
})";
    const double psnr = psnrAgainstOneProcess(percentiles, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, hidesSplatsBehindMeshesThatOneRankDraws) {
    // Fibers through the volume: opaque, drawn once under the splats in front of them.
    const std::string fibers = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset COOL_WARM range 0 2 opacityValues [ 0, 0.3, 1 ] opacities [ 0, 2, 9 ] }
    VolumeData { source AEROGEL resolution 24 24 24 }
    Separator { Material { diffuseColor 0.9 0.9 0.85 } Fibers { segments 8 } }
    TextureSplat { }
})";
    const double psnr = psnrAgainstOneProcess(fibers, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, drawsTheOneProcessOctreeCutOfAnErrorThreshold) {
    // The threshold is relative to the whole grid's largest value, not the brick's.
    const std::string cut = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT opacityValues [ 0, 0.25, 1 ] opacities [ 0, 0, 9 ] }
    VolumeData { source MARSCHNER_LOBB resolution 33 33 33 }
    TextureSplat { errorThreshold 0.1 }
})";
    const double psnr = psnrAgainstOneProcess(cut, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, sharesASplatBudgetAsOneProcessSpendsIt) {
    // The bricks refine to the priority at which their cuts add up to the budget.
    const std::string budget = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset HOT opacityValues [ 0, 0.25, 1 ] opacities [ 0, 0, 9 ] }
    VolumeData { source MARSCHNER_LOBB resolution 33 33 33 }
    TextureSplat { maxSplats 4000 }
})";
    const double psnr = psnrAgainstOneProcess(budget, View());
    if (rank() == 0) {
        EXPECT_GE(psnr, kMinimumPsnr) << ranks() << " ranks";
    }
}

TEST(DistributedRender, drawsTheOneProcessMarksOfVectorAndCombinedSplats) {
    // Marks are drawn per cell of the whole grid (octree::MarkSource), as many per voxel as one
    // process draws (the whole grid's depth and centre set the count): each brick draws the
    // whole's marks of its own voxels, so the bricks together draw one process's marks, and the
    // picture is one process's.
    for (const char* splat : {"VectorSplat { markType PARTICLES markDensity 4 }",
                              "CombinedSplat { markType SCRATCHES markDensity 4 }"}) {
        const std::string marks = std::string(R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { preset BROWNS range 0 0.32 opacityValues [ 0, 0.3, 1 ] opacities [ 0, 0, 40 ] }
    VolumeData { source TORNADO resolution 37 40 43 }
    )") + splat + "\n}";
        for (const glm::vec3 direction : {glm::vec3(0.3f, -1.0f, 0.4f), kOctants[5]}) {
            View view;
            view.direction = direction;
            constexpr int kSize = 128;
            distributed::SceneRenderer renderer(MPI_COMM_WORLD, testImage(kSize));
            const std::optional<image::Image> split =
                renderer.render(*framedScene(marks, view, true));
            std::uint64_t splats = renderer.statistics().splats;
            MPI_Allreduce(MPI_IN_PLACE, &splats, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
            if (rank() != 0) {
                continue;
            }
            render::SceneRenderer alone(testImage(kSize));
            const image::Image reference = alone.render(*framedScene(marks, view, false));
            if (std::string(splat).rfind("VectorSplat", 0) == 0) {
                // One splat per mark.
                EXPECT_GT(alone.statistics().splats, 1000U);
                EXPECT_EQ(splats, alone.statistics().splats) << ranks() << " ranks";
            }
            EXPECT_GE(image::ImageComparison(reference, *split).rgb().psnr, kMinimumPsnr)
                << splat << ", " << ranks() << " ranks";
        }
    }
}

TEST(DistributedRender, endsOnEveryRankWithTheMessageOfARankThatCannotRead) {
    // Rank 1 (rank 0 alone) reads a file that is not there; the others read none.
    const int failing = ranks() > 1 ? 1 : 0;
    const std::string source = rank() == failing ? "source FILE_NPY fileName \"no-such-volume.npy\""
                                                 : "source BLOB resolution 16 16 16";
    const std::string scene = "#Inventor V2.1 ascii\nSeparator {\n"
                              "TransferFunction { range 0 1 }\n"
                              "PerspectiveCamera { position 0 0 5 }\n"
                              "VolumeData { " +
                              source + " }\nTextureSplat { }\n}";
    distributed::SceneRenderer renderer(MPI_COMM_WORLD, testImage());
    const sg::Node::Ptr root = sg::SceneReader::readString(scene, "test.iv");
    try {
        renderer.render(*root);
        FAIL() << "expected IoError on every rank";
    } catch (const IoError& error) {
        const std::string prefix = ranks() > 1 ? "rank 1: " : "";
        EXPECT_EQ(std::string(error.what()).rfind(prefix + "test.iv:5:1: VolumeData: ", 0), 0u)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("cannot open file"), std::string::npos)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("no-such-volume.npy"), std::string::npos)
            << error.what();
    }
}

TEST(DistributedRender, refusesOneVolumeDrawnAtTwoPlaces) {
    const std::string twice = R"(#Inventor V2.1 ascii
Separator {
    TransferFunction { range 0 1 }
    DEF data VolumeData { source BLOB resolution 8 8 8 }
    TextureSplat { }
    Transform { translation 3 0 0 }
    TextureSplat { }
})";
    distributed::SceneRenderer renderer(MPI_COMM_WORLD, testImage());
    try {
        renderer.render(*framedScene(twice, View(), true));
        if (ranks() > 1) {
            FAIL() << "expected DataError";
        }
    } catch (const DataError& error) {
        EXPECT_STREQ(error.what(), "VolumeData 'data' is drawn at two places: a render split "
                                   "over processes splits each volume once; give each place its "
                                   "own VolumeData");
    }
}

} // namespace
} // namespace texsplat::test
