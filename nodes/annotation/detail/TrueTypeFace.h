#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace texsplat::annotation::detail {

/// @brief A TrueType font file, rasterized with stb_truetype: anti-aliased coverage of a line of
/// text at a pixel height.
class TrueTypeFace {
public:
    /// @brief The coverage of a line of text: `width` × `height` values in [0, 1], top row first;
    /// the baseline is `baseline` rows from the top.
    struct Coverage {
        int width = 0;
        int height = 0;
        int baseline = 0;
        std::vector<float> values;

        /// @brief The coverage of pixel (x, y) of the text's box.
        float at(int x, int y) const { return values[std::size_t(y) * std::size_t(width) + x]; }
    };

    /// @brief Reads the font file at `path`.
    /// @throws IoError when it cannot be read, DataError "path: not a TrueType font" when it is
    /// not one.
    explicit TrueTypeFace(const std::string& path);
    TrueTypeFace(const TrueTypeFace&) = delete;
    TrueTypeFace& operator=(const TrueTypeFace&) = delete;
    ~TrueTypeFace();

    /// @brief The coverage of `text` (one line of UTF-8; a byte that starts no UTF-8 character
    /// is the Latin-1 character of its value) with an em of
    /// `pixelHeight` pixels from the highest ascent to the lowest descent.
    Coverage render(std::string_view text, float pixelHeight) const;

private:
    struct Font;
    std::vector<unsigned char> mBytes;
    std::unique_ptr<Font> mFont;
};

} // namespace texsplat::annotation::detail
