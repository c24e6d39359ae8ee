#pragma once

#include "nodes/image/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace texsplat::annotation {

namespace detail {
class TrueTypeFace;
} // namespace detail

/// @brief Which way a label reads.
enum class TextDirection {
    LeftToRight, ///< a line of text
    BottomToTop, ///< turned a quarter counter-clockwise, as the title beside a vertical bar
};

/// @brief The font of labels drawn into images: DejaVu Sans, anti-aliased (stb_truetype), or the
/// built-in NumberFont when the font file cannot be read.
///
/// The font file is the one CMake found when texsplat was built (kDefaultFile; Debian's
/// fonts-dejavu-core). When it cannot be read at run time, labels fall back to NumberFont and
/// one warning per file and process says why. Faces are read once per file and shared.
class LabelFont {
public:
    /// @brief The font file found at build time; empty when none was found.
    static const std::string kDefaultFile;

    /// @brief The label font for an image of `width` × `height`: a pixel height that grows with
    /// the smaller side (12 pixels up to 240, then a twentieth of it), and NumberFont scale
    /// 1 + side / 256 in the fallback.
    static LabelFont forImage(int width, int height, const std::string& file = kDefaultFile);

    /// @brief Glyphs `pixelHeight` pixels from ascent to descent from the TrueType `file`, or
    /// NumberFont at `fallbackScale` when it cannot be read.
    LabelFont(const std::string& file, int pixelHeight, int fallbackScale);

    /// @brief True when labels are drawn with the TrueType font.
    bool isTrueType() const { return mFace != nullptr; }

    /// @brief Whether every character of `text` has a glyph: always with the TrueType font (a
    /// character it lacks is drawn as its box), digits, sign, point, `e` and space in the
    /// fallback.
    bool canDraw(std::string_view text) const;

    /// @brief The width in pixels of `text`.
    int textWidth(std::string_view text) const;

    /// @brief The height in pixels of a line of text.
    int height() const;

    /// @brief How far a label's shadow is offset right and down, in pixels.
    int shadowOffset() const;

    /// @brief Draws `text` with its box's top-left corner at `topLeft`, compositing the
    /// premultiplied `rgba` over the image by the glyphs' coverage; pixels outside the image are
    /// left out.
    /// @throws DataError for a character NumberFont has no glyph for, in the fallback.
    void draw(image::Image& image, glm::ivec2 topLeft, std::string_view text,
              const glm::vec4& rgba) const;

    /// @brief draw() reading `direction`: BottomToTop turns the text's box a quarter
    /// counter-clockwise, so it is height() wide and textWidth() high, its top-left corner at
    /// `topLeft`.
    void draw(image::Image& image, glm::ivec2 topLeft, std::string_view text,
              const glm::vec4& rgba, TextDirection direction) const;

private:
    std::shared_ptr<const detail::TrueTypeFace> mFace; // nullptr: NumberFont
    int mPixelHeight;
    int mFallbackScale;
};

} // namespace texsplat::annotation
