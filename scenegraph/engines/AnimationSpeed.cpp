#include "scenegraph/engines/AnimationSpeed.h"

#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/fields/ValueFormat.h"
#include "scenegraph/io/detail/ContainerGraph.h"

#include <cmath>
#include <unordered_set>

namespace texsplat::sg {

AnimationSpeed::AnimationSpeed(Node& root) {
    // The same walk as connectTimeInputs(): graph order, so the engines are set in the same
    // order in every run.
    std::unordered_set<const FieldContainer*> seen{&root};
    std::vector<FieldContainer*> pending{&root};
    while (!pending.empty()) {
        FieldContainer& container = *pending.back();
        pending.pop_back();
        if (container.type().isDerivedFrom(ElapsedTime::classType())) {
            auto engine = std::static_pointer_cast<ElapsedTime>(container.shared_from_this());
            if (!engine->speed.isConnected()) {
                mEngines.push_back({engine, engine->speed.value()});
            }
        }
        detail::forEachReference(container, [&](FieldContainer& referenced) {
            if (seen.insert(&referenced).second) {
                pending.push_back(&referenced);
            }
        });
    }
}

void AnimationSpeed::setFactor(float factor) {
    if (!std::isfinite(factor)) {
        throw DataError("AnimationSpeed: the speed factor must be finite, got " +
                        formatFloat(factor));
    }
    mFactor = factor;
    apply();
}

void AnimationSpeed::setPaused(bool paused) {
    mIsPaused = paused;
    apply();
}

void AnimationSpeed::apply() {
    for (const Controlled& controlled : mEngines) {
        const float speed = mIsPaused ? 0.0f : mFactor * controlled.ownSpeed;
        // Setting an equal value would still notify the engine and the scene (a redraw).
        if (controlled.engine->speed.value() != speed) {
            controlled.engine->speed.setValue(speed);
        }
    }
}

} // namespace texsplat::sg
