#pragma once

#include "nodes/image/Image.h"
#include "scenegraph/Node.h"

#include <glm/vec4.hpp>

namespace texsplat::render {

/// @brief What sceneImage() renders.
struct SceneImageOptions {
    int width = 512;                                  ///< pixels, >= 1
    int height = 512;                                 ///< pixels, >= 1
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};     ///< premultiplied RGBA (opaque black)
    int threads = 0;                                  ///< CPU threads, 0: all cores
};

/// @brief `scene` rendered in one call, the way an embedding program renders its data: framed
/// by framedScene() when it has no camera, collected by FrameAction and drawn by the CPU backend
/// (cpu::CpuRenderer) — no GL context, no display, the same image `texsplat render --backend
/// cpu` writes. Write it with image::writeImage(). For many frames of one scene, keep a
/// FrameAction and a CpuRenderer instead (their caches then serve every frame).
/// @throws DataError for a bad size or a scene that cannot be framed, and whatever loading the
/// scene's data throws.
image::Image sceneImage(const sg::Node::Ptr& scene, const SceneImageOptions& options = {});

} // namespace texsplat::render
