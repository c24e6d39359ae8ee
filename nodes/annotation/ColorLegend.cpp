#include "nodes/annotation/ColorLegend.h"

#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace texsplat::annotation {
namespace {

bool isVertical(LegendPosition position) {
    return position == LegendPosition::Right || position == LegendPosition::Left;
}

// `start` moved so that [start, start + size) lies inside [0, limit) where it can; at 0 when it
// cannot (an image smaller than the label: the label is cut, not misplaced).
int keepInside(int start, int size, int limit) {
    return std::max(0, std::min(start, limit - size));
}

// Fills the part of `region` inside `image` with `rgba`.
void fillRegion(image::Image& image, const image::ImageRegion& region, const glm::vec4& rgba) {
    const int x0 = std::max(region.x, 0);
    const int y0 = std::max(region.y, 0);
    const int x1 = std::min(region.x + region.width, image.width());
    const int y1 = std::min(region.y + region.height, image.height());
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            image.setPixel(x, y, rgba);
        }
    }
}

// The step of a tick: `mantissa` (1, 2, 2.5 or 5) times 10^`exponent`.
struct Step {
    double mantissa = 1.0;
    int exponent = 0;
    double value() const { return mantissa * std::pow(10.0, exponent); }
    // k steps, as the double nearest the decimal value (3 · 0.2 is 0.6, not 0.6000000000000001).
    double times(double k) const {
        return exponent < 0 ? k * mantissa / std::pow(10.0, -exponent)
                            : k * mantissa * std::pow(10.0, exponent);
    }
};

// The multiples of `step` in [low, high], a millionth of a step of slack at each end so that
// round ends (0 and 1.2 of a range 0..1.2) count.
std::vector<double> multiples(double low, double high, const Step& step) {
    const double slack = 1e-6;
    const double first = std::ceil(low / step.value() - slack);
    const double last = std::floor(high / step.value() + slack);
    std::vector<double> values;
    for (double k = first; k <= last && values.size() <= LegendStyle::kMaxTicks * 10; ++k) {
        values.push_back(step.times(k));
    }
    return values;
}

// The step between consecutive `ticks` (at least two), as mantissa and exponent.
Step stepOf(const std::vector<double>& ticks) {
    const double step = ticks[1] - ticks[0];
    Step best;
    best.exponent = static_cast<int>(std::floor(std::log10(step)));
    const double mantissa = step / std::pow(10.0, best.exponent);
    best.mantissa = 1.0;
    for (const double candidate : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        if (std::abs(mantissa - candidate) < std::abs(mantissa - best.mantissa)) {
            best.mantissa = candidate;
        }
    }
    if (best.mantissa == 10.0) {
        best = {1.0, best.exponent + 1};
    }
    return best;
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

std::vector<double> ColorLegend::ticks(glm::vec2 range, int count) {
    const double low = std::min(range.x, range.y);
    const double high = std::max(range.x, range.y);
    const double span = high - low;
    if (!(span > 0.0) || !std::isfinite(span)) {
        return {low};
    }
    const int base = static_cast<int>(std::floor(std::log10(span / std::max(count, 1))));
    std::vector<double> best;
    for (int exponent = base - 1; exponent <= base + 1; ++exponent) {
        // Larger steps first: on a tie, the fewer ticks win.
        for (const double mantissa : {5.0, 2.5, 2.0, 1.0}) {
            const std::vector<double> values = multiples(low, high, Step{mantissa, exponent});
            const auto distance = [count](const std::vector<double>& v) {
                return std::abs(static_cast<int>(v.size()) - count);
            };
            if (values.size() >= 2 && (best.empty() || distance(values) < distance(best))) {
                best = values;
            }
        }
    }
    if (best.empty()) {
        best = {low, high};
    }
    for (double& value : best) {
        if (std::abs(value) < 1e-9 * span) {
            value = 0.0; // no "-1e-17" for a tick at zero
        }
    }
    return best;
}

std::vector<std::string> ColorLegend::tickLabels(const std::vector<double>& ticks) {
    double largest = 0.0;
    for (const double value : ticks) {
        largest = std::max(largest, std::abs(value));
    }
    const bool scientific =
        ticks.size() >= 2 && (largest >= 1e6 || (largest > 0.0 && largest < 1e-4));
    int decimals = 0;
    if (ticks.size() >= 2) {
        const Step step = stepOf(ticks);
        if (scientific) {
            // Mantissas of the largest value's power of ten.
            const int power = static_cast<int>(std::floor(std::log10(largest)));
            decimals = std::max(0, power - step.exponent + (step.mantissa == 2.5 ? 1 : 0));
        } else {
            decimals = std::max(0, -step.exponent + (step.mantissa == 2.5 ? 1 : 0));
        }
    }
    std::vector<std::string> labels;
    for (const double value : ticks) {
        char text[48];
        if (ticks.size() < 2) {
            std::snprintf(text, sizeof text, "%.3g", value == 0.0 ? 0.0 : value);
        } else {
            std::snprintf(text, sizeof text, scientific ? "%.*e" : "%.*f", decimals,
                          value == 0.0 ? 0.0 : value);
        }
        std::string label = text;
        if (label.size() > 1 && label[0] == '-' &&
            label.find_first_not_of("-0.e+") == std::string::npos) {
            label.erase(0, 1); // "-0.00" is "0.00"
        }
        labels.push_back(label);
    }
    return labels;
}

glm::vec4 ColorLegend::inkFor(const glm::vec4& background) {
    if (background.a < 0.5f) {
        return {0.0f, 0.0f, 0.0f, 1.0f}; // a page of its own: the figure's usual black
    }
    // Rec. 709 luminance of the colour shown (premultiplied over nothing).
    const float luminance =
        0.2126f * background.r + 0.7152f * background.g + 0.0722f * background.b;
    return luminance > 0.5f ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(1.0f);
}

ColorLegend::ColorLegend(std::vector<ColorBar> bars, LegendStyle style, int width, int height)
    : mBars(std::move(bars)), mStyle(style), mWidth(width), mHeight(height),
      mFont(LabelFont::forImage(width, height)) {
    // Sizes follow the picture (`width` × `height`); mWidth and mHeight become the figure's.
    if (mBars.empty()) {
        throw DataError("colour legend: no colour bar to draw");
    }
    if (style.ticks < 2 || style.ticks > LegendStyle::kMaxTicks) {
        throw DataError("colour legend: the tick count must be from 2 to " +
                        std::to_string(LegendStyle::kMaxTicks) + ", got " +
                        std::to_string(style.ticks));
    }
    const int side = std::min(width, height);
    const int step = 1 + side / 256; // one more every 256 pixels
    const int margin = 4 * step + side / 64;
    mGap = 3 * step;
    const int thickness = std::max(6, side / 24);
    mTick = std::max(3, thickness / 3);
    mLine = std::max(1, side / 512);
    const int fontHeight = mFont.height();
    bool anyTitle = false;
    for (ColorBar& bar : mBars) {
        if (!bar.title.empty() && !mFont.canDraw(bar.title)) {
            log(LogLevel::Warning, "colour legend: the title '" + bar.title +
                                       "' is left out: the built-in bitmap font writes numbers "
                                       "only (install fonts-dejavu-core and rebuild)");
            bar.title.clear();
        }
        anyTitle = anyTitle || !bar.title.empty();
        Placed placed;
        placed.ticks = ticks(bar.range, style.ticks);
        placed.labels = tickLabels(placed.ticks);
        for (const std::string& label : placed.labels) {
            placed.labelWidth = std::max(placed.labelWidth, mFont.textWidth(label));
        }
        mPlaced.push_back(std::move(placed));
    }
    const int count = static_cast<int>(mBars.size());
    if (isVertical(style.position)) {
        // Per bar a column: the bar, its ticks, the labels and the title (mirrored on the left,
        // so the bar stays nearest the picture).
        std::vector<int> columns;
        int strip = 2 * margin + (count - 1) * 2 * mGap;
        for (int i = 0; i < count; ++i) {
            const int title = mBars[i].title.empty() ? 0 : mGap + fontHeight;
            columns.push_back(thickness + mTick + mGap + mPlaced[i].labelWidth + title);
            strip += columns.back();
        }
        mWidth = width + strip;
        const bool right = style.position == LegendPosition::Right;
        mData = {right ? 0 : strip, 0, width, height};
        const int barHeight = std::max(8, height - 2 * (height / 10));
        int cursor = right ? width + margin : strip - margin;
        for (int i = 0; i < count; ++i) {
            image::ImageRegion bar{0, (height - barHeight) / 2, thickness, barHeight};
            bar.x = right ? cursor : cursor - thickness;
            cursor += (right ? 1 : -1) * (columns[i] + 2 * mGap);
            mBarRegions.push_back(bar);
        }
    } else {
        const int title = anyTitle ? mGap + fontHeight : 0;
        const int strip = 2 * margin + thickness + mTick + mGap + fontHeight + title;
        mHeight = height + strip;
        const bool bottom = style.position == LegendPosition::Bottom;
        mData = {0, bottom ? 0 : strip, width, height};
        int spacing = 0;
        for (const Placed& placed : mPlaced) {
            spacing = std::max(spacing, placed.labelWidth + 2 * mGap);
        }
        const int available = width * 4 / 5;
        const int barWidth = std::max(8, (available - (count - 1) * spacing) / count);
        const int total = count * barWidth + (count - 1) * spacing;
        // The bar nearest the picture: below it at the bottom, above it at the top.
        const int y = bottom ? height + margin : strip - margin - thickness;
        for (int i = 0; i < count; ++i) {
            mBarRegions.push_back(
                {(width - total) / 2 + i * (barWidth + spacing), y, barWidth, thickness});
        }
    }
}

image::Image ColorLegend::compose(const image::Image& picture, const glm::vec4& background) const {
    image::Image figure(mWidth, mHeight);
    figure.fill(background);
    if (picture.hasDepth()) {
        figure.addDepth(1.0f);
    }
    const int width = std::min(picture.width(), mData.width);
    const int height = std::min(picture.height(), mData.height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            figure.setPixel(mData.x + x, mData.y + y, picture.pixel(x, y));
            if (picture.hasDepth()) {
                figure.setDepth(mData.x + x, mData.y + y, picture.depth(x, y));
            }
        }
    }
    const glm::vec4 ink = inkFor(background);
    for (std::size_t i = 0; i < mBars.size(); ++i) {
        draw(figure, i, ink);
    }
    return figure;
}

void ColorLegend::draw(image::Image& image, std::size_t index, const glm::vec4& ink) const {
    const ColorBar& colorBar = mBars[index];
    const Placed& placed = mPlaced[index];
    const image::ImageRegion& bar = mBarRegions[index];
    const bool vertical = isVertical(mStyle.position);
    const int length = vertical ? bar.height : bar.width;
    for (int i = 0; i < length; ++i) {
        // Pixel centres from t = 0 at the low end to t = 1 at the high end.
        const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(length);
        const glm::vec4 rgba(colorBar.colorMap(t), 1.0f);
        if (vertical) {
            fillRegion(image, {bar.x, bar.y + bar.height - 1 - i, bar.width, 1}, rgba);
        } else {
            fillRegion(image, {bar.x + i, bar.y, 1, bar.height}, rgba);
        }
    }
    // The frame, just outside the bar.
    fillRegion(image, {bar.x - mLine, bar.y - mLine, bar.width + 2 * mLine, mLine}, ink);
    fillRegion(image, {bar.x - mLine, bar.y + bar.height, bar.width + 2 * mLine, mLine}, ink);
    fillRegion(image, {bar.x - mLine, bar.y, mLine, bar.height}, ink);
    fillRegion(image, {bar.x + bar.width, bar.y, mLine, bar.height}, ink);

    // Ticks and labels on the side away from the picture.
    const bool outward = mStyle.position == LegendPosition::Right ||
                         mStyle.position == LegendPosition::Bottom;
    const int fontHeight = mFont.height();
    const double low = colorBar.range.x;
    const double span = double(colorBar.range.y) - low;
    for (std::size_t k = 0; k < placed.ticks.size(); ++k) {
        const double t = span != 0.0 ? (placed.ticks[k] - low) / span : 0.5;
        const int along = std::clamp(static_cast<int>(std::lround(t * length)) - mLine / 2, 0,
                                     std::max(0, length - mLine));
        const std::string& label = placed.labels[k];
        const int textWidth = mFont.textWidth(label);
        glm::ivec2 topLeft;
        if (vertical) {
            const int y = bar.y + bar.height - along - mLine;
            const int tickX = outward ? bar.x + bar.width : bar.x - mTick;
            fillRegion(image, {tickX, y, mTick, mLine}, ink);
            topLeft.x = outward ? tickX + mTick + mGap : tickX - mGap - textWidth;
            topLeft.y = keepInside(y + mLine / 2 - fontHeight / 2, fontHeight, image.height());
        } else {
            const int x = bar.x + along;
            const int tickY = outward ? bar.y + bar.height : bar.y - mTick;
            fillRegion(image, {x, tickY, mLine, mTick}, ink);
            topLeft.x = keepInside(x + mLine / 2 - textWidth / 2, textWidth, image.width());
            topLeft.y = outward ? tickY + mTick + mGap : tickY - mGap - fontHeight;
        }
        mFont.draw(image, topLeft, label, ink);
    }
    if (colorBar.title.empty()) {
        return;
    }
    const int titleWidth = mFont.textWidth(colorBar.title);
    if (vertical) {
        const int labels = mTick + mGap + placed.labelWidth + mGap;
        const int x = outward ? bar.x + bar.width + labels : bar.x - labels - fontHeight;
        const int y = keepInside(bar.y + (bar.height - titleWidth) / 2, titleWidth,
                                 image.height());
        mFont.draw(image, {x, y}, colorBar.title, ink, TextDirection::BottomToTop);
    } else {
        const int labels = mTick + mGap + fontHeight + mGap;
        const int y = outward ? bar.y + bar.height + labels : bar.y - labels - fontHeight;
        const int x = keepInside(bar.x + (bar.width - titleWidth) / 2, titleWidth, image.width());
        mFont.draw(image, {x, y}, colorBar.title, ink);
    }
}

} // namespace texsplat::annotation
