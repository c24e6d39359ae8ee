/// @file
/// @brief Embedding the texsplat scene graph in an application, start to end: declare and
/// register an application node type, build a small animated graph in code, write it as an
/// Inventor file, read it back, and run it on a simulated clock with a TimerSensor, so that
/// every run prints the same frames.
///
/// Usage: `texsplat_example_embedding <scene.iv>` (the file is written, then read back).
/// Built by CMake and run by ctest (see examples/CMakeLists.txt); docs/sensors.md walks
/// through it.

#include "scenegraph/Declare.h"
#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/Separator.h"
#include "scenegraph/actions/Path.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/engines/ElapsedTime.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/engines/TimeInputs.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "scenegraph/sensors/NodeSensor.h"
#include "scenegraph/sensors/SensorQueue.h"
#include "scenegraph/sensors/SimulatedClock.h"
#include "scenegraph/sensors/TimerSensor.h"

#include <iostream>
#include <string>

namespace sg = texsplat::sg;

namespace {

/// An application-defined node. Declared once (type name and fields), registered once, it is
/// read and written exactly like a built-in node.
class Pulse : public sg::Declare<Pulse, sg::Node> {
public:
    static constexpr const char* kTypeName = "Pulse";
    sg::SFFloat radius;

protected:
    Pulse() { addField(radius, "radius", 1.0f, "Radius of the pulse, world units"); }
};

/// Separator { DEF pulse Pulse { radius = ElapsedTime { speed 2 } . timeOut } }
sg::Node::Ptr buildScene() {
    auto pulse = Pulse::create();
    pulse->setName("pulse");
    auto elapsed = sg::ElapsedTime::create();
    elapsed->speed = 2.0f;
    pulse->radius.connectFrom(elapsed->timeOut); // the field now keeps the engine alive
    auto root = sg::Separator::create();
    root->addChild(pulse);
    return root;
}

/// The node named `name` below `root`; throws DataError when there is none.
Pulse& findPulse(sg::Node& root, const std::string& name) {
    sg::SearchAction search;
    search.setName(name);
    search.setType(Pulse::classType());
    search.apply(root);
    if (search.paths().empty()) {
        throw texsplat::DataError("no Pulse named '" + name + "' in the scene");
    }
    return static_cast<Pulse&>(*search.paths().front().tail());
}

void run(const std::string& path) {
    // Registration: the built-in engines, then the application's own types.
    sg::registerEngineTypes(sg::NodeRegistry::instance());
    sg::NodeRegistry::instance().add<Pulse>();

    // Write the graph built in code (atomically: a temporary file renamed over `path`), read
    // it back, and check that writing the copy gives the same text.
    const sg::Node::Ptr built = buildScene();
    sg::WriteAction::writeFile(*built, path);
    const sg::Node::Ptr scene = sg::SceneReader::readFile(path);
    const std::string text = sg::WriteAction::writeString(*scene);
    std::cout << "wrote and read back " << path << ":\n" << text;
    std::cout << "round trip: " << (text == sg::WriteAction::writeString(*built) ? "identical"
                                                                                 : "DIFFERENT")
              << "\n";

    // Time: no global clock. The queue runs on a simulated clock, and the scene's engines take
    // their time from the queue (Inventor would connect them to its global realTime field).
    sg::SimulatedClock clock;
    sg::SensorQueue queue(clock);
    std::cout << "engines on the queue's time: "
              << sg::connectTimeInputs(*scene, queue.timeField()) << "\n";

    Pulse& pulse = findPulse(*scene, "pulse");
    // A timer every 0.25 s: its triggers stay on the grid 0.25, 0.5, ... whatever the frame rate.
    sg::TimerSensor timer(queue);
    timer.setInterval(0.25);
    timer.setCallback([&] {
        std::cout << "timer at " << timer.lastTriggerTime() << " s (frame time " << queue.time()
                  << " s): radius " << pulse.radius.value() << "\n";
    });
    timer.schedule();
    // What a viewer does to redraw: one callback per processing, however many changes.
    int redraws = 0;
    sg::NodeSensor redraw(queue, [&] { ++redraws; });
    redraw.attach(*scene);

    // Batch rendering: one second at 30 frames per second. setTime(frame / fps) rather than
    // advance(1 / fps): the frame times are then exact, not sums of rounded steps.
    constexpr int kFrames = 30;
    for (int frame = 1; frame <= kFrames; ++frame) {
        clock.setTime(frame / 30.0);
        queue.process();
        // ... render the frame here ...
    }
    std::cout << "frames: " << kFrames << ", redraws: " << redraws << ", final radius "
              << pulse.radius.value() << "\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: " << argv[0] << " <scene.iv>\n";
        return 2;
    }
    try {
        run(argv[1]);
    } catch (const texsplat::Error& error) {
        std::cerr << "embedding: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
