#include "nodes/annotation/detail/TrueTypeFace.h"

#include "nodes/image/detail/FileBytes.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cmath>

// The implementation, static to this file (as detail/PngCodec.cpp compiles stb_image's).
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>

namespace texsplat::annotation::detail {

namespace {

// The code points of `text`: UTF-8 sequences decoded ("°C", "µm"), any other byte taken as the
// Latin-1 character of that value, so that no text is refused.
std::vector<int> codePoints(std::string_view text) {
    std::vector<int> points;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const int length = lead < 0xC2   ? 1
                           : lead < 0xE0 ? 2
                           : lead < 0xF0 ? 3
                           : lead < 0xF5 ? 4
                                         : 1;
        int point = length == 1 ? lead : lead & (0x7F >> length);
        bool valid = length > 1 && i + std::size_t(length) <= text.size();
        for (int k = 1; valid && k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
            valid = (next & 0xC0) == 0x80;
            point = (point << 6) | (next & 0x3F);
        }
        if (length > 1 && !valid) {
            points.push_back(lead);
            ++i;
            continue;
        }
        points.push_back(point);
        i += std::size_t(length);
    }
    return points;
}

} // namespace

struct TrueTypeFace::Font {
    stbtt_fontinfo info{};
};

TrueTypeFace::TrueTypeFace(const std::string& path) : mFont(std::make_unique<Font>()) {
    const std::vector<char> bytes = image::detail::readFileBytes(path);
    mBytes.assign(bytes.begin(), bytes.end());
    const int offset = mBytes.empty() ? -1 : stbtt_GetFontOffsetForIndex(mBytes.data(), 0);
    if (offset < 0 || stbtt_InitFont(&mFont->info, mBytes.data(), offset) == 0) {
        throw DataError(path + ": not a TrueType font");
    }
}

TrueTypeFace::~TrueTypeFace() = default;

TrueTypeFace::Coverage TrueTypeFace::render(std::string_view text, float pixelHeight) const {
    const stbtt_fontinfo& info = mFont->info;
    const float scale = stbtt_ScaleForPixelHeight(&info, pixelHeight);
    int ascent = 0;
    int descent = 0;
    int lineGap = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &lineGap);
    Coverage coverage;
    coverage.baseline = static_cast<int>(std::ceil(float(ascent) * scale));
    coverage.height = coverage.baseline + static_cast<int>(std::ceil(float(-descent) * scale));
    // Pen positions in fractional pixels, so glyphs keep their spacing at any size.
    const std::vector<int> characters = codePoints(text);
    std::vector<float> pens;
    float pen = 0.0f;
    for (std::size_t i = 0; i < characters.size(); ++i) {
        const int character = characters[i];
        pens.push_back(pen);
        int advance = 0;
        int leftBearing = 0;
        stbtt_GetCodepointHMetrics(&info, character, &advance, &leftBearing);
        pen += float(advance) * scale;
        if (i + 1 < characters.size()) {
            pen += float(stbtt_GetCodepointKernAdvance(&info, character, characters[i + 1])) *
                   scale;
        }
    }
    coverage.width = static_cast<int>(std::ceil(pen));
    coverage.values.assign(std::size_t(coverage.width) * std::size_t(coverage.height), 0.0f);
    for (std::size_t i = 0; i < characters.size(); ++i) {
        const int character = characters[i];
        const float shift = pens[i] - std::floor(pens[i]);
        int x0 = 0;
        int y0 = 0;
        int x1 = 0;
        int y1 = 0;
        stbtt_GetCodepointBitmapBoxSubpixel(&info, character, scale, scale, shift, 0.0f, &x0, &y0,
                                            &x1, &y1);
        const int glyphWidth = x1 - x0;
        const int glyphHeight = y1 - y0;
        if (glyphWidth <= 0 || glyphHeight <= 0) {
            continue; // a space
        }
        std::vector<unsigned char> glyph(std::size_t(glyphWidth) * std::size_t(glyphHeight));
        stbtt_MakeCodepointBitmapSubpixel(&info, glyph.data(), glyphWidth, glyphHeight,
                                          glyphWidth, scale, scale, shift, 0.0f, character);
        const int left = static_cast<int>(std::floor(pens[i])) + x0;
        const int top = coverage.baseline + y0;
        for (int y = 0; y < glyphHeight; ++y) {
            for (int x = 0; x < glyphWidth; ++x) {
                const int cx = left + x;
                const int cy = top + y;
                if (cx < 0 || cy < 0 || cx >= coverage.width || cy >= coverage.height) {
                    continue;
                }
                float& value = coverage.values[std::size_t(cy) * std::size_t(coverage.width) + cx];
                // Glyphs may overlap by their kerning; the text covers what either covers.
                value = std::max(value, float(glyph[std::size_t(y) * glyphWidth + x]) / 255.0f);
            }
        }
    }
    return coverage;
}

} // namespace texsplat::annotation::detail
