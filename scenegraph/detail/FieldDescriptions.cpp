#include "scenegraph/detail/FieldDescriptions.h"

#include "scenegraph/FieldContainer.h"
#include "scenegraph/NodeType.h"

#include <memory>
#include <utility>
#include <vector>

namespace texsplat::sg::detail {
namespace {

struct Description {
    const FieldContainer* container;
    std::string name;
    const char* text;
};

// The descriptions recorded while collectFieldDescriptions() makes an instance on this thread.
// Constructors of other containers (a node that makes a default child) record theirs too; they
// are told apart by container.
thread_local std::vector<Description>* tRecorded = nullptr;

// Points tRecorded at `recorded` for its lifetime, restoring the previous target (a constructor
// may ask for another type's descriptions).
class Recording {
public:
    explicit Recording(std::vector<Description>& recorded)
        : mPrevious(std::exchange(tRecorded, &recorded)) {}
    Recording(const Recording&) = delete;
    Recording& operator=(const Recording&) = delete;
    ~Recording() { tRecorded = mPrevious; }

private:
    std::vector<Description>* mPrevious;
};

} // namespace

std::map<std::string, std::string, std::less<>> collectFieldDescriptions(const NodeType& type) {
    std::map<std::string, std::string, std::less<>> descriptions;
    if (type.isAbstract()) {
        return descriptions;
    }
    std::vector<Description> recorded;
    std::shared_ptr<FieldContainer> instance;
    {
        const Recording recording(recorded);
        instance = type.create();
    }
    for (const Description& description : recorded) {
        if (description.container == instance.get()) {
            descriptions.emplace(description.name, description.text);
        }
    }
    return descriptions;
}

void recordFieldDescription(const FieldContainer& container, const std::string& name,
                            const char* description) {
    if (tRecorded != nullptr) {
        tRecorded->push_back({&container, name, description});
    }
}

} // namespace texsplat::sg::detail
