#include "nodes/actions/SplatInputs.h"

#include "nodes/ScalarSplat.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "nodes/elements/VolumeElement.h"
#include "scenegraph/actions/Action.h"

#include <utility>

namespace texsplat::nodes {
namespace {

// Records the inputs at each splat node; the other nodes do what they do for any action: put
// themselves into the state.
class SplatInputsAction : public sg::Action {
public:
    SplatInputsAction() : Action(methods()) {}

    std::vector<SplatInput> inputs;

private:
    static sg::MethodTable& methods() {
        static sg::MethodTable table = [] {
            sg::MethodTable initial;
            initial.add(ScalarSplat::classType(), [](sg::Action& action, sg::Node& node) {
                auto& self = static_cast<SplatInputsAction&>(action);
                const SplatInput input{
                    self.state().get<TransferFunctionElement>().transferFunction,
                    self.state().get<VolumeElement>().volume,
                    static_cast<const ScalarSplat*>(&node)};
                if (input.transfer != nullptr && input.volume != nullptr) {
                    self.inputs.push_back(input);
                }
            });
            return initial;
        }();
        return table;
    }
};

} // namespace

std::vector<SplatInput> splatInputs(sg::Node& root) {
    SplatInputsAction action;
    action.apply(root);
    return std::move(action.inputs);
}

} // namespace texsplat::nodes
