#pragma once

#include "nodes/annotation/ColorBar.h"
#include "nodes/annotation/LabelFont.h"
#include "nodes/image/Image.h"
#include "nodes/image/ImageRegion.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace texsplat::annotation {

/// @brief Which side of the image a ColorLegend takes: vertical bars at the right or left,
/// horizontal ones at the top or bottom.
enum class LegendPosition { Right, Left, Top, Bottom };

/// @brief The position named `name` ("right", "left", "top", "bottom").
/// @throws DataError naming the accepted names.
LegendPosition parseLegendPosition(const std::string& name);

/// @brief How a ColorLegend is laid out.
struct LegendStyle {
    LegendPosition position = LegendPosition::Right; ///< the side of the image it takes
    int ticks = 5; ///< how many tick values to aim for (ColorLegend::ticks()), 2 to kMaxTicks

    /// @brief The most ticks a bar may ask for.
    static constexpr int kMaxTicks = 20;
};

/// @brief Colour bars for a figure: a strip along one side of a rendered picture holding one bar
/// per ColorBar, with tick marks at round values, their labels and the bar's title, beside the
/// picture and never over it.
///
/// The figure is the picture, as large as it was rendered (so a scene's own camera shows what
/// it framed), with the strip added at its side: wider for bars at the right or left, taller for
/// bars at the top or bottom (figureSize(); dataRegion() is where the picture lies in it). Bars
/// are opaque, their pixels the colour map's colours
/// S(t) as they are (lower values at the bottom or left), framed by a thin line. Ticks sit at
/// the round values ticks() finds in the range, labelled with as many decimals as their step
/// needs ("0", "0.25", "0.5" …; powers of ten beyond 10⁶ and below 10⁻⁴ as "2e+06"), and the title
/// runs along the bar (bottom to top beside a vertical bar, under a horizontal one). Text and
/// lines are black on a light or transparent background and white on a dark one, in the
/// LabelFont (DejaVu Sans, anti-aliased; the built-in NumberFont when the font file is missing,
/// which leaves titles out with a warning). Sizes follow the picture (LabelFont::forImage();
/// margins grow by a step every 256 pixels of the smaller side). Several bars stand side by
/// side, vertical ones in columns, horizontal ones sharing the width.
class ColorLegend {
public:
    /// @brief The legend of `bars` (at least one) beside a picture of `width` × `height`.
    /// @throws DataError when `bars` is empty or the tick count is outside 2 to kMaxTicks.
    ColorLegend(std::vector<ColorBar> bars, LegendStyle style, int width, int height);

    /// @brief The bars, in order.
    const std::vector<ColorBar>& bars() const { return mBars; }

    /// @brief The figure's size: the picture's and the strip's.
    glm::ivec2 figureSize() const { return {mWidth, mHeight}; }

    /// @brief Where the picture lies in the figure: all of it but the strip.
    image::ImageRegion dataRegion() const { return mData; }

    /// @brief The rectangle of bar `index`'s colours in the figure.
    image::ImageRegion barRegion(std::size_t index) const { return mBarRegions.at(index); }

    /// @brief The figure: `picture` (of the size given to the constructor) in the data region,
    /// the strip filled with the premultiplied `background` and the bars drawn there in ink that
    /// reads on it. A picture with depth gives the figure depth, 1 (no surface) in the strip.
    image::Image compose(const image::Image& picture, const glm::vec4& background) const;

    /// @brief Round values inside `range` (its ends included when round): the multiples of a
    /// step of 1, 2, 2.5 or 5 times a power of ten whose count comes closest to `count` (the
    /// fewer on a tie); at least the two ends' values when no step gives two.
    static std::vector<double> ticks(glm::vec2 range, int count);

    /// @brief The labels of `ticks` (from ticks(), at least one): each with the decimals their
    /// step needs, "-0" written "0".
    static std::vector<std::string> tickLabels(const std::vector<double>& ticks);

    /// @brief The ink that reads on `background` (premultiplied): opaque black on a light or
    /// mostly transparent one, opaque white on a dark one.
    static glm::vec4 inkFor(const glm::vec4& background);

private:
    struct Placed {
        std::vector<double> ticks;
        std::vector<std::string> labels;
        int labelWidth = 0;
    };

    void draw(image::Image& image, std::size_t index, const glm::vec4& ink) const;

    std::vector<ColorBar> mBars;
    LegendStyle mStyle;
    int mWidth;
    int mHeight;
    LabelFont mFont;
    int mGap = 0;
    int mTick = 0;
    int mLine = 1;
    std::vector<Placed> mPlaced;
    std::vector<image::ImageRegion> mBarRegions;
    image::ImageRegion mData;
};

} // namespace texsplat::annotation
