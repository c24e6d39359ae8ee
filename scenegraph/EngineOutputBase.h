#pragma once

#include "scenegraph/Fwd.h"

#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief The untyped part of an engine output: its name, its engine and the fields it feeds.
///
/// Generic code (reader, writer) uses this interface: `engine.findOutput("timeOut")`, then
/// `field.connectFrom(*output)`. Values are set through the typed EngineOutput<F>.
class EngineOutputBase {
public:
    EngineOutputBase(const EngineOutputBase&) = delete;
    EngineOutputBase& operator=(const EngineOutputBase&) = delete;

    /// @brief Disconnects the fields it feeds (they keep their last value).
    virtual ~EngineOutputBase();

    /// @brief The output name, as registered by the engine ("timeOut").
    const std::string& name() const { return mName; }

    /// @brief The engine that owns the output.
    Engine& engine() const { return *mEngine; }

    /// @brief "Type(name).output" for error messages.
    std::string fullName() const;

    /// @brief The type name of the fields it can feed ("SFFloat").
    virtual std::string_view typeName() const = 0;

    /// @brief The fields connected from this output.
    const std::vector<Field*>& connectedFields() const { return mTargets; }

    /// @brief The current value, as a standalone field of the output's type (evaluates the
    /// engine first if its inputs changed).
    const Field& valueField();

protected:
    EngineOutputBase() = default;

    /// @brief Copies the current value into every connected field.
    void push();

    /// @brief The standalone field holding the value.
    virtual Field& storage() = 0;

private:
    friend class Engine;
    friend class Field;

    Engine* mEngine = nullptr;
    std::string mName;
    std::vector<Field*> mTargets;
};

} // namespace texsplat::sg
