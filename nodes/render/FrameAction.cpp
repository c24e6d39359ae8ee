#include "nodes/render/FrameAction.h"

#include "scenegraph/Error.h"

#include <string>

namespace texsplat::render {

FrameAction::FrameAction(int width, int height, const glm::vec4& background)
    : sg::Action(methods()) {
    if (width < 1 || height < 1) {
        throw DataError("frame: size " + std::to_string(width) + "x" + std::to_string(height) +
                        " must be at least 1x1");
    }
    mFrame.width = width;
    mFrame.height = height;
    mFrame.background = background;
}

sg::MethodTable& FrameAction::methods() {
    static sg::MethodTable table;
    return table;
}

const Frame& FrameAction::collect(sg::Node& root) {
    mStatistics = sg::RenderStatistics();
    apply(root);
    return mFrame;
}

float FrameAction::aspectRatio() const {
    return static_cast<float>(mFrame.width) / static_cast<float>(mFrame.height);
}

void FrameAction::beginTraversal(sg::Node& /*root*/) {
    mFrame.meshes.clear();
    mFrame.splats.clear();
}

} // namespace texsplat::render
