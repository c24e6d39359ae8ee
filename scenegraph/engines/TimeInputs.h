#pragma once

#include "scenegraph/Fwd.h"
#include "scenegraph/fields/Fields.h"

#include <cstddef>

namespace texsplat::sg {

/// @brief Connects the `timeIn` input of every engine reachable from `root` that has no
/// incoming connection to `time` (normally `SensorQueue::timeField()`); returns how many.
///
/// Inventor engines that follow time (ElapsedTime; later TimeCounter, OneShot) connect their
/// `timeIn` to the global `realTime` field when they are made. texsplat has no global clock, so
/// after reading a scene the application hands its engines the queue's time with one call:
/// @code
/// auto root = sg::SceneReader::readFile("animated.iv");
/// sg::connectTimeInputs(*root, queue.timeField());
/// @endcode
/// Engines are found through the graph as the writer sees it: children, node fields and
/// connections. An input already connected (to another engine, another clock) is left alone.
std::size_t connectTimeInputs(Node& root, SFFloat& time);

} // namespace texsplat::sg
