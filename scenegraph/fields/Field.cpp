#include "scenegraph/fields/Field.h"

#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/FieldValueWriter.h"

#include <algorithm>
#include <unordered_set>

namespace texsplat::sg {

namespace {

// One-line text form for messages and tests: `v`, `[ v, v ]`; nodes by type name.
class LineWriter final : public FieldValueWriter {
public:
    void writeToken(std::string_view text) override {
        separate();
        mText += text;
    }
    void writeNode(const std::shared_ptr<Node>& node) override {
        separate();
        mText += node ? node->typeName() : std::string("NULL");
    }
    void beginList() override {
        mText += "[";
        mIsListStart = true;
        mIsInList = true;
    }
    void endList() override {
        mText += mIsListStart ? "]" : " ]";
        mIsInList = false;
    }
    const std::string& text() const { return mText; }

private:
    void separate() {
        if (mIsInList) {
            mText += mIsListStart ? " " : ", ";
        }
        mIsListStart = false;
    }

    std::string mText;
    bool mIsInList = false;
    bool mIsListStart = false;
};

void eraseOne(std::vector<Field*>& fields, Field* field) {
    auto found = std::find(fields.begin(), fields.end(), field);
    if (found != fields.end()) {
        fields.erase(found);
    }
}

} // namespace

Field::~Field() {
    disconnect();
    for (Field* target : mTargets) {
        target->mSourceField = nullptr;
    }
}

std::string Field::fullName() const {
    if (mContainer == nullptr) {
        return "<standalone>";
    }
    return mContainer->describe() + "." + mName;
}

std::string Field::valueText() const {
    LineWriter writer;
    writeValue(writer);
    return writer.text();
}

void Field::touch() { propagate(false); }

void Field::valueChanged() { propagate(!mIsReceiving); }

void Field::receive(const Field& source) {
    mIsReceiving = true;
    struct Done {
        bool& isReceiving;
        ~Done() { isReceiving = false; }
    } done{mIsReceiving};
    copyValueFrom(source);
}

void Field::propagate(bool clearDefault) {
    if (clearDefault) {
        mIsDefault = false;
    }
    notifyObservers(this);
    // Index loop: a target may disconnect itself while being updated.
    for (std::size_t i = 0; i < mTargets.size(); ++i) {
        mTargets[i]->receive(*this);
    }
    if (mContainer != nullptr) {
        mContainer->notify(this);
    }
}

void Field::checkSameType(const Field& other) const {
    if (other.typeName() != typeName()) {
        throw DataError("cannot copy " + std::string(other.typeName()) + " " + other.fullName() +
                        " into " + std::string(typeName()) + " " + fullName());
    }
}

void Field::connectFrom(Field& source) {
    checkConnectable(source.typeName(), source.fullName(), &source, nullptr);
    disconnect();
    mSourceField = &source;
    source.mTargets.push_back(this);
    receive(source);
}

void Field::connectFrom(EngineOutputBase& output) {
    checkConnectable(output.typeName(), output.fullName(), nullptr, &output);
    std::shared_ptr<FieldContainer> engine = output.engine().shared_from_this();
    disconnect();
    mSourceOutput = &output;
    mSourceEngine = std::move(engine);
    output.mTargets.push_back(this);
    receive(output.valueField());
}

void Field::disconnect() {
    if (mSourceField != nullptr) {
        eraseOne(mSourceField->mTargets, this);
        mSourceField = nullptr;
    }
    if (mSourceOutput != nullptr) {
        eraseOne(mSourceOutput->mTargets, this);
        mSourceOutput = nullptr;
    }
    // Last: releasing the engine may destroy it and its outputs.
    std::shared_ptr<FieldContainer> engine = std::move(mSourceEngine);
}

void Field::checkConnectable(std::string_view sourceType, const std::string& sourceName,
                             const Field* sourceField,
                             const EngineOutputBase* sourceOutput) const {
    const std::string what = "cannot connect " + std::string(typeName()) + " " + fullName() +
                             " from " + std::string(sourceType) + " " + sourceName;
    if (sourceType != typeName()) {
        throw DataError(what + ": the types differ");
    }
    // Depth-first search upstream of the source (fields follow their source; an engine output
    // depends on all inputs of its engine). Reaching this field means a cycle.
    struct Step {
        const Field* field;
        const EngineOutputBase* output;
        std::size_t previous;
    };
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<Step> steps{{sourceField, sourceOutput, kNone}};
    std::vector<std::size_t> pending{0};
    std::unordered_set<const void*> visited{sourceField != nullptr
                                                ? static_cast<const void*>(sourceField)
                                                : static_cast<const void*>(sourceOutput)};
    auto visit = [&](const Field* field, const EngineOutputBase* output, std::size_t from) {
        const void* key = field != nullptr ? static_cast<const void*>(field)
                                           : static_cast<const void*>(output);
        if (key != nullptr && visited.insert(key).second) {
            steps.push_back({field, output, from});
            pending.push_back(steps.size() - 1);
        }
    };
    while (!pending.empty()) {
        const std::size_t index = pending.back();
        pending.pop_back();
        const Step step = steps[index];
        if (step.field == this) {
            // Names from the source down to the field that depends on this one.
            std::vector<std::string> names;
            for (std::size_t i = step.previous; i != kNone; i = steps[i].previous) {
                names.push_back(steps[i].field != nullptr ? steps[i].field->fullName()
                                                          : steps[i].output->fullName());
            }
            std::string chain = fullName();
            for (auto name = names.rbegin(); name != names.rend(); ++name) {
                chain += " <- " + *name;
            }
            throw DataError(what + ": connection cycle " + chain + " <- " + fullName());
        }
        if (step.field != nullptr) {
            visit(step.field->mSourceField, step.field->mSourceOutput, index);
        } else {
            for (const Field* input : step.output->engine().fields()) {
                visit(input, nullptr, index);
            }
        }
    }
}

} // namespace texsplat::sg
