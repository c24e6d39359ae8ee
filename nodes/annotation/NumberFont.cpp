#include "nodes/annotation/NumberFont.h"

#include "scenegraph/Error.h"

#include <array>
#include <cstdint>
#include <string>

namespace texsplat::annotation {
namespace {

struct Glyph {
    char character;
    // Rows top to bottom; bit 4 is the leftmost column.
    std::array<std::uint8_t, NumberFont::kGlyphHeight> rows;
};

constexpr std::array<Glyph, 15> kGlyphs = {{
    {'0', {0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110}},
    {'1', {0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}},
    {'2', {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111}},
    {'3', {0b11111, 0b00010, 0b00100, 0b00010, 0b00001, 0b10001, 0b01110}},
    {'4', {0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010}},
    {'5', {0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110}},
    {'6', {0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110}},
    {'7', {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000}},
    {'8', {0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110}},
    {'9', {0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100}},
    {'-', {0b00000, 0b00000, 0b00000, 0b11111, 0b00000, 0b00000, 0b00000}},
    {'+', {0b00000, 0b00100, 0b00100, 0b11111, 0b00100, 0b00100, 0b00000}},
    {'.', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b01100}},
    {'e', {0b00000, 0b00000, 0b01110, 0b10001, 0b11111, 0b10000, 0b01110}},
    {' ', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000}},
}};

const Glyph* glyphOf(char character) {
    for (const Glyph& glyph : kGlyphs) {
        if (glyph.character == character) {
            return &glyph;
        }
    }
    return nullptr;
}

} // namespace

bool NumberFont::hasGlyph(char character) { return glyphOf(character) != nullptr; }

int NumberFont::textWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (static_cast<int>(text.size()) * kAdvance - 1) * scale;
}

void NumberFont::draw(image::Image& image, glm::ivec2 topLeft, std::string_view text, int scale,
                      const glm::vec4& rgba) {
    int left = topLeft.x;
    for (const char character : text) {
        const Glyph* glyph = glyphOf(character);
        if (!glyph) {
            throw DataError("NumberFont: no glyph for '" + std::string(1, character) +
                            "'; it writes digits, '-', '+', '.', 'e' and space");
        }
        for (int row = 0; row < kGlyphHeight * scale; ++row) {
            for (int column = 0; column < kGlyphWidth * scale; ++column) {
                const int x = left + column;
                const int y = topLeft.y + row;
                const bool isSet = (glyph->rows[static_cast<std::size_t>(row / scale)] >>
                                    (kGlyphWidth - 1 - column / scale)) & 1U;
                if (isSet && x >= 0 && y >= 0 && x < image.width() && y < image.height()) {
                    image.setPixel(x, y, rgba);
                }
            }
        }
        left += kAdvance * scale;
    }
}

} // namespace texsplat::annotation
