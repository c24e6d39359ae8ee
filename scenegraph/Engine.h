#pragma once

#include "scenegraph/FieldContainer.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief Base of engines: objects whose input fields compute typed outputs that feed fields
/// (Inventor's `size = ElapsedTime { speed 2 } . timeOut`).
///
/// A concrete engine derives from `Declare<MyEngine, Engine>`, registers inputs with
/// `addField()` and outputs with `addOutput()` in its constructor, and implements
/// `evaluate()`, which sets every output from the inputs. Evaluation is lazy: a changed input
/// marks the engine dirty and, if some output is connected, evaluates at once so the connected
/// fields (and their observers) see the new value; an unconnected engine evaluates when an
/// output is connected or read. Engines are registered and read/written like nodes.
class Engine : public FieldContainer {
public:
    /// @brief Shared ownership; connected fields keep their engine alive.
    using Ptr = std::shared_ptr<Engine>;

    /// @brief The abstract type "Engine".
    static const NodeType& classType();

    /// @brief The outputs in declaration order.
    const std::vector<EngineOutputBase*>& outputs() const { return mOutputs; }

    /// @brief The output named `name`, or nullptr.
    EngineOutputBase* findOutput(std::string_view name) const;

    /// @brief Runs evaluate() if an input changed since the last evaluation.
    void evaluateIfNeeded();

    /// @brief An input changed (or `source` is null: a referenced node changed): mark dirty and
    /// evaluate now if any output is connected.
    void notify(const Field* source) override;

protected:
    Engine() = default;

    /// @brief Registers `output` under `name` with its one-line meaning (as addField());
    /// call once per output in the constructor.
    void addOutput(EngineOutputBase& output, std::string name, const char* description);

    /// @brief Computes and sets every output from the inputs.
    virtual void evaluate() = 0;

private:
    std::vector<EngineOutputBase*> mOutputs;
    bool mIsDirty = true;
    bool mIsEvaluating = false;
};

} // namespace texsplat::sg
