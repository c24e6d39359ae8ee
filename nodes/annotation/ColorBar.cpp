#include "nodes/annotation/ColorBar.h"

#include "nodes/TransferFunction.h"
#include "nodes/VectorSplat.h"
#include "nodes/VolumeData.h"
#include "nodes/actions/SplatInputs.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <tuple>

namespace texsplat::annotation {
namespace {

template <class T> std::shared_ptr<T> firstOfType(sg::Node& root) {
    sg::SearchAction search;
    search.setType(T::classType());
    search.apply(root);
    return search.paths().empty() ? nullptr
                                  : std::dynamic_pointer_cast<T>(search.paths().front().tail());
}

// What a bar stands for: the transfer function's colours over a range, titled.
struct Scale {
    std::shared_ptr<const nodes::TransferFunction> transfer;
    glm::vec2 range;
    std::string title;

    bool operator==(const Scale& other) const {
        return std::tie(transfer, range, title) ==
               std::tie(other.transfer, other.range, other.title);
    }
};

// What `volume` holds, its refusals located at its line in the scene file, as a render's are
// (the bars are made outside a traversal).
volume::ScalarGridPtr scalarsOf(const nodes::VolumeData& volume) {
    return sg::withNodeLocation(volume, [&volume] { return volume.scalarGrid(); });
}

// The range `transfer` uses for `grid`, its refusals located at its line.
template <class Grid>
glm::vec2 rangeOf(const nodes::TransferFunction& transfer, const Grid& grid) {
    return sg::withNodeLocation(transfer, [&] { return transfer.dataScale(grid).range; });
}

// `preferred`, or `fallback` when it is empty.
std::string either(const std::string& preferred, const std::string& fallback) {
    return preferred.empty() ? fallback : preferred;
}

// The scale `input`'s splat node colours by; nothing for constant colour.
std::optional<Scale> scaleOf(const nodes::SplatInput& input) {
    Scale scale;
    scale.transfer = std::static_pointer_cast<const nodes::TransferFunction>(
        input.transfer->shared_from_this());
    const nodes::TransferFunction& transfer = *input.transfer;
    const std::string titled =
        ColorBar::titleOf(transfer.title.value(), transfer.units.value());
    const auto* vectors = dynamic_cast<const nodes::VectorSplat*>(input.splat);
    if (!vectors) {
        scale.range = rangeOf(transfer, *scalarsOf(*input.volume));
        scale.title = titled;
        return scale;
    }
    switch (vectors->colorMode.as<nodes::VectorColorMode>()) {
    case nodes::VectorColorMode::Magnitude:
        scale.range = rangeOf(transfer, *sg::withNodeLocation(*input.volume, [&] {
            return input.volume->vectorGrid();
        }));
        scale.title = either(titled, "magnitude");
        return scale;
    case nodes::VectorColorMode::Scalar: {
        const auto* colors =
            dynamic_cast<const nodes::VolumeData*>(vectors->colorData.value().get());
        if (!colors) {
            return std::nullopt; // the node refuses to draw without it
        }
        scale.range = rangeOf(transfer, *scalarsOf(*colors));
        scale.title = either(titled, colors->name());
        return scale;
    }
    case nodes::VectorColorMode::Position:
        scale.range = vectors->positionRange.value();
        scale.title = either(titled, std::string(1, "xyz"[static_cast<int>(
                                                        vectors->positionAxis.as<nodes::Axis>())]));
        return scale;
    case nodes::VectorColorMode::Constant:
        break;
    }
    return std::nullopt;
}

ColorBar barOf(const Scale& scale) {
    const std::shared_ptr<const nodes::TransferFunction> transfer = scale.transfer;
    return {[transfer](float t) { return transfer->colorAt(t); }, scale.range, scale.title};
}

} // namespace

std::string ColorBar::titleOf(const std::string& title, const std::string& units) {
    if (title.empty() || units.empty()) {
        return title + units;
    }
    return title + " (" + units + ")";
}

std::vector<ColorBar> ColorBar::ofScene(sg::Node& root) {
    std::vector<Scale> scales;
    const std::vector<nodes::SplatInput> inputs = nodes::splatInputs(root);
    for (const nodes::SplatInput& input : inputs) {
        const std::optional<Scale> scale = scaleOf(input);
        if (scale && std::find(scales.begin(), scales.end(), *scale) == scales.end()) {
            scales.push_back(*scale);
        }
    }
    if (inputs.empty()) {
        const std::shared_ptr<nodes::TransferFunction> transfer =
            firstOfType<nodes::TransferFunction>(root);
        if (!transfer) {
            throw DataError("colour legend: the scene has no TransferFunction");
        }
        const std::shared_ptr<nodes::VolumeData> volume = firstOfType<nodes::VolumeData>(root);
        const volume::ScalarGridPtr grid = volume ? scalarsOf(*volume) : nullptr;
        scales.push_back({transfer,
                          grid ? rangeOf(*transfer, *grid) : transfer->range.value(),
                          titleOf(transfer->title.value(), transfer->units.value())});
    }
    std::vector<ColorBar> bars;
    for (const Scale& scale : scales) {
        bars.push_back(barOf(scale));
    }
    return bars;
}

} // namespace texsplat::annotation
