#include "scenegraph/Separator.h"

#include "scenegraph/actions/Action.h"

namespace texsplat::sg {

Separator::Separator() {
    addField(renderCaching, "renderCaching", CacheEnabled::Auto, kCacheEnabledNames,
             "Inventor's render-cache hint; read and written back, not used by texsplat");
    addField(boundingBoxCaching, "boundingBoxCaching", CacheEnabled::Auto, kCacheEnabledNames,
             "Inventor's bounding-box-cache hint; read and written back, not used by texsplat");
    addField(renderCulling, "renderCulling", CacheEnabled::Auto, kCacheEnabledNames,
             "Inventor's view-frustum culling hint; read and written back, not used by texsplat");
    addField(pickCulling, "pickCulling", CacheEnabled::Auto, kCacheEnabledNames,
             "Inventor's pick-culling hint; read and written back, not used by texsplat");
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
