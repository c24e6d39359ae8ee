#include "nodes/detail/TransferTable.h"

#include "nodes/TransferFunction.h"
#include "nodes/colormap/ListedColormaps.h"
#include "nodes/image/detail/Viridis.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Random.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <utility>

namespace texsplat::nodes::detail {

template <class Y>
PiecewiseLinear<Y>::PiecewiseLinear(std::vector<float> x, std::vector<Y> y)
    : mX(std::move(x)), mY(std::move(y)) {
    TEXSPLAT_ASSERT(mX.size() == mY.size(), "PiecewiseLinear: control points unpaired");
    const double width = mX.empty() ? 0.0 : double(mX.back()) - mX.front();
    if (!(width > 0.0) || mX.size() < 3) {
        return; // at most one segment, or a single step: nothing to index
    }
    // About four cells per segment: one or two steps from a cell's start to the segment.
    const std::size_t cells = std::min<std::size_t>(4 * mX.size(), 1 << 16);
    mCellsPerUnit = static_cast<float>(static_cast<double>(cells) / width);
    mCellStart.resize(cells);
    for (std::size_t cell = 0; cell < cells; ++cell) {
        const float edge = mX.front() + static_cast<float>(cell) / mCellsPerUnit;
        mCellStart[cell] = static_cast<std::uint32_t>(
            std::distance(mX.begin(), std::upper_bound(mX.begin(), mX.end(), edge)));
    }
}

template <class Y> Y PiecewiseLinear<Y>::operator()(float t) const {
    TEXSPLAT_ASSERT(!mX.empty() && mX.size() == mY.size(),
                    "PiecewiseLinear::operator(): control points missing or unpaired");
    if (!(t > mX.front())) {
        return mY.front();
    }
    if (t >= mX.back()) {
        return mY.back();
    }
    // i: the first point beyond t (std::upper_bound's answer), 1 <= i < size.
    std::size_t i = 0;
    if (mCellStart.empty()) {
        i = static_cast<std::size_t>(
            std::distance(mX.begin(), std::upper_bound(mX.begin(), mX.end(), t)));
    } else {
        const auto cell = std::min(static_cast<std::size_t>((t - mX.front()) * mCellsPerUnit),
                                   mCellStart.size() - 1);
        // From the cell's start, both ways: rounding may put t's cell one off.
        i = std::max<std::size_t>(mCellStart[cell], 1);
        while (mX[i - 1] > t) {
            --i;
        }
        while (mX[i] <= t) {
            ++i;
        }
    }
    const float weight = (t - mX[i - 1]) / (mX[i] - mX[i - 1]);
    return mY[i - 1] + weight * (mY[i] - mY[i - 1]);
}

template class PiecewiseLinear<float>;
template class PiecewiseLinear<glm::vec3>;

namespace {

PiecewiseLinear<glm::vec3> evenlySpaced(std::vector<glm::vec3> colors) {
    const std::size_t last = colors.size() - 1;
    std::vector<float> x;
    for (std::size_t i = 0; i <= last; ++i) {
        x.push_back(static_cast<float>(i) / static_cast<float>(last));
    }
    return {std::move(x), std::move(colors)};
}

// A listed colour map's 256 entries as control points at t = i / 255.
PiecewiseLinear<glm::vec3> listed(const colormap::ColorTable& table) {
    return evenlySpaced(std::vector<glm::vec3>(table.begin(), table.end()));
}

// A fixed integer hash (splitmix64's finalizer) mapped to [0, 1): the same noise everywhere.
float hashToUnit(std::uint64_t i) {
    const std::uint64_t z = sg::Random::mix(i + 0x9e3779b97f4a7c15ULL);
    return static_cast<float>(z >> 40U) / static_cast<float>(1ULL << 24U);
}

// The paper's Figure 5 colours the tornado "with a noisy brown color map": a dark-to-light brown
// ramp whose brightness jitters by +-20 % from one control point to the next.
PiecewiseLinear<glm::vec3> noisyBrowns() {
    constexpr int kPoints = 64;
    const glm::vec3 dark(0.25f, 0.13f, 0.05f);
    const glm::vec3 light(0.87f, 0.70f, 0.47f);
    std::vector<glm::vec3> colors;
    for (int i = 0; i < kPoints; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(kPoints - 1);
        const float jitter = 1.0f + 0.4f * (hashToUnit(static_cast<std::uint64_t>(i)) - 0.5f);
        colors.push_back(glm::min(glm::mix(dark, light, t) * jitter, glm::vec3(1.0f)));
    }
    return evenlySpaced(std::move(colors));
}

} // namespace

PiecewiseLinear<glm::vec3> presetColors(int preset) {
    switch (static_cast<ColorPreset>(preset)) {
    case ColorPreset::Gray:
        return evenlySpaced({glm::vec3(0.0f), glm::vec3(1.0f)});
    case ColorPreset::Hot:
        // Black through red and yellow to white, as matplotlib's "hot".
        return {{0.0f, 0.375f, 0.75f, 1.0f},
                {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.0f),
                 glm::vec3(1.0f)}};
    case ColorPreset::Viridis: {
        // The image library's viridis interpolates matplotlib's 256-entry table between every
        // 8th entry and the last: sample it exactly there to get the same map.
        std::vector<float> x;
        std::vector<glm::vec3> y;
        for (int entry = 0;; entry = std::min(entry + 8, 255)) {
            const float t = static_cast<float>(entry) / 255.0f;
            x.push_back(t);
            y.push_back(image::detail::viridis(t));
            if (entry == 255) {
                return {std::move(x), std::move(y)};
            }
        }
    }
    case ColorPreset::Browns:
        return noisyBrowns();
    case ColorPreset::CoolWarm:
        // Moreland's diverging blue-white-red map ("Diverging Color Maps for Scientific
        // Visualization", 2009) at t = 0, 1/4, ..., 1.
        return evenlySpaced({{0.230f, 0.299f, 0.754f},
                             {0.552f, 0.690f, 0.996f},
                             {0.865f, 0.865f, 0.865f},
                             {0.958f, 0.604f, 0.482f},
                             {0.706f, 0.016f, 0.150f}});
    case ColorPreset::Magma:
        return listed(colormap::magma());
    case ColorPreset::Inferno:
        return listed(colormap::inferno());
    case ColorPreset::Plasma:
        return listed(colormap::plasma());
    case ColorPreset::Cividis:
        return listed(colormap::cividis());
    case ColorPreset::Turbo:
        return listed(colormap::turbo());
    }
    TEXSPLAT_ASSERT(false, "presetColors(): unknown preset");
    return evenlySpaced({glm::vec3(0.0f), glm::vec3(1.0f)});
}

} // namespace texsplat::nodes::detail
