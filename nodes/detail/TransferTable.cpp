#include "nodes/detail/TransferTable.h"

#include "nodes/TransferFunction.h"
#include "nodes/colormap/ListedColormaps.h"
#include "nodes/image/detail/Viridis.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Random.h"

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace texsplat::nodes::detail {

template <class Y> Y PiecewiseLinear<Y>::operator()(float t) const {
    TEXSPLAT_ASSERT(!x.empty() && x.size() == y.size(),
                    "PiecewiseLinear::operator(): control points missing or unpaired");
    if (!(t > x.front())) {
        return y.front();
    }
    if (t >= x.back()) {
        return y.back();
    }
    const auto upper = std::upper_bound(x.begin(), x.end(), t);
    const std::size_t i = static_cast<std::size_t>(std::distance(x.begin(), upper));
    const float weight = (t - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + weight * (y[i] - y[i - 1]);
}

template struct PiecewiseLinear<float>;
template struct PiecewiseLinear<glm::vec3>;

namespace {

PiecewiseLinear<glm::vec3> evenlySpaced(std::vector<glm::vec3> colors) {
    PiecewiseLinear<glm::vec3> map;
    const std::size_t last = colors.size() - 1;
    for (std::size_t i = 0; i <= last; ++i) {
        map.x.push_back(static_cast<float>(i) / static_cast<float>(last));
    }
    map.y = std::move(colors);
    return map;
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
        PiecewiseLinear<glm::vec3> map;
        for (int entry = 0;; entry = std::min(entry + 8, 255)) {
            const float t = static_cast<float>(entry) / 255.0f;
            map.x.push_back(t);
            map.y.push_back(image::detail::viridis(t));
            if (entry == 255) {
                return map;
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
