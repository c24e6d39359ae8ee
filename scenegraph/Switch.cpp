#include "scenegraph/Switch.h"

#include "scenegraph/actions/SearchAction.h"

namespace texsplat::sg {

Switch::Switch() {
    addField(whichChild, "whichChild", kNone,
             "Index of the one child to traverse (from 0); -1 traverses none, -3 all");
}

void Switch::doAction(Action& action) {
    const std::int32_t which = whichChild.value();
    if (which == kAll) {
        Group::doAction(action);
    } else if (which >= 0 && static_cast<std::size_t>(which) < childCount()) {
        traverseChild(action, static_cast<std::size_t>(which));
    }
}

void Switch::search(SearchAction& action) {
    action.checkCurrent(*this);
    if (action.hasTerminated()) {
        return;
    }
    if (action.isSearchingAll()) {
        Group::doAction(action);
    } else {
        doAction(action);
    }
}

} // namespace texsplat::sg
