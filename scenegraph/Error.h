#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace texsplat {

/// @brief Base of every expected failure texsplat reports (bad file, bad value, no GL context).
///
/// The message starts with where the problem is (`scene.iv:12:5:` or `grid.raw:`) and says what
/// was expected, so an application can print `what()` as it is.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;

    /// @brief Puts `where` (a node's place in its scene file, "scene.iv:12:5") in front of the
    /// message, once: the first node an action was in when the error passed through it claims
    /// it (Action::traverse()), enclosing nodes leave it alone. An empty `where` (a node made
    /// in code) claims it without changing the message, so that no enclosing node is blamed.
    void locateAtNode(std::string_view where) {
        if (mIsLocatedAtNode) {
            return;
        }
        mIsLocatedAtNode = true;
        if (!where.empty()) {
            std::runtime_error::operator=(
                std::runtime_error(std::string(where) + ": " + what()));
        }
    }

    /// @brief Whether a node has claimed the error (locateAtNode()).
    [[nodiscard]] bool isLocatedAtNode() const { return mIsLocatedAtNode; }

private:
    bool mIsLocatedAtNode = false;
};

/// @brief A scene file or other text input that does not follow its grammar.
class ParseError : public Error {
public:
    using Error::Error;
};

/// @brief A file that cannot be opened, read or written.
class IoError : public Error {
public:
    using Error::Error;
};

/// @brief Data that is readable but unusable (wrong size, wrong type, non-finite where finite
/// values are required, an optimizer start outside the admissible domain, ...).
class DataError : public Error {
public:
    using Error::Error;
};

/// @brief Work that needs more memory than the limit allows or the system gives
/// (MemoryLimit.h): the message names the stage, the bytes where known, and what to do.
class ResourceError : public Error {
public:
    using Error::Error;
};

/// @brief An OpenGL failure: no context, a shader that does not compile, a GL error.
class GlError : public Error {
public:
    using Error::Error;
};

} // namespace texsplat
