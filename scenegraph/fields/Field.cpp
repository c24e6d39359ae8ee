#include "scenegraph/fields/Field.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/Node.h"
#include "scenegraph/detail/FieldNames.h"
#include "scenegraph/fields/FieldValueWriter.h"

#include <algorithm>
#include <unordered_map>

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

// One element of a connection chain: a field or an engine output.
struct ChainLink {
    const Field* field;
    const EngineOutputBase* output;

    const void* key() const {
        return field != nullptr ? static_cast<const void*>(field)
                                : static_cast<const void*>(output);
    }
    std::string fullName() const {
        return field != nullptr ? field->fullName() : output->fullName();
    }
};

// The longest chain, in links, that leaves `start` through `next(link, neighbours)`, which appends
// the links one step further. Each link is visited once and no recursion is used, so the cost is
// the size of the region reached. Reaching `stop` calls `onStop(path)` (which must throw) with the
// links from `start` to the one that leads to `stop`; otherwise the region must be acyclic.
template <class Next, class OnStop>
std::size_t longestChain(ChainLink start, const void* stop, const Next& next,
                         const OnStop& onStop) {
    struct Step {
        ChainLink link;
        std::vector<ChainLink> neighbours;
        std::size_t nextNeighbour = 0;
        std::size_t length = 0;
    };
    std::unordered_map<const void*, std::size_t> lengths;
    std::vector<Step> steps(1, Step{start, {}});
    next(start, steps.back().neighbours);
    std::vector<ChainLink> path;
    while (true) {
        Step& step = steps.back();
        if (step.nextNeighbour < step.neighbours.size()) {
            const ChainLink neighbour = step.neighbours[step.nextNeighbour++];
            if (neighbour.key() == stop) {
                path.clear();
                for (const Step& onPath : steps) {
                    path.push_back(onPath.link);
                }
                onStop(path);
            }
            if (const auto known = lengths.find(neighbour.key()); known != lengths.end()) {
                step.length = std::max(step.length, known->second + 1);
            } else {
                steps.push_back(Step{neighbour, {}});
                next(neighbour, steps.back().neighbours);
            }
            continue;
        }
        const std::size_t length = step.length;
        lengths.emplace(step.link.key(), length);
        steps.pop_back();
        if (steps.empty()) {
            return length;
        }
        steps.back().length = std::max(steps.back().length, length + 1);
    }
}

void eraseOne(std::vector<Field*>& fields, Field* field) {
    auto found = std::find(fields.begin(), fields.end(), field);
    if (found != fields.end()) {
        fields.erase(found);
    }
}

} // namespace

Field::~Field() {
    disconnect();
    for (Field* target : targets()) {
        target->mConnections->sourceField = nullptr;
    }
}

Field::Connections& Field::connections() {
    if (!mConnections) {
        mConnections = std::make_unique<Connections>();
    }
    return *mConnections;
}

const std::vector<Field*>& Field::targets() const {
    static const std::vector<Field*> none;
    return mConnections ? mConnections->targets : none;
}

std::string Field::fullName() const {
    if (mContainer == nullptr) {
        return "<standalone>";
    }
    return mContainer->describe() + "." + name();
}

const std::string& Field::name() const { return mName != nullptr ? *mName : detail::noName(); }

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
    if (!mIsNotifyEnabled) {
        return;
    }
    notifyObservers(this);
    // Index loop: a target may disconnect itself while being updated.
    const std::vector<Field*>& followers = targets();
    for (std::size_t i = 0; i < followers.size(); ++i) {
        followers[i]->receive(*this);
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
    connections().sourceField = &source;
    source.connections().targets.push_back(this);
    receive(source);
}

void Field::connectFrom(EngineOutputBase& output) {
    checkConnectable(output.typeName(), output.fullName(), nullptr, &output);
    std::shared_ptr<FieldContainer> engine = output.engine().shared_from_this();
    disconnect();
    Connections& connection = connections();
    connection.sourceOutput = &output;
    connection.sourceOwner = std::move(engine);
    output.mTargets.push_back(this);
    receive(output.valueField());
}

void Field::disconnect() {
    if (!mConnections) {
        return;
    }
    Connections& connection = *mConnections;
    if (connection.sourceField != nullptr) {
        eraseOne(connection.sourceField->mConnections->targets, this);
        connection.sourceField = nullptr;
    }
    if (connection.sourceOutput != nullptr) {
        eraseOne(connection.sourceOutput->mTargets, this);
        connection.sourceOutput = nullptr;
    }
    // Last: releasing the owner may destroy it and its fields or outputs.
    std::shared_ptr<FieldContainer> owner = std::move(connection.sourceOwner);
}

void Field::keepSourceAlive() {
    Field* source = connectedField();
    TEXSPLAT_ASSERT(source != nullptr && source->mContainer != nullptr,
                    "Field::keepSourceAlive(): not connected from a field of a container");
    mConnections->sourceOwner = source->mContainer->shared_from_this();
}

void Field::checkConnectable(std::string_view sourceType, const std::string& sourceName,
                             const Field* sourceField,
                             const EngineOutputBase* sourceOutput) const {
    const std::string what = "cannot connect " + std::string(typeName()) + " " + fullName() +
                             " from " + std::string(sourceType) + " " + sourceName;
    if (sourceType != typeName()) {
        throw DataError(what + ": the types differ");
    }
    if (sourceField == this) {
        throw DataError(what + ": connection cycle " + fullName() + " <- " + fullName());
    }
    // Reaching this field upstream of the source means the connection closes a cycle.
    const auto cycle = [&](const std::vector<ChainLink>& path) {
        std::string chain = fullName();
        for (const ChainLink& link : path) {
            chain += " <- " + link.fullName();
        }
        throw DataError(what + ": connection cycle " + chain + " <- " + fullName());
    };
    // Upstream a field follows its source alone: a plain list, walked without bookkeeping.
    std::vector<ChainLink> path{{sourceField, sourceOutput}};
    while (path.back().field != nullptr && path.back().field->isConnected()) {
        const Field& field = *path.back().field;
        if (field.connectedField() == this) {
            cycle(path);
        }
        path.push_back({field.connectedField(), field.connectedOutput()});
    }
    std::size_t above = path.size() - 1;
    if (const EngineOutputBase* output = path.back().output) {
        // An engine output follows all inputs of its engine: the chains branch from here.
        const auto upstream = [](const ChainLink& link, std::vector<ChainLink>& next) {
            if (link.field == nullptr) {
                for (const Field* input : link.output->engine().fields()) {
                    next.push_back({input, nullptr});
                }
            } else if (link.field->isConnected()) {
                next.push_back({link.field->connectedField(), link.field->connectedOutput()});
            }
        };
        path.pop_back();
        above += longestChain({nullptr, output}, this, upstream,
                              [&](const std::vector<ChainLink>& rest) {
                                  path.insert(path.end(), rest.begin(), rest.end());
                                  cycle(path);
                              });
    }
    // Downstream a field feeds its targets and, as an engine input, its engine's outputs.
    const auto downstream = [](const ChainLink& link, std::vector<ChainLink>& next) {
        const std::vector<Field*>& targets =
            link.field != nullptr ? link.field->targets() : link.output->connectedFields();
        for (const Field* target : targets) {
            next.push_back({target, nullptr});
        }
        const auto* engine =
            dynamic_cast<const Engine*>(link.field != nullptr ? link.field->mContainer : nullptr);
        if (engine != nullptr) {
            for (const EngineOutputBase* output : engine->outputs()) {
                next.push_back({nullptr, output});
            }
        }
    };
    // No cycle can be downstream (nothing to stop at): every connection so far was checked.
    const std::size_t below = longestChain({this, nullptr}, nullptr, downstream, cycle);
    if (above + 1 + below > kMaxConnectionChain) {
        throw DataError(what + ": connection chain longer than the limit of " +
                        std::to_string(kMaxConnectionChain) + " links");
    }
}

} // namespace texsplat::sg
