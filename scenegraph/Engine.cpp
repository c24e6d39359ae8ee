#include "scenegraph/Engine.h"

#include "scenegraph/Assert.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/detail/FieldDescriptions.h"

namespace texsplat::sg {

const NodeType& Engine::classType() {
    static const NodeType type("Engine", &FieldContainer::classType(), nullptr);
    return type;
}

EngineOutputBase* Engine::findOutput(std::string_view name) const {
    for (EngineOutputBase* output : mOutputs) {
        if (output->name() == name) {
            return output;
        }
    }
    return nullptr;
}

void Engine::evaluateIfNeeded() {
    // Guarded: an output feeding an observer that reads this engine again must not recurse.
    if (!mIsDirty || mIsEvaluating) {
        return;
    }
    mIsDirty = false;
    mIsEvaluating = true;
    struct Done {
        bool& isEvaluating;
        ~Done() { isEvaluating = false; }
    } done{mIsEvaluating};
    evaluate();
}

void Engine::notify(const Field* source) {
    FieldContainer::notify(source);
    mIsDirty = true;
    for (EngineOutputBase* output : mOutputs) {
        if (!output->connectedFields().empty()) {
            evaluateIfNeeded();
            return;
        }
    }
}

void Engine::addOutput(EngineOutputBase& output, std::string name, const char* description) {
    TEXSPLAT_ASSERT(output.mEngine == nullptr, "Engine::addOutput(): output added twice");
    TEXSPLAT_ASSERT(this->findOutput(name) == nullptr, "Engine::addOutput(): duplicate name");
    detail::recordFieldDescription(*this, name, description);
    output.mEngine = this;
    output.mName = std::move(name);
    mOutputs.push_back(&output);
}

} // namespace texsplat::sg
