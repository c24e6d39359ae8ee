#pragma once

#include "scenegraph/Notifier.h"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::sg {

/// @brief Base of every field type (SFFloat, MFVec3f, SFNode, ...): a named, typed value of a
/// node or engine that can be observed, connected, read and written.
///
/// Generic code (reader, writer) handles any field through this interface: `typeName()`
/// ("SFFloat"), `name()`, `isDefault()`, `readValue()`, `writeValue()`. Typed access is on the
/// concrete field (`SFFloat::value()`, `setValue()`).
///
/// Setting a value clears the default flag and notifies, in order: the field's observers, the
/// fields connected from it, and its container (which passes it on to parent nodes).
///
/// Connections: `connectFrom(field)` or `connectFrom(engineOutput)` makes this field follow a
/// source of the same type; a connection that would close a cycle throws DataError naming the
/// fields. Connections form chains (a field follows a field that follows an engine output whose
/// engine's input follows a field ...): each connection is one link, and so is each engine, from
/// its inputs to its outputs. A change travels down a chain recursively, so no chain may be longer
/// than kMaxConnectionChain links; a connection that would make one longer throws DataError. A
/// field connected from an engine output keeps that engine alive; a field-to-field connection
/// does not own the source (it is dropped when the source dies) unless keepSourceAlive() says so.
///
/// A field costs what its value holds plus 48 bytes: what connections need is made on the first
/// connection to or from it, its observer list on the first observer (Notifier), and its name is
/// shared by every field of that name (issue 14: a field cost 144 bytes whatever it held).
class Field : public Notifier {
public:
    /// @brief The longest chain of connections, in links. A change passes each link in a few
    /// nested calls (measured: about 50 bytes of stack a link optimized, 450 bytes in a debug
    /// build under AddressSanitizer), so a chain at the limit needs under 0.5 MB of the 8 MB
    /// stack that the main thread and std::thread have by default on Linux. Checking a new
    /// connection walks only chains of at most this many links upstream.
    static constexpr std::size_t kMaxConnectionChain = 1000;

    ~Field() override;

    /// @brief The Inventor type name, e.g. "SFFloat", "MFVec3f".
    virtual std::string_view typeName() const = 0;

    /// @brief The name under which the container registered it ("size"); empty if standalone.
    const std::string& name() const;

    /// @brief The owning node or engine, nullptr for a standalone field.
    FieldContainer* container() const { return mContainer; }

    /// @brief "Type(name).field" for error messages, e.g. "Cube(box).size" ("Cube.size" for an
    /// unnamed node, "<standalone>" without container).
    std::string fullName() const;

    /// @brief True while the field holds the default its container gave it (never set since);
    /// the writer writes only fields that are not default. Values arriving through a
    /// connection leave the flag as it is: the connection, not the value, is what is written.
    bool isDefault() const { return mIsDefault; }

    /// @brief Marks the value as default (or not) without changing it.
    void setDefault(bool isDefault) { mIsDefault = isDefault; }

    /// @brief Parses a value in Inventor ASCII syntax and sets it. Throws ParseError.
    virtual void readValue(FieldValueReader& reader) = 0;

    /// @brief Writes the value in Inventor ASCII syntax.
    virtual void writeValue(FieldValueWriter& writer) const = 0;

    /// @brief The value as one line of Inventor ASCII (`1 0 0`, `[ 1, 2 ]`); nodes appear as
    /// `NULL` or their type name. For messages and tests; files are written by the writer.
    std::string valueText() const;

    /// @brief Copies the value of a field of the same type (`typeName()` equal).
    virtual void copyValueFrom(const Field& other) = 0;

    /// @brief The bytes the value holds on the heap beside the field itself (an MF field's list,
    /// a long string); what the scene reader counts of a file against the memory limit.
    virtual std::size_t heapBytes() const { return 0; }

    /// @brief Notifies as if the value had changed (without clearing the default flag).
    void touch();

    /// @brief Turns notification off or back on and returns whether it was on (Inventor's
    /// SoField::enableNotify()). While it is off, a change of the value tells nobody: no
    /// observer, not the container, and no connected field follows it. For a change that the
    /// caller knows makes no difference to anything observing the field.
    bool enableNotify(bool enable) {
        const bool was = mIsNotifyEnabled;
        mIsNotifyEnabled = enable;
        return was;
    }

    /// @brief Whether a change of the value notifies (enableNotify()); on by default.
    bool isNotifyEnabled() const { return mIsNotifyEnabled; }

    /// @brief Follows `source` from now on (takes its value now). Throws DataError if the
    /// types differ, or the connection would make a cycle or a chain longer than
    /// kMaxConnectionChain links.
    void connectFrom(Field& source);

    /// @brief Follows an engine output (keeps the engine alive). Throws DataError if the types
    /// differ, or the connection would make a cycle or a chain longer than kMaxConnectionChain
    /// links.
    void connectFrom(EngineOutputBase& output);

    /// @brief Makes the present connection from a field keep that field's container alive until
    /// the connection ends, as a connection from an engine output keeps its engine. For a source
    /// that nothing else holds, such as a node written in place in a scene file. The caller makes
    /// sure that the source's container does not hold this field's container, directly or
    /// through other containers: such a cycle of shared pointers would never be freed.
    void keepSourceAlive();

    /// @brief Removes the incoming connection, if any; the value stays.
    void disconnect();

    /// @brief True when connected from a field or an engine output.
    bool isConnected() const { return connectedField() != nullptr || connectedOutput() != nullptr; }

    /// @brief The field this one follows, or nullptr.
    Field* connectedField() const { return mConnections ? mConnections->sourceField : nullptr; }

    /// @brief The engine output this one follows, or nullptr.
    EngineOutputBase* connectedOutput() const {
        return mConnections ? mConnections->sourceOutput : nullptr;
    }

protected:
    Field() = default;

    /// @brief Call after every change of the value: clears the default flag and notifies.
    void valueChanged();

    /// @brief Throws DataError unless `other` has this field's type; used by copyValueFrom().
    void checkSameType(const Field& other) const;

    /// @brief Called once the container has registered the field (container() is set).
    virtual void attached() {}

private:
    friend class FieldContainer;
    friend class EngineOutputBase;

    // The incoming connection and the fields that follow this one: made on the first connection
    // to or from the field, and kept.
    struct Connections {
        Field* sourceField = nullptr;
        EngineOutputBase* sourceOutput = nullptr;
        // The engine of sourceOutput, or the container of sourceField after keepSourceAlive().
        std::shared_ptr<FieldContainer> sourceOwner;
        std::vector<Field*> targets;
    };

    Connections& connections();
    const std::vector<Field*>& targets() const;
    void propagate(bool clearDefault);
    void receive(const Field& source);
    void checkConnectable(std::string_view sourceType, const std::string& sourceName,
                          const Field* sourceField, const EngineOutputBase* sourceOutput) const;

    FieldContainer* mContainer = nullptr;
    // Interned (detail::internFieldName()): one string for every field of that name; or, for a
    // name read from a file, the container's own (FieldContainer::addFieldNamedBy()).
    const std::string* mName = nullptr;
    std::unique_ptr<Connections> mConnections;
    // Last, so that a derived field's value may fill the padding after them.
    bool mIsDefault = true;
    bool mIsReceiving = false;
    bool mIsNotifyEnabled = true;
};

} // namespace texsplat::sg
