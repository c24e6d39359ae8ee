#include "scenegraph/Notifier.h"

#include "TestNodes.h"

#include <gtest/gtest.h>

namespace texsplat::sg {
namespace {

// Removes itself (and optionally another observer) when notified.
class SelfRemover final : public Observer {
public:
    void changed(Notifier& subject, const Field* /*source*/) override {
        ++calls;
        subject.removeObserver(*this);
        if (other != nullptr) {
            subject.removeObserver(*other);
        }
    }
    void subjectDestroyed(Notifier& /*subject*/) override {}
    Observer* other = nullptr;
    int calls = 0;
};

TEST(Notifier, observersMayRemoveThemselvesAndOthersWhileNotified) {
    test::TestCube::Ptr cube = test::TestCube::create();
    SelfRemover first;
    test::RecordingObserver second;
    first.other = &second;
    cube->size.addObserver(first);
    cube->size.addObserver(second);
    EXPECT_EQ(cube->size.observerCount(), 2u);
    cube->size = 1.0f;
    EXPECT_EQ(first.calls, 1);
    EXPECT_TRUE(second.subjects.empty());
    EXPECT_EQ(cube->size.observerCount(), 0u);
    cube->size = 2.0f;
    EXPECT_EQ(first.calls, 1);
}

TEST(Notifier, removingAnUnknownObserverIsIgnored) {
    test::TestCube::Ptr cube = test::TestCube::create();
    test::RecordingObserver observer;
    cube->removeObserver(observer);
    cube->addObserver(observer);
    cube->addObserver(observer);
    cube->size = 1.0f;
    EXPECT_EQ(observer.subjects.size(), 2u);
    cube->removeObserver(observer);
    EXPECT_EQ(cube->observerCount(), 1u);
    cube->removeObserver(observer);
}

} // namespace
} // namespace texsplat::sg
