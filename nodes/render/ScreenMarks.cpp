#include "nodes/render/ScreenMarks.h"

#include "nodes/render/Frame.h"
#include "octree/Splat.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace texsplat::render {
namespace {

// What every mark of a batch shares.
struct MarkFrame {
    glm::mat4 localToClip;
    float halfWidth;  // of the image, pixels
    float halfHeight; // of the image, pixels
    // Pixels per local unit across the line of sight where clip w = 1 (at w, that over w).
    float pixelsPerUnit;
    float voxel;              // a voxel's size, local units: the spacing's geometric mean
    glm::vec3 inverseSpacing; // 1 / spacing
    bool isPerspective;
    glm::vec3 eye;       // local space (perspective)
    glm::vec3 direction; // local space, unit (orthographic)
    const MarkDrawing* drawing;
};

MarkFrame markFrame(const FrameSplats& batch, int width, int height) {
    const SplatView& view = batch.view;
    MarkFrame frame{};
    frame.localToClip = view.localToClip;
    frame.halfWidth = 0.5f * static_cast<float>(width);
    frame.halfHeight = 0.5f * static_cast<float>(height);
    // The camera's x and y axes in local space: moving along them changes clip x (y) and not w.
    const glm::mat4 cameraToLocal = glm::inverse(batch.localToCamera);
    const glm::vec3 right = glm::normalize(glm::vec3(cameraToLocal[0]));
    const glm::vec3 up = glm::normalize(glm::vec3(cameraToLocal[1]));
    const glm::vec4 clipRight = view.localToClip * glm::vec4(right, 0.0f);
    const glm::vec4 clipUp = view.localToClip * glm::vec4(up, 0.0f);
    frame.pixelsPerUnit =
        std::sqrt(std::abs(frame.halfWidth * clipRight.x) * std::abs(frame.halfHeight * clipUp.y));
    frame.voxel = std::cbrt(view.spacing.x * view.spacing.y * view.spacing.z);
    frame.inverseSpacing = 1.0f / view.spacing;
    frame.isPerspective = view.isPerspective;
    frame.eye = view.eye;
    frame.direction = view.direction;
    frame.drawing = &batch.marks;
    return frame;
}

// Where `local` lands: pixel x, y, z_ndc and clip w.
glm::vec4 toImage(const MarkFrame& frame, const glm::vec3& local) {
    const glm::vec4 clip = frame.localToClip * glm::vec4(local, 1.0f);
    const float inverseW = 1.0f / clip.w;
    return {frame.halfWidth * (clip.x * inverseW + 1.0f),
            frame.halfHeight * (1.0f - clip.y * inverseW), clip.z * inverseW, clip.w};
}

// The direction of `vector`, or zero for a vector with none (zero, or not finite): scaled by
// its largest component first, so that a huge one does not overflow and a tiny one not vanish.
glm::vec3 unitOf(const glm::vec3& vector) {
    const float largest = std::max({std::abs(vector.x), std::abs(vector.y), std::abs(vector.z)});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        return glm::vec3(0.0f);
    }
    return glm::normalize(vector / largest);
}

// The fade of a mark at `u` of its life cycle: in over the first kLifeFade, out over the last.
float lifeFade(float u) {
    constexpr float kFade = MarkDrawing::kLifeFade;
    return std::min({1.0f, u / kFade, (1.0f - u) / kFade});
}

ScreenMark screenMark(const MarkFrame& frame, const octree::SplatMark& emitted) {
    ScreenMark mark{};
    const MarkDrawing& drawing = *frame.drawing;
    const glm::vec3 unit = unitOf(emitted.vector);
    if (unit == glm::vec3(0.0f) || !(drawing.marksPerVoxel > 0.0) || !(emitted.extinction > 0.0f)) {
        return mark;
    }
    const float length = drawing.length * frame.voxel; // local units
    // The life cycle: the fraction of the phase first, so that a huge phase keeps its digits.
    const float cycle = emitted.phase + static_cast<float>(std::fmod(double(drawing.phase), 1.0));
    const float u = cycle - std::floor(cycle);
    const glm::vec3 travelled = emitted.position + (u - 0.5f) * length * unit;
    // The part of the mark inside the grid's box: a mark near the data's edge is cut there (its
    // head and tail kept, shorter), so that no mark draws beyond the data.
    float from = -0.5f;
    float to = 0.5f;
    for (int axis = 0; axis < 3; ++axis) {
        const float step = length * unit[axis];
        const float low = (drawing.dataLow[axis] - travelled[axis]);
        const float high = (drawing.dataHigh[axis] - travelled[axis]);
        if (step == 0.0f) {
            if (low > 0.0f || high < 0.0f) {
                return mark;
            }
            continue;
        }
        const float a = low / step;
        const float b = high / step;
        from = std::max(from, std::min(a, b));
        to = std::min(to, std::max(a, b));
    }
    if (!(from < to)) {
        return mark;
    }
    const glm::vec3 centre = travelled + 0.5f * (from + to) * length * unit;
    const float kept = to - from; // of the mark's length
    const glm::vec4 middle = toImage(frame, centre);
    const glm::vec4 tail = toImage(frame, centre - 0.5f * kept * length * unit);
    const glm::vec4 head = toImage(frame, centre + 0.5f * kept * length * unit);
    if (!(middle.w > 0.0f && tail.w > 0.0f && head.w > 0.0f) || !(std::abs(middle.z) <= 1.0f)) {
        return mark; // behind the eye, or outside the near and far planes
    }
    // Pixels per voxel at the mark, across the line of sight.
    const float pixels = frame.pixelsPerUnit * frame.voxel / middle.w;
    const float unforeshortened = 0.5f * kept * drawing.length * pixels;
    const glm::vec2 along(head.x - tail.x, head.y - tail.y);
    const float projected = 0.5f * glm::length(along);
    const float foreshortening =
        unforeshortened > 0.0f ? std::min(projected / unforeshortened, 1.0f) : 0.0f;
    const MarkSize size(drawing, pixels, kept * foreshortening);
    mark.halfLength = size.halfLength;
    mark.halfWidth = size.halfWidth;
    mark.head = size.head;
    if (projected > 0.0f && std::isfinite(projected)) {
        mark.axis[0] = along.x / (2.0f * projected);
        mark.axis[1] = along.y / (2.0f * projected);
    } else {
        mark.axis[0] = 1.0f; // straight at the eye: a round dot, any axis
    }
    mark.centre[0] = middle.x;
    mark.centre[1] = middle.y;
    mark.depth = middle.z;
    // The voxel's optical depth through its cell over the cell's area on screen, spread over the
    // area of its expected marks (and their mean fade).
    const glm::vec3 sight =
        frame.isPerspective ? glm::normalize(centre - frame.eye) : frame.direction;
    const float voxelDepth = 1.0f / glm::length(sight * frame.inverseSpacing);
    // The whole mark's area: the part cut off at the data's edge keeps its share.
    const MarkSize whole(drawing, pixels, foreshortening);
    const float area =
        whole.halfLength * whole.halfWidth * markProfileArea(drawing.type, whole.head);
    const double opticalDepth = double(emitted.extinction) * voxelDepth * pixels * pixels /
                                (drawing.marksPerVoxel * area * (1.0 - MarkDrawing::kLifeFade));
    const double alpha = -std::expm1(-opticalDepth * lifeFade(u));
    mark.alpha = static_cast<float>(drawing.isCombined ? alpha * drawing.contrast : alpha);
    if (drawing.isCombined) {
        const glm::vec3 color =
            drawing.textureOperator == MarkOperator::Blend ? drawing.blendColor : glm::vec3(0.0f);
        mark.color[0] = color.r;
        mark.color[1] = color.g;
        mark.color[2] = color.b;
    } else {
        mark.color[0] = emitted.color.r;
        mark.color[1] = emitted.color.g;
        mark.color[2] = emitted.color.b;
    }
    if (!std::isfinite(mark.alpha) || !std::isfinite(mark.centre[0]) ||
        !std::isfinite(mark.centre[1]) || !std::isfinite(mark.halfLength)) {
        return ScreenMark{};
    }
    return mark;
}

} // namespace

MarkSize::MarkSize(const MarkDrawing& drawing, float pixels, float foreshortening) {
    halfWidth = std::max(0.5f * drawing.width * pixels, MarkDrawing::kMinHalfWidthPixels);
    const float unforeshortened = 0.5f * drawing.length * pixels;
    halfLength = std::max(
        std::max(unforeshortened, MarkDrawing::kMinHalfLengthPixels) * foreshortening, halfWidth);
    head = std::min(std::max(MarkDrawing::kHeadPixels, halfWidth) / halfLength, 1.0f);
}

float markArea(const MarkDrawing& drawing, float pixels) {
    const MarkSize size(drawing, pixels, 1.0f);
    return size.halfLength * size.halfWidth * markProfileArea(drawing.type, size.head) /
           (pixels * pixels);
}

float pixelsPerVoxel(const FrameSplats& batch, int width, int height, const glm::vec3& local) {
    const MarkFrame frame = markFrame(batch, width, height);
    const glm::vec4 clip = frame.localToClip * glm::vec4(local, 1.0f);
    return frame.pixelsPerUnit * frame.voxel / clip.w;
}

float markProfileArea(MarkType type, float head) {
    if (type == MarkType::Scratches) {
        return 16.0f / 15.0f; // the ramp's area is 1 for any head; (1 − t²)² gives 16/15
    }
    // Particles: ∫ ramp(s) ∫ max(0, τ − t²)² dt ds, and ∫ … dt = (16/15) τ^(5/2). With
    // y = (s + 1)/2 (ds = 2 dy), τ = a + c·y (c = 1 − a) and Y = 1 − h/2, the ramp rises as y/Y
    // to Y, then falls as (1 − y)/(1 − Y); in w = τ both pieces integrate in closed form.
    const double a = MarkDrawing::kParticleTail;
    const double c = 1.0 - a;
    const double y = 1.0 - 0.5 * double(head);
    const auto rising = [&](double w) { // ∫ y τ^(5/2) dy
        return (std::pow(w, 4.5) / 4.5 - a * std::pow(w, 3.5) / 3.5) / (c * c);
    };
    const auto falling = [&](double w) { // ∫ (1 − y) τ^(5/2) dy
        return (std::pow(w, 3.5) / 3.5 - std::pow(w, 4.5) / 4.5) / (c * c);
    };
    const double w = a + c * y;
    const double area = (rising(w) - rising(a)) / y + (falling(1.0) - falling(w)) / (1.0 - y);
    return static_cast<float>(2.0 * area * 16.0 / 15.0);
}

void makeScreenMarks(const FrameSplats& batch, int width, int height,
                     std::vector<ScreenMark>& marks) {
    const octree::SplatList& list = *batch.splats;
    marks.resize(list.marks().size());
    if (marks.empty()) {
        return;
    }
    const MarkFrame frame = markFrame(batch, width, height);
    const octree::SplatMark* emitted = list.marks().data();
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, marks.size(), 4096), [&](const Range& range) {
        for (std::size_t m = range.begin(); m < range.end(); ++m) {
            marks[m] = screenMark(frame, emitted[m]);
        }
    });
}

} // namespace texsplat::render
