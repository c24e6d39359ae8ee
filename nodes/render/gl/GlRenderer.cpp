#include "nodes/render/gl/GlRenderer.h"

#include "nodes/render/detail/DepthOrderedRuns.h"
#include "nodes/render/gl/MeshBatch.h"
#include "nodes/render/gl/SplatBatch.h"
#include "nodes/render/gl/detail/SplatBatchCache.h"
#include "octree/Splat.h"
#include "scenegraph/Error.h"
#include "scenegraph/gl/CheckGlError.h"
#include "scenegraph/gl/Context.h"
#include "scenegraph/gl/LightScale.h"
#include "scenegraph/gl/ObjectName.h"
#include "scenegraph/actions/Seconds.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <string>

namespace texsplat::render {
namespace {

using Clock = sg::TimingClock;
using sg::secondsSince;

// Leaves the GL state as it found it for the caller (a viewer may draw its UI after the frame, a
// test its own quads): the depth test, blending and depth writes are what the passes change.
struct PassState {
    PassState() : depthTest(glIsEnabled(GL_DEPTH_TEST) == GL_TRUE) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
    }
    ~PassState() {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        if (!depthTest) {
            glDisable(GL_DEPTH_TEST);
        }
    }
    const bool depthTest;
    PassState(const PassState&) = delete;
    PassState& operator=(const PassState&) = delete;
};

constexpr gl::FramebufferColor kColor = gl::FramebufferColor::Rgba32F;
constexpr gl::FramebufferDepth kDepth = gl::FramebufferDepth::Depth32F;

// Light as the read-back returns it: scaled back from what GL drew (kLightScale, a power of
// two: exact) and clamped to FLT_MAX (+Inf beyond it), as on the CPU backend and in the ray
// caster; alpha is not scaled.
glm::vec4 readLight(const float* rgba) {
    constexpr float kMax = std::numeric_limits<float>::max();
    glm::vec4 light;
    for (int channel = 0; channel < 4; ++channel) {
        const float value = channel < 3 ? rgba[channel] / gl::kLightScale : rgba[channel];
        light[channel] = std::clamp(value, -kMax, kMax);
    }
    return light;
}

} // namespace

// What a frame draws with, made or found once for all its tiles.
struct GlRenderer::Prepared {
    std::vector<MeshBatch> meshes;      // one per FrameMesh
    std::vector<SplatBatch*> batches;   // one per FrameSplats, kept by mBatches
    std::vector<detail::SplatRun> runs; // the splat pass's order
};

// Pixels [x, x + width) x [y, y + height) of the image, y from the bottom row (GL's window
// coordinates), drawn into the framebuffer's corner at the origin.
struct GlRenderer::Tile {
    int x;
    int y;
    int width;
    int height;
    // Clip space of the whole image to clip space of the tile's viewport: the tile's part of
    // normalized device coordinates, [2x/W − 1, 2(x + width)/W − 1] along x, is scaled and moved
    // onto [−1, 1]; depth and w stay as they are.
    glm::dmat4 matrix(int imageWidth, int imageHeight) const {
        glm::dmat4 result(1.0);
        result[0][0] = double(imageWidth) / width;
        result[1][1] = double(imageHeight) / height;
        result[3][0] = double(imageWidth - 2 * x - width) / width;
        result[3][1] = double(imageHeight - 2 * y - height) / height;
        return result;
    }
};

GlRenderer::GlRenderer() : mBatches(std::make_unique<detail::SplatBatchCache>()) {
    gl::ObjectName::requireCurrentContext("GlRenderer");
}

GlRenderer::~GlRenderer() = default;
GlRenderer::GlRenderer(GlRenderer&&) noexcept = default;
GlRenderer& GlRenderer::operator=(GlRenderer&&) noexcept = default;

void GlRenderer::setMaxTileSize(int pixels) {
    if (pixels < 0) {
        throw DataError("GlRenderer: the tile size must be 0 (the device's) or positive, got " +
                        std::to_string(pixels));
    }
    mMaxTileSize = pixels;
}

int GlRenderer::maxTileSize() {
    if (mMaxTileSize == 0) {
        mMaxTileSize = gl::Framebuffer::largestSquare(kColor, kDepth);
    }
    return mMaxTileSize;
}

const gl::Framebuffer& GlRenderer::framebuffer() const {
    if (!mFramebuffer) {
        throw GlError("GlRenderer::framebuffer(): no frame drawn yet");
    }
    return *mFramebuffer;
}

void GlRenderer::useFramebuffer(int width, int height) {
    if (!mFramebuffer || mFramebuffer->width() != width || mFramebuffer->height() != height) {
        mFramebuffer.reset();
        mFramebuffer.emplace(width, height, kColor, kDepth);
    }
}

GlRenderer::Prepared GlRenderer::prepare(const Frame& frame, sg::RenderStatistics& statistics) {
    const Clock::time_point start = Clock::now();
    Prepared prepared;
    prepared.meshes.reserve(frame.meshes.size());
    for (const FrameMesh& mesh : frame.meshes) {
        prepared.meshes.emplace_back(*mesh.mesh);
    }
    const std::uint64_t context = gl::Context::current()->serial();
    const std::size_t madeBefore = mBatches->made();
    for (const FrameSplats& splats : frame.splats) {
        SplatBatch& batch = mBatches->batch(splats.footprint, context);
        statistics.memory.textures += batch.textureBytes();
        if (splats.voxels) {
            // GL draws a list: a batch of voxels is listed here (the CPU backend walks them).
            statistics.memory.splats += splats.list()->memoryBytes();
        }
        prepared.batches.push_back(&batch);
    }
    statistics.builds.splatBatches += mBatches->made() - madeBefore;
    statistics.addTime(sg::RenderPhase::Upload, secondsSince(start));
    if (!frame.splats.empty()) {
        prepared.runs = detail::frameRuns(frame, statistics);
    }
    return prepared;
}

void GlRenderer::drawPasses(const Frame& frame, Prepared& prepared, const Tile* tile,
                            sg::RenderStatistics& statistics) {
    const Clock::time_point start = Clock::now();
    // Instances are uploaded when a run of a list is first drawn: a node used twice in the graph
    // (DEF/USE) has one footprint, so one batch, for two lists whose runs may interleave.
    double upload = 0.0;
    // Light is drawn scaled (gl/LightScale.h), the background too.
    glm::vec4 background = frame.background * gl::kLightScale;
    background.a = frame.background.a;
    mFramebuffer->clear(background, 1.0f);
    // A frame's clip matrix as the tile sees it, multiplied in double: the tile matrix of an
    // image 10⁴ pixels wide scales by 10⁴.
    const auto toTile = [&](const glm::mat4& localToClip) {
        return tile ? glm::mat4(tile->matrix(frame.width, frame.height) * glm::dmat4(localToClip))
                    : localToClip;
    };
    if (tile) {
        glViewport(0, 0, tile->width, tile->height);
    }
    {
        const PassState passState;
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        const GLboolean meshColor = frame.meshesHideOnly ? GL_FALSE : GL_TRUE;
        glColorMask(meshColor, meshColor, meshColor, meshColor);
        for (std::size_t i = 0; i < prepared.meshes.size(); ++i) {
            MeshLighting lighting = frame.meshes[i].lighting;
            lighting.localToClip = toTile(lighting.localToClip);
            prepared.meshes[i].draw(lighting);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        // Pass 2: the splats see the surfaces (depth test) but do not occlude each other; the
        // back-to-front order does that through "over" on premultiplied colors.
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        // Image pixels (x right, y down) to the whole image's clip space, for the marks.
        glm::mat4 imageToClip(1.0f);
        imageToClip[0][0] = 2.0f / static_cast<float>(frame.width);
        imageToClip[1][1] = -2.0f / static_cast<float>(frame.height);
        imageToClip[3][0] = -1.0f;
        imageToClip[3][1] = 1.0f;
        imageToClip = toTile(imageToClip);
        // The list whose marks each mark batch holds in this pass (marks follow the view, and a
        // node used twice has one batch for two lists).
        std::map<const SplatBatch*, const FrameSplats*> markLists;
        for (const detail::SplatRun& run : prepared.runs) {
            const FrameSplats& splats = frame.splats[run.batch];
            SplatBatch& batch = *prepared.batches[run.batch];
            if (splats.footprint->hasMarks()) {
                const FrameSplats*& uploaded = markLists[&batch];
                if (uploaded != &splats) {
                    const Clock::time_point uploadStart = Clock::now();
                    batch.uploadMarks(splats, frame.width, frame.height);
                    upload += secondsSince(uploadStart);
                    uploaded = &splats;
                }
            } else if (!batch.isUploaded(splats.list())) {
                const Clock::time_point uploadStart = Clock::now();
                batch.upload(splats.list());
                upload += secondsSince(uploadStart);
            }
            SplatView view = splats.view;
            view.localToClip = toTile(view.localToClip);
            batch.draw(view, splats.marks, imageToClip, run.begin, run.end - run.begin);
        }
    }
    glFinish();
    statistics.addTime(sg::RenderPhase::Upload, upload);
    statistics.addTime(sg::RenderPhase::Draw, secondsSince(start) - upload);
    gl::checkGlError("GlRenderer::render()");
}

void GlRenderer::render(const Frame& frame, sg::RenderStatistics& statistics) {
    useFramebuffer(frame.width, frame.height);
    Prepared prepared = prepare(frame, statistics);
    drawPasses(frame, prepared, nullptr, statistics);
}

image::Image GlRenderer::draw(const Frame& frame, sg::RenderStatistics& statistics,
                              bool withDepth) {
    const int tileSize = maxTileSize();
    const bool isTiled = frame.width > tileSize || frame.height > tileSize;
    useFramebuffer(std::min(frame.width, tileSize), std::min(frame.height, tileSize));
    Prepared prepared = prepare(frame, statistics);
    image::Image image = image::Image::uncleared(frame.width, frame.height); // tiles cover it
    if (withDepth) {
        image.addDepth();
    }
    for (int y = 0; y < frame.height; y += tileSize) {
        for (int x = 0; x < frame.width; x += tileSize) {
            const Tile tile{x, y, std::min(tileSize, frame.width - x),
                            std::min(tileSize, frame.height - y)};
            drawPasses(frame, prepared, isTiled ? &tile : nullptr, statistics);
            readTile(tile, image, statistics);
        }
    }
    return image;
}

void GlRenderer::readTile(const Tile& tile, image::Image& image,
                          sg::RenderStatistics& statistics) const {
    const Clock::time_point start = Clock::now();
    const std::vector<float> rgba = mFramebuffer->readColor(gl::RowOrder::BottomUp);
    const std::vector<float> depths =
        image.hasDepth() ? mFramebuffer->readDepth(gl::RowOrder::BottomUp) : std::vector<float>();
    const auto framebufferWidth = static_cast<std::size_t>(mFramebuffer->width());
    for (int row = 0; row < tile.height; ++row) {
        // The image's rows run from the top.
        const int imageRow = image.height() - 1 - (tile.y + row);
        for (int column = 0; column < tile.width; ++column) {
            const std::size_t texel = static_cast<std::size_t>(row) * framebufferWidth +
                                      static_cast<std::size_t>(column);
            image.setPixel(tile.x + column, imageRow, readLight(&rgba[4 * texel]));
            if (!depths.empty()) {
                image.setDepth(tile.x + column, imageRow, depths[texel]);
            }
        }
    }
    statistics.addTime(sg::RenderPhase::ReadBack, secondsSince(start));
}

} // namespace texsplat::render
