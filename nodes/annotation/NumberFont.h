#pragma once

#include "nodes/image/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <string_view>

namespace texsplat::annotation {

/// @brief A built-in 5 × 7 pixel font of the characters numbers are written with: the digits,
/// `-`, `+`, `.`, `e` and space (what `%g` prints), so that labels need no font file.
///
/// Each glyph is drawn as `scale` × `scale` blocks of pixels and advances 6 × `scale` pixels (one
/// column of space).
class NumberFont {
public:
    static constexpr int kGlyphWidth = 5;  ///< pixels of a glyph at scale 1
    static constexpr int kGlyphHeight = 7; ///< pixels of a glyph at scale 1
    static constexpr int kAdvance = 6;     ///< pixels from one glyph to the next at scale 1

    /// @brief Whether `character` has a glyph.
    static bool hasGlyph(char character);

    /// @brief The width in pixels of `text` at `scale` (>= 1): kAdvance · scale per character,
    /// less the trailing column of space.
    static int textWidth(std::string_view text, int scale);

    /// @brief Draws `text` with its top-left corner at `topLeft`, replacing the covered pixels by
    /// the premultiplied `rgba`; pixels outside the image are left out.
    /// @throws DataError for a character without a glyph.
    static void draw(image::Image& image, glm::ivec2 topLeft, std::string_view text, int scale,
                     const glm::vec4& rgba);
};

} // namespace texsplat::annotation
