#include "nodes/distributed/SplatPlacements.h"

#include "nodes/ScalarSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "nodes/elements/VolumeElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/ModelMatrixElement.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/fields/SFNode.h"

#include <algorithm>
#include <mutex>

namespace texsplat::distributed {
namespace {

// Traverses a scene as a render does and notes each splat node's placement.
class PlacementAction : public sg::Action {
public:
    explicit PlacementAction(float aspect) : sg::Action(methods()), mAspect(aspect) {}

    static sg::MethodTable& methods() {
        static sg::MethodTable table;
        static std::once_flag once;
        std::call_once(once, [] {
            table.add(nodes::ScalarSplat::classType(), [](sg::Action& action, sg::Node& node) {
                static_cast<PlacementAction&>(action).place(static_cast<nodes::ScalarSplat&>(node));
            });
        });
        return table;
    }

    std::vector<SplatPlacement> placements;

private:
    void place(nodes::ScalarSplat& splat) {
        sg::State& state = this->state();
        const nodes::VolumeData* volume = state.get<nodes::VolumeElement>().volume;
        if (!volume) {
            throw DataError(nodes::detail::nodeContext(splat) + ": no VolumeData before this node");
        }
        if (!state.get<nodes::TransferFunctionElement>().transferFunction) {
            throw DataError(nodes::detail::nodeContext(splat) +
                            ": no TransferFunction before this node");
        }
        SplatPlacement placement;
        placement.splat = &splat;
        // The traversal holds the scene's nodes as const; the scene is the caller's.
        placement.volume = const_cast<nodes::VolumeData*>(volume);
        placement.model = state.get<sg::ModelMatrixElement>().matrix;
        placement.camera = render::CameraView::current(state, splat, mAspect);
        for (sg::Field* field : splat.fields()) {
            const auto* node = dynamic_cast<sg::SFNode*>(field);
            if (node) {
                if (auto* companion = dynamic_cast<nodes::VolumeData*>(node->value().get())) {
                    placement.companions.push_back(companion);
                }
            }
        }
        placements.push_back(std::move(placement));
    }

    float mAspect;
};

void addVolume(nodes::VolumeData* volume, std::vector<nodes::VolumeData*>& volumes) {
    if (std::find(volumes.begin(), volumes.end(), volume) == volumes.end()) {
        volumes.push_back(volume);
    }
}

} // namespace

std::vector<SplatPlacement> findSplatPlacements(sg::Node& root, float aspect) {
    PlacementAction action(aspect);
    action.apply(root);
    return std::move(action.placements);
}

std::vector<nodes::VolumeData*> findVolumes(sg::Node& root) {
    sg::SearchAction search;
    search.setType(nodes::VolumeData::classType());
    search.setInterest(sg::SearchAction::Interest::All);
    search.setSearchingAll(true);
    search.apply(root);
    std::vector<nodes::VolumeData*> volumes;
    for (const sg::Path& path : search.paths()) {
        addVolume(static_cast<nodes::VolumeData*>(path.tail().get()), volumes);
    }
    // Volumes held in fields (masks, colour data) are not children: the splat nodes name them.
    sg::SearchAction splats;
    splats.setType(nodes::ScalarSplat::classType());
    splats.setInterest(sg::SearchAction::Interest::All);
    splats.setSearchingAll(true);
    splats.apply(root);
    for (const sg::Path& path : splats.paths()) {
        for (sg::Field* field : path.tail()->fields()) {
            if (const auto* node = dynamic_cast<sg::SFNode*>(field)) {
                if (auto* volume = dynamic_cast<nodes::VolumeData*>(node->value().get())) {
                    addVolume(volume, volumes);
                }
            }
        }
    }
    return volumes;
}

} // namespace texsplat::distributed
