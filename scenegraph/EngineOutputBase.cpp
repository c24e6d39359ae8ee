#include "scenegraph/EngineOutputBase.h"

#include "scenegraph/Engine.h"
#include "scenegraph/fields/Field.h"

namespace texsplat::sg {

EngineOutputBase::~EngineOutputBase() {
    for (Field* target : mTargets) {
        target->mConnections->sourceOutput = nullptr;
    }
}

std::string EngineOutputBase::fullName() const {
    return (mEngine != nullptr ? mEngine->describe() : std::string()) + "." + mName;
}

const Field& EngineOutputBase::valueField() {
    if (mEngine != nullptr) {
        mEngine->evaluateIfNeeded();
    }
    return storage();
}

void EngineOutputBase::push() {
    Field& value = storage();
    // Index loop: a target may disconnect itself while being updated.
    for (std::size_t i = 0; i < mTargets.size(); ++i) {
        mTargets[i]->receive(value);
    }
}

} // namespace texsplat::sg
