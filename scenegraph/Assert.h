#pragma once

/// @file
/// @brief `TEXSPLAT_ASSERT(cond, "Class::fn(): what")`: invariant checks, on in debug builds and
/// tests (`TEXSPLAT_ENABLE_ASSERTS`), compiled out otherwise. A failed invariant is a bug in
/// texsplat, not a user error, so it aborts with the message instead of throwing.

namespace texsplat::detail {
[[noreturn]] void assertionFailed(const char* condition, const char* message, const char* file,
                                  int line) noexcept;
} // namespace texsplat::detail

#if defined(TEXSPLAT_ENABLE_ASSERTS) || !defined(NDEBUG)
#define TEXSPLAT_ASSERT(condition, message)                                                        \
    ((condition) ? static_cast<void>(0)                                                            \
                 : ::texsplat::detail::assertionFailed(#condition, message, __FILE__, __LINE__))
#else
#define TEXSPLAT_ASSERT(condition, message) static_cast<void>(0)
#endif
