#include "nodes/annotation/VolumeOutline.h"

#include "nodes/ScalarSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace texsplat::annotation {
namespace {

// The edges of a box between its corners (sg::Box3::corner()).
constexpr std::array<std::pair<int, int>, 12> kEdges = {{{0, 1},
                                                         {2, 3},
                                                         {4, 5},
                                                         {6, 7},
                                                         {0, 2},
                                                         {1, 3},
                                                         {4, 6},
                                                         {5, 7},
                                                         {0, 4},
                                                         {1, 5},
                                                         {2, 6},
                                                         {3, 7}}};

// Collects, per splat node with a volume, its box's corners in clip space.
class OutlineAction : public sg::Action {
public:
    explicit OutlineAction(float aspectRatio) : sg::Action(methods()), mAspect(aspectRatio) {}

    // A box's corners in clip space, and which of its faces face the camera: face 2·axis is
    // the one at the box's minimum along that axis, 2·axis + 1 at its maximum.
    struct Box {
        std::array<glm::vec4, 8> corners;
        std::array<bool, 6> facesCamera;
    };
    std::vector<Box> boxes;

private:
    static sg::MethodTable& methods() {
        static sg::MethodTable table = [] {
            sg::MethodTable initial;
            initial.add(nodes::ScalarSplat::classType(), &collectBox);
            return initial;
        }();
        return table;
    }

    static void collectBox(sg::Action& action, sg::Node& node) {
        auto& outline = static_cast<OutlineAction&>(action);
        const nodes::VolumeData* volume = action.state().get<nodes::VolumeElement>().volume;
        if (volume == nullptr) {
            return; // the splat node draws nothing
        }
        const sg::Box3 box = volume->bounds();
        if (box.isEmpty()) {
            return;
        }
        const render::CameraView camera =
            render::CameraView::current(action.state(), node, outline.mAspect);
        const glm::mat4 toCamera =
            camera.view * action.state().get<sg::ModelMatrixElement>().matrix;
        const glm::mat4 toClip = camera.projection * toCamera;
        Box result;
        for (int corner = 0; corner < 8; ++corner) {
            result.corners[corner] = toClip * glm::vec4(box.corner(corner), 1.0f);
        }
        // The eye in the box's space, homogeneous: a point for a perspective camera, the
        // direction towards the viewer (w = 0) for an orthographic one.
        const bool isPerspective = camera.projection[3][3] == 0.0f;
        const glm::vec4 eye = glm::inverse(toCamera) * (isPerspective ? glm::vec4(0, 0, 0, 1)
                                                                        : glm::vec4(0, 0, 1, 0));
        for (int axis = 0; axis < 3; ++axis) {
            // The eye is outside the face's plane, on the side its outward normal points to.
            result.facesCamera[2 * axis] = box.min()[axis] * eye.w - eye[axis] > 0.0f;
            result.facesCamera[2 * axis + 1] = eye[axis] - box.max()[axis] * eye.w > 0.0f;
        }
        outline.boxes.push_back(result);
    }

    float mAspect;
};

// The part of the clip-space segment a–b inside the view volume (-w <= x, y, z <= w), as
// parameters [t0, t1] along it; empty (t0 > t1) when none is.
std::pair<float, float> insideViewVolume(const glm::vec4& a, const glm::vec4& b) {
    float t0 = 0.0f;
    float t1 = 1.0f;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {1.0f, -1.0f}) {
            // Distance inside the plane sign * coordinate <= w.
            const float da = a.w - sign * a[axis];
            const float db = b.w - sign * b[axis];
            if (da < 0.0f && db < 0.0f) {
                return {1.0f, 0.0f};
            }
            if (da < 0.0f) {
                t0 = std::max(t0, da / (da - db));
            } else if (db < 0.0f) {
                t1 = std::min(t1, da / (da - db));
            }
        }
    }
    return {t0, t1};
}

} // namespace

VolumeOutline VolumeOutline::ofScene(sg::Node& root, int width, int height,
                                     const glm::vec4& rgba) {
    OutlineAction action(static_cast<float>(width) / static_cast<float>(height));
    action.apply(root);
    VolumeOutline outline;
    outline.mColor = rgba;
    const glm::vec2 size(width, height);
    const auto toPixels = [&](const glm::vec4& clip) {
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return glm::vec2(0.5f * (ndc.x + 1.0f), 0.5f * (1.0f - ndc.y)) * size;
    };
    for (const OutlineAction::Box& box : action.boxes) {
        for (const auto& [from, to] : kEdges) {
            const glm::vec4& a = box.corners[from];
            const glm::vec4& b = box.corners[to];
            const auto [t0, t1] = insideViewVolume(a, b);
            if (t0 > t1) {
                continue;
            }
            // The edge runs along the axis in which its corners differ; its two faces are the
            // sides of the other two axes that its corners share.
            bool isBehind = true;
            for (int axis = 0; axis < 3; ++axis) {
                const int bit = 1 << axis;
                if ((from & bit) == (to & bit)) {
                    isBehind = isBehind && !box.facesCamera[2 * axis + ((from & bit) ? 1 : 0)];
                }
            }
            outline.mSegments.push_back(
                {toPixels(glm::mix(a, b, t0)), toPixels(glm::mix(a, b, t1)), isBehind});
        }
    }
    return outline;
}

void VolumeOutline::draw(image::Image& image, Edges which) const {
    const int width = std::max(1, std::min(image.width(), image.height()) / 256);
    // The `width` × `width` pixels whose centres lie nearest to points one pixel apart along
    // the line's longer axis.
    const auto plot = [&](glm::vec2 centre) {
        const glm::ivec2 low(glm::round(centre - 0.5f - 0.5f * float(width - 1)));
        for (int y = low.y; y < low.y + width; ++y) {
            for (int x = low.x; x < low.x + width; ++x) {
                if (x >= 0 && y >= 0 && x < image.width() && y < image.height()) {
                    image.setPixel(x, y, mColor);
                }
            }
        }
    };
    for (const Segment& segment : mSegments) {
        if ((which == Edges::InFront && segment.isBehind) ||
            (which == Edges::Behind && !segment.isBehind)) {
            continue;
        }
        const glm::vec2 delta = segment.to - segment.from;
        const int steps =
            static_cast<int>(std::ceil(std::max(std::abs(delta.x), std::abs(delta.y))));
        for (int step = 0; step <= steps; ++step) {
            plot(segment.from + delta * (steps == 0 ? 0.0f : float(step) / float(steps)));
        }
    }
}

} // namespace texsplat::annotation
