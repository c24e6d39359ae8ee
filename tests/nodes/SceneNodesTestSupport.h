#pragma once

// Helpers for the tests of the scene nodes (cameras, Transform, TransferFunction, ...).

#include "scenegraph/Declare.h"
#include "scenegraph/Node.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

namespace texsplat::nodes::test {

/// The message of the `Exception` that `function` throws, or "no such error".
template <typename Exception, typename Function> std::string errorOf(Function function) {
    try {
        function();
    } catch (const Exception& error) {
        return error.what();
    }
    return "no such error";
}

/// A file name in the test temp folder, unique per test.
inline std::string testPath(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return (std::filesystem::path(::testing::TempDir()) /
            (std::string("SceneNodes_") + info->test_suite_name() + "_" + info->name() + "_" +
             name))
        .string();
}

/// A leaf that hands the traversal state to a callback whenever an action visits it, so tests can
/// read the elements the nodes before it set.
class StateProbe : public sg::Declare<StateProbe, sg::Node> {
public:
    static constexpr const char* kTypeName = "TestStateProbe";
    std::function<void(sg::Action&)> visit;

    void doAction(sg::Action& action) override {
        if (visit) {
            visit(action);
        }
    }
};

} // namespace texsplat::nodes::test
