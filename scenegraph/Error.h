#pragma once

#include <stdexcept>
#include <string>

namespace texsplat {

/// @brief Base of every expected failure texsplat reports (bad file, bad value, no GL context).
///
/// The message starts with where the problem is (`scene.iv:12:5:` or `grid.raw:`) and says what
/// was expected, so an application can print `what()` as it is.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
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

/// @brief An OpenGL failure: no context, a shader that does not compile, a GL error.
class GlError : public Error {
public:
    using Error::Error;
};

} // namespace texsplat
