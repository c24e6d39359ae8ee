#pragma once

#include "scenegraph/EngineOutputBase.h"

#include <string_view>

namespace texsplat::sg {

/// @brief A typed engine output feeding fields of type `F` (e.g. `EngineOutput<SFFloat>`).
///
/// The engine registers it with `addOutput(output, "name")` in its constructor and sets it in
/// `evaluate()`; every set pushes the value to the connected fields.
template <class F> class EngineOutput final : public EngineOutputBase {
public:
    /// @brief The C++ value type of `F`.
    using Value = typename F::Value;

    EngineOutput() = default;

    /// @copydoc EngineOutputBase::typeName
    std::string_view typeName() const override { return mValue.typeName(); }

    /// @brief The current value (evaluates the engine first if its inputs changed).
    const Value& value() { return static_cast<const F&>(valueField()).value(); }

    /// @brief Sets the value and pushes it to the connected fields. Called from evaluate().
    void setValue(const Value& value) {
        mValue.setValue(value);
        push();
    }

protected:
    /// @copydoc EngineOutputBase::storage
    Field& storage() override { return mValue; }

private:
    F mValue;
};

} // namespace texsplat::sg
