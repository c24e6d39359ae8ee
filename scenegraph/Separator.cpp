#include "scenegraph/Separator.h"

#include "scenegraph/actions/Action.h"

namespace texsplat::sg {

Separator::Separator() {
    addField(renderCaching, "renderCaching", CacheEnabled::Auto, kCacheEnabledNames);
    addField(boundingBoxCaching, "boundingBoxCaching", CacheEnabled::Auto, kCacheEnabledNames);
    addField(renderCulling, "renderCulling", CacheEnabled::Auto, kCacheEnabledNames);
    addField(pickCulling, "pickCulling", CacheEnabled::Auto, kCacheEnabledNames);
}

void Separator::doAction(Action& action) {
    State& state = action.state();
    state.push();
    // Pop also when a child throws, so the action's state stays balanced.
    struct Pop {
        State& state;
        ~Pop() { state.pop(); }
    } pop{state};
    Group::doAction(action);
}

} // namespace texsplat::sg
