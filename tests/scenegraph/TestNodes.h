#pragma once

// Minimal node, engine and observer types for the scene-graph tests.

#include "scenegraph/Declare.h"
#include "scenegraph/Engine.h"
#include "scenegraph/Error.h"
#include "scenegraph/EngineOutput.h"
#include "scenegraph/Node.h"
#include "scenegraph/Observer.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/BoundingBoxAction.h"
#include "scenegraph/actions/ModelMatrixElement.h"
#include "scenegraph/fields/Fields.h"

#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

namespace texsplat::sg::test {

/// A cube of edge `size` centred at the origin.
class TestCube : public Declare<TestCube, Node> {
public:
    static constexpr const char* kTypeName = "TestCube";
    SFFloat size;

    void getBoundingBox(BoundingBoxAction& action) override {
        const glm::vec3 half(0.5f * size.value());
        action.extendBy(Box3(-half, half));
    }

protected:
    TestCube() { addField(size, "size", 2.0f, "Edge length"); }
};

/// A Transform-like node: translates what follows it.
class TestTranslation : public Declare<TestTranslation, Node> {
public:
    static constexpr const char* kTypeName = "TestTranslation";
    SFVec3f translation;

    void doAction(Action& action) override {
        glm::mat4& matrix = action.state().modify<ModelMatrixElement>().matrix;
        matrix = glm::translate(matrix, translation.value());
    }

protected:
    TestTranslation() {
        addField(translation, "translation", glm::vec3(0.0f), "Offset of what follows");
    }
};

/// An engine: output = 2 * input; counts its evaluations.
class TestDoubler : public Declare<TestDoubler, Engine> {
public:
    static constexpr const char* kTypeName = "TestDoubler";
    SFFloat input;
    EngineOutput<SFFloat> output;
    int evaluations = 0;

protected:
    TestDoubler() {
        addField(input, "input", 1.0f, "The number to double");
        addOutput(output, "output", "Twice input");
    }
    void evaluate() override {
        ++evaluations;
        output.setValue(2.0f * input.value());
    }
};

/// Records the notifications it receives.
class RecordingObserver final : public Observer {
public:
    void changed(Notifier& subject, const Field* source) override {
        subjects.push_back(&subject);
        sources.push_back(source);
    }
    void subjectDestroyed(Notifier& subject) override { destroyed.push_back(&subject); }

    std::vector<Notifier*> subjects;
    std::vector<const Field*> sources;
    std::vector<Notifier*> destroyed;
};

/// The message of the DataError that `target.connectFrom(source)` throws, or "no error".
inline std::string connectError(Field& target, Field& source) {
    try {
        target.connectFrom(source);
    } catch (const DataError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace texsplat::sg::test
