#pragma once

#include "nodes/distributed/SceneRenderer.h"
#include "nodes/image/Image.h"
#include "nodes/image/ImageComparison.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneRenderer.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <mpi.h>

#include <functional>
#include <optional>
#include <string>

namespace texsplat::test {

/// @brief This process's rank and the number of ranks.
inline int rank() {
    int value = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &value);
    return value;
}
inline int ranks() {
    int value = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &value);
    return value;
}

/// @brief The least PSNR against the one-process picture that a distributed render must reach.
inline constexpr double kMinimumPsnr = 50.0;

/// @brief How a test scene is seen.
struct View {
    glm::vec3 direction{-1.0f, -0.7f, -0.4f};
    render::FramingCamera camera = render::FramingCamera::Perspective;
    std::function<void(sg::Node&)> adjust; ///< changes the framed scene (moves its camera)
};

/// @brief Options of the small images the tests draw (CPU backend, one thread).
inline render::SceneRenderOptions testImage(int size = 96) {
    render::SceneRenderOptions options;
    options.width = size;
    options.height = size;
    options.backend = render::BackendRequest::Cpu;
    options.threads = 1;
    return options;
}

/// @brief `text`, read and framed as `view` says; with `bricks`, its volumes made bricks first
/// (distributed::SceneRenderer::prepareBricks()), as `texsplat render` does under mpirun.
inline sg::Node::Ptr framedScene(const std::string& text, const View& view, bool bricks) {
    const sg::Node::Ptr scene = sg::SceneReader::readString(text, "test.iv");
    if (bricks) {
        distributed::SceneRenderer::prepareBricks(*scene);
    }
    render::Framing framing;
    framing.camera = view.camera;
    framing.direction = view.direction;
    const sg::Node::Ptr root = render::framedScene(scene, 1.0f, framing);
    if (view.adjust) {
        view.adjust(*root);
    }
    return root;
}

/// @brief The PSNR (RGB, peak 1) of the distributed render of `text` against its one-process
/// render, on rank 0 (0 elsewhere). Every rank calls it.
inline double
psnrAgainstOneProcess(const std::string& text, const View& view,
                      distributed::Compositing compositing = distributed::Compositing::RadixK,
                      int size = 96) {
    distributed::SceneRenderer renderer(MPI_COMM_WORLD, testImage(size), compositing);
    const std::optional<image::Image> split = renderer.render(*framedScene(text, view, true));
    if (rank() != 0) {
        return 0.0;
    }
    render::SceneRenderer alone(testImage(size));
    const image::Image reference = alone.render(*framedScene(text, view, false));
    return image::ImageComparison(reference, *split).rgb().psnr;
}

} // namespace texsplat::test
