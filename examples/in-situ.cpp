/// @file
/// @brief A simulation that renders its data where it lives, on every rank at once (in situ):
/// each rank holds its own block of the grid, with a layer of ghost cells as simulations keep
/// them, hands it to texsplat::distributed::InSituRenderer without a copy, and rank 0 gets the
/// picture of the whole grid and writes it (docs/distributed.md, "In situ").
///
/// The "simulation" is a field of two Gaussian blobs circling each other over waves, sampled on
/// a grid of R³ voxels over [-1, 1]³ that MPI_Dims_create() splits into a grid of blocks, one per
/// rank. Each time step the ranks update their blocks (ghost cells included, as a halo exchange
/// would leave them) and render.
///
/// Usage: `mpirun -np N texsplat_example_in_situ PREFIX [--resolution R] [--ghost G]
/// [--steps S] [--size W] [--direction x,y,z] [--reference]` writes PREFIX_0000.png,
/// PREFIX_0001.png, ... (W x W pixels, default R 48, G 1, S 2, W 256, seen along -1,-0.6,-0.45).
/// With --reference, rank 0 also renders each step's whole grid in one process and prints how
/// close the two pictures are. Run by a test under mpirun (examples/CMakeLists.txt) and by
/// scripts/distributed-results.py.

#include "nodes/NodeTypes.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/distributed/InSituRenderer.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/CameraView.h"
#include "nodes/render/SceneRenderer.h"
#include "nodes/volume/ExternalGrid.h"
#include "scenegraph/Box3.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"

#include <mpi.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace texsplat;

namespace {

struct Arguments {
    std::string prefix;
    int resolution = 48;
    int ghost = 1;
    int steps = 2;
    int size = 256;
    glm::vec3 direction{-1.0f, -0.6f, -0.45f};
    bool reference = false;
};

Arguments parse(int argc, char** argv) {
    Arguments arguments;
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        const auto number = [&](int& value) {
            if (i + 1 >= argc) {
                throw DataError(option + ": expected a number");
            }
            value = std::stoi(argv[++i]);
        };
        if (option == "--resolution") {
            number(arguments.resolution);
        } else if (option == "--ghost") {
            number(arguments.ghost);
        } else if (option == "--steps") {
            number(arguments.steps);
        } else if (option == "--size") {
            number(arguments.size);
        } else if (option == "--direction") {
            if (i + 1 >= argc || std::sscanf(argv[++i], "%f,%f,%f", &arguments.direction.x,
                                             &arguments.direction.y, &arguments.direction.z) != 3) {
                throw DataError("--direction: expected x,y,z");
            }
        } else if (option == "--reference") {
            arguments.reference = true;
        } else {
            arguments.prefix = option;
        }
    }
    if (arguments.prefix.empty()) {
        throw DataError("usage: texsplat_example_in_situ PREFIX [--resolution R] [--ghost G] "
                        "[--steps S] [--size W] [--direction x,y,z] [--reference]");
    }
    return arguments;
}

// The simulated field at a point of [-1, 1]³ and time t.
float field(const glm::dvec3& p, double t) {
    const auto blob = [&](const glm::dvec3& centre, double width) {
        const glm::dvec3 d = p - centre;
        return std::exp(-glm::dot(d, d) / (width * width));
    };
    const glm::dvec3 orbit(0.4 * std::cos(t), 0.4 * std::sin(t), 0.1 * std::sin(2.0 * t));
    const double waves = 0.15 * std::sin(6.0 * p.x + t) * std::cos(5.0 * p.y) * std::cos(4.0 * p.z);
    return static_cast<float>(blob(orbit, 0.35) + 0.7 * blob(-orbit, 0.25) + waves);
}

// A rank's block: its box of the whole grid widened by the ghost layers (inside the grid).
struct Block {
    glm::i64vec3 first; // whole-grid index of the block's first voxel (ghost cells included)
    glm::i64vec3 dims;  // voxels held
    glm::i64vec3 ghostLow;
    glm::i64vec3 ghostHigh;
    std::vector<float> values; // x fastest, as a simulation stores them
};

Block makeBlock(const std::array<int, 3>& ranks, const std::array<int, 3>& coordinates,
                int resolution, int ghost) {
    Block block;
    for (int axis = 0; axis < 3; ++axis) {
        const std::int64_t n = resolution;
        const std::int64_t lo = n * coordinates[axis] / ranks[axis];
        const std::int64_t hi = n * (coordinates[axis] + 1) / ranks[axis];
        const std::int64_t low = std::max<std::int64_t>(0, lo - ghost);
        const std::int64_t high = std::min<std::int64_t>(n, hi + ghost);
        block.first[axis] = low;
        block.dims[axis] = high - low;
        block.ghostLow[axis] = lo - low;
        block.ghostHigh[axis] = high - hi;
    }
    block.values.resize(static_cast<std::size_t>(block.dims.x * block.dims.y * block.dims.z));
    return block;
}

// The simulation's time step: the block's values (ghost cells included) at time t.
void update(Block& block, const volume::GridGeometry& whole, double t) {
    std::size_t i = 0;
    for (std::int64_t z = 0; z < block.dims.z; ++z)
        for (std::int64_t y = 0; y < block.dims.y; ++y)
            for (std::int64_t x = 0; x < block.dims.x; ++x)
                block.values[i++] =
                    field(whole.indexToWorld(glm::dvec3(block.first + glm::i64vec3(x, y, z))), t);
}

// The scene: a transfer function over the data's range and the paper's texture splats of the
// VolumeData that receives the blocks.
sg::Node::Ptr makeScene() {
    auto scene = sg::Separator::create();
    auto transfer = nodes::TransferFunction::create();
    transfer->opacityValues.setValue({0.0f, 0.35f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.0f, 6.0f});
    scene->addChild(transfer);
    auto data = nodes::VolumeData::create();
    data->source.setValue(nodes::VolumeSource::Memory);
    scene->addChild(data);
    scene->addChild(nodes::TextureSplat::create());
    return scene;
}

} // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0;
    int size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int status = 0;
    try {
        const Arguments arguments = parse(argc, argv);
        nodes::registerNodeTypes();
        // The simulation's decomposition: a grid of blocks, one per rank.
        std::array<int, 3> ranks{0, 0, 0};
        MPI_Dims_create(size, 3, ranks.data());
        std::array<int, 3> coordinates{rank % ranks[0], rank / ranks[0] % ranks[1],
                                       rank / (ranks[0] * ranks[1])};
        const std::int64_t n = arguments.resolution;
        const volume::GridGeometry whole({n, n, n}, glm::dvec3(-1.0),
                                         glm::dvec3(2.0 / double(n - 1)));
        Block block = makeBlock(ranks, coordinates, arguments.resolution, arguments.ghost);

        // The scene and a camera framing the whole grid, obliquely.
        const sg::Node::Ptr scene = makeScene();
        auto camera = nodes::PerspectiveCamera::create();
        camera->orientation.setValue(render::rotationLookingAlong(arguments.direction));
        camera->viewAll(sg::Box3(glm::vec3(whole.boundsMin()), glm::vec3(whole.boundsMax())), 1.0f);

        distributed::InSituOptions options;
        options.image.width = arguments.size;
        options.image.height = arguments.size;
        options.image.backend = render::BackendRequest::Cpu;
        distributed::InSituRenderer renderer(MPI_COMM_WORLD, options);
        for (int step = 0; step < arguments.steps; ++step) {
            const double t = 0.5 * step;
            update(block, whole, t);
            distributed::LocalBlock local;
            local.voxels = std::make_shared<volume::ExternalScalarGrid>(
                volume::GridGeometry(block.dims, whole.indexToWorld(glm::dvec3(block.first)),
                                     whole.spacing()),
                block.values.data(), block.values.size());
            local.ghostLow = block.ghostLow;
            local.ghostHigh = block.ghostHigh;
            const std::optional<image::Image> picture =
                renderer.render(local, whole, scene, camera);
            if (rank != 0) {
                continue;
            }
            char name[32];
            std::snprintf(name, sizeof name, "_%04d.png", step);
            image::writeImage(*picture, arguments.prefix + name);
            std::printf("in-situ: %d ranks (%d x %d x %d blocks, %d ghost layers), step %d: "
                        "wrote %s%s",
                        size, ranks[0], ranks[1], ranks[2], arguments.ghost, step,
                        arguments.prefix.c_str(), name);
            if (arguments.reference) {
                // The same frame in one process, from the whole grid.
                std::vector<float> values(static_cast<std::size_t>(whole.voxelCount()));
                std::size_t i = 0;
                for (std::int64_t z = 0; z < n; ++z)
                    for (std::int64_t y = 0; y < n; ++y)
                        for (std::int64_t x = 0; x < n; ++x)
                            values[i++] = field(whole.indexToWorld(glm::dvec3(x, y, z)), t);
                const sg::Node::Ptr alone = makeScene();
                auto root = sg::Separator::create();
                root->addChild(camera);
                root->addChild(alone);
                static_cast<nodes::VolumeData&>(*static_cast<sg::Separator&>(*alone).child(1))
                    .setGrid(std::make_shared<volume::ExternalScalarGrid>(whole, values.data(),
                                                                          values.size()));
                render::SceneRenderOptions single = options.image;
                single.threads = 1; // mpirun bound this rank to one core
                render::SceneRenderer one(single);
                const image::ImageComparison comparison(one.render(*root), *picture);
                std::printf("; against one process: PSNR %.1f dB", comparison.rgb().psnr);
            }
            std::printf("\n");
        }
    } catch (const std::exception& error) {
        if (rank == 0) {
            std::fprintf(stderr, "in-situ: %s\n", error.what());
        }
        status = 1;
    }
    MPI_Finalize();
    return status;
}
