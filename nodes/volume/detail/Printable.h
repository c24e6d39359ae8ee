#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace texsplat::volume::detail {

/// @brief Whether `text` is printable ASCII (with tabs), so a message may quote it as it is.
inline bool isText(std::string_view text) {
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x20 && byte != '\t') || byte >= 0x7f)
            return false;
    }
    return true;
}

/// @brief `text` for a message: printable ASCII as it is, every other byte as `\xNN`, and cut to
/// `maxLength` bytes of input ("..." follows then), so a binary file read as text never puts raw
/// bytes on the user's terminal.
inline std::string printable(std::string_view text, std::size_t maxLength = 64) {
    std::string result;
    for (std::size_t i = 0; i < text.size() && i < maxLength; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if ((byte < 0x20 && byte != '\t') || byte >= 0x7f) {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            result += escaped;
        } else {
            result += text[i];
        }
    }
    if (text.size() > maxLength)
        result += "...";
    return result;
}

} // namespace texsplat::volume::detail
