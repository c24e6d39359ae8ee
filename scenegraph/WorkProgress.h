#pragma once

#include "scenegraph/Error.h"

#include <functional>
#include <string_view>

namespace texsplat::sg {

/// @brief Told now and then how a long step of a frame goes (classifying a grid, building its
/// octree): the step and the fraction done (0 to 1). Answering false cancels the step, which then
/// throws Cancelled; what it made so far is dropped, and the next frame starts it again.
/// Applications set one on an action (Action::setWorkProgress()): `texsplat render` draws a
/// progress bar on a terminal, the viewer lets Escape cancel.
using WorkProgress = std::function<bool(std::string_view step, double fraction)>;

/// @brief Thrown when a WorkProgress cancelled a step; the message names the step.
class Cancelled : public Error {
public:
    using Error::Error;
};

/// @brief Tells `progress` (when set) that `step` is `fraction` done, and throws
/// Cancelled("<step>: cancelled") when it answers false.
void reportWork(const WorkProgress& progress, std::string_view step, double fraction);

} // namespace texsplat::sg
