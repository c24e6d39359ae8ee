#include "nodes/annotation/ColorLegend.h"

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/actions/SplatInputs.h"
#include "nodes/annotation/LabelFont.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"

#include <algorithm>
#include <cstdio>
#include <utility>

namespace texsplat::annotation {
namespace {

struct Layout {
    int margin = 0;    // from the image edge
    int gap = 0;       // between bar and labels
    int thickness = 0; // of the bar
};

Layout layoutFor(int width, int height) {
    const int side = std::min(width, height);
    const int step = 1 + side / 256; // one more every 256 pixels
    Layout layout;
    layout.margin = 4 * step + side / 32;
    layout.gap = 3 * step;
    layout.thickness = std::max(6, side / 24);
    return layout;
}

// `start` moved so that [start, start + size) lies inside [0, limit) where it can; at 0 when it
// cannot (an image smaller than the label: the label is cut, not misplaced).
int keepInside(int start, int size, int limit) {
    return std::max(0, std::min(start, limit - size));
}

bool isVertical(LegendPosition position) {
    return position == LegendPosition::Right || position == LegendPosition::Left;
}

template <class T> std::shared_ptr<T> firstOfType(sg::Node& root) {
    sg::SearchAction search;
    search.setType(T::classType());
    search.apply(root);
    return search.paths().empty() ? nullptr
                                  : std::dynamic_pointer_cast<T>(search.paths().front().tail());
}

// Mean luminance (Rec. 709) of the part of `region` inside `image`, over an opaque black page
// where the image is transparent; 0 for a region outside the image.
double luminanceUnder(const image::Image& image, image::ImageRegion region) {
    const int x0 = std::max(region.x, 0);
    const int y0 = std::max(region.y, 0);
    const int x1 = std::min(region.x + region.width, image.width());
    const int y1 = std::min(region.y + region.height, image.height());
    if (x0 >= x1 || y0 >= y1) {
        return 0.0;
    }
    const glm::dvec4 mean = image.statistics({x0, y0, x1 - x0, y1 - y0}).mean;
    return 0.2126 * mean.r + 0.7152 * mean.g + 0.0722 * mean.b;
}

} // namespace

LegendPosition parseLegendPosition(const std::string& name) {
    const std::pair<const char*, LegendPosition> names[] = {{"right", LegendPosition::Right},
                                                            {"left", LegendPosition::Left},
                                                            {"top", LegendPosition::Top},
                                                            {"bottom", LegendPosition::Bottom}};
    for (const auto& [text, position] : names) {
        if (name == text) {
            return position;
        }
    }
    throw DataError("legend position must be right, left, top or bottom, got '" + name + "'");
}

ColorLegend::ColorLegend(ColorMap colorMap, glm::vec2 range, LegendPosition position)
    : mColorMap(std::move(colorMap)), mRange(range), mPosition(position) {}

ColorLegend ColorLegend::ofScene(sg::Node& root, LegendPosition position) {
    std::shared_ptr<const nodes::TransferFunction> transfer;
    std::shared_ptr<const nodes::VolumeData> volume;
    const std::vector<nodes::SplatInput> inputs = nodes::splatInputs(root);
    if (!inputs.empty()) {
        // What the first splat node draws: its function over its own volume.
        transfer = std::static_pointer_cast<const nodes::TransferFunction>(
            inputs.front().transfer->shared_from_this());
        volume = std::static_pointer_cast<const nodes::VolumeData>(
            inputs.front().volume->shared_from_this());
    } else {
        transfer = firstOfType<nodes::TransferFunction>(root);
        volume = firstOfType<nodes::VolumeData>(root);
    }
    if (!transfer) {
        throw DataError("colour legend: the scene has no TransferFunction");
    }
    // Checked here, outside a traversal: a refusal names the node's line as a render's does.
    const volume::ScalarGridPtr grid =
        volume ? sg::withNodeLocation(*volume, [&volume] { return volume->scalarGrid(); })
               : nullptr;
    const glm::vec2 range = sg::withNodeLocation(*transfer, [&] {
        return grid ? transfer->dataScale(*grid).range : transfer->range.value();
    });
    return ColorLegend([transfer](float t) { return transfer->colorAt(t); }, range, position);
}

image::ImageRegion ColorLegend::barRegion(int width, int height) const {
    const Layout layout = layoutFor(width, height);
    const LabelFont font = LabelFont::forImage(width, height);
    const int labelWidth = std::max({font.textWidth(label(mRange.x)),
                                     font.textWidth(label(mRange.y)),
                                     font.textWidth(label(0.5 * (double(mRange.x) + mRange.y)))});
    const int labelHeight = font.height();
    image::ImageRegion bar;
    if (isVertical(mPosition)) {
        bar.width = layout.thickness;
        bar.height = std::max(8, height * 3 / 5);
        bar.y = (height - bar.height) / 2;
        bar.x = mPosition == LegendPosition::Left
                    ? layout.margin
                    : width - layout.margin - labelWidth - layout.gap - bar.width;
    } else {
        bar.height = layout.thickness;
        bar.width = std::max(8, width * 3 / 5);
        bar.x = (width - bar.width) / 2;
        bar.y = mPosition == LegendPosition::Top
                    ? layout.margin
                    : height - layout.margin - labelHeight - layout.gap - bar.height;
    }
    return bar;
}

void ColorLegend::draw(image::Image& image) const {
    const Layout layout = layoutFor(image.width(), image.height());
    const image::ImageRegion bar = barRegion(image.width(), image.height());
    const bool vertical = isVertical(mPosition);
    const int length = vertical ? bar.height : bar.width;
    for (int i = 0; i < length; ++i) {
        // Pixel centres from t = 0 at the low end to t = 1 at the high end.
        const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(length);
        const glm::vec4 rgba(mColorMap(t), 1.0f);
        for (int j = 0; j < (vertical ? bar.width : bar.height); ++j) {
            const int x = vertical ? bar.x + j : bar.x + i;
            const int y = vertical ? bar.y + bar.height - 1 - i : bar.y + j;
            if (x >= 0 && y >= 0 && x < image.width() && y < image.height()) {
                image.setPixel(x, y, rgba);
            }
        }
    }
    const LabelFont font = LabelFont::forImage(image.width(), image.height());
    const int labelHeight = font.height();
    for (const float t : {0.0f, 0.5f, 1.0f}) {
        const std::string text = label(double(mRange.x) + t * (double(mRange.y) - mRange.x));
        const int textWidth = font.textWidth(text);
        glm::ivec2 topLeft;
        if (vertical) {
            topLeft.x = bar.x + bar.width + layout.gap;
            const int centre = bar.y + static_cast<int>((1.0f - t) * float(bar.height - 1));
            topLeft.y = keepInside(centre - labelHeight / 2, labelHeight, image.height());
        } else {
            const int centre = bar.x + static_cast<int>(t * float(bar.width - 1));
            topLeft.x = keepInside(centre - textWidth / 2, textWidth, image.width());
            topLeft.y = bar.y + bar.height + layout.gap;
        }
        // Ink that stands out from what lies under the label, with a shadow of the other tone.
        const bool onLight = luminanceUnder(image, {topLeft.x, topLeft.y, textWidth, labelHeight}) >
                             0.5;
        const glm::vec4 black(0.0f, 0.0f, 0.0f, 1.0f);
        const glm::vec4 white(1.0f);
        font.draw(image, topLeft + glm::ivec2(font.shadowOffset()), text, onLight ? white : black);
        font.draw(image, topLeft, text, onLight ? black : white);
    }
}

std::string ColorLegend::label(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value == 0.0 ? 0.0 : value);
    return text;
}

} // namespace texsplat::annotation
