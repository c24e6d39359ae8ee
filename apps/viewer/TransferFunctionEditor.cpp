#include "apps/viewer/TransferFunctionEditor.h"

#include "nodes/actions/SplatInputs.h"
#include "nodes/detail/DataRange.h"
#include "nodes/volume/ValueHistogram.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/io/WriteAction.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace texsplat::apps {

namespace {

std::vector<sg::Path> pathsOfType(sg::Node& root, const sg::NodeType& type,
                                  sg::SearchAction::Interest interest) {
    sg::SearchAction search;
    search.setType(type);
    search.setInterest(interest);
    search.apply(root);
    return search.paths();
}

void checkFinite(glm::vec2 point) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y)) {
        throw DataError("transfer function editor: an opacity point must be finite, got " +
                        std::to_string(point.x) + " " + std::to_string(point.y));
    }
}

} // namespace

TransferFunctionEditor::TransferFunctionEditor(sg::Node& root) {
    for (const sg::Path& path :
         pathsOfType(root, nodes::TransferFunction::classType(), sg::SearchAction::Interest::All)) {
        auto node = std::static_pointer_cast<nodes::TransferFunction>(path.tail());
        const bool seen =
            std::any_of(mFunctions.begin(), mFunctions.end(),
                        [&](const Function& function) { return function.node == node; });
        if (seen) { // a USEd node is found once per path
            continue;
        }
        Function function;
        function.node = node;
        function.original = {node->range.value(),         node->range.isDefault(),
                             node->rangeMode.value(),     node->rangeMode.isDefault(),
                             node->opacityValues.values(), node->opacityValues.isDefault(),
                             node->opacities.values(),     node->opacities.isDefault(),
                             node->preset.value(),        node->preset.isDefault()};
        function.points = pointsOf(function.original);
        mFunctions.push_back(std::move(function));
    }
    findVolumes(root);
}

void TransferFunctionEditor::findVolumes(sg::Node& root) {
    const std::vector<nodes::SplatInput> inputs = nodes::splatInputs(root);
    const std::vector<sg::Path> first =
        pathsOfType(root, nodes::VolumeData::classType(), sg::SearchAction::Interest::First);
    for (Function& function : mFunctions) {
        const auto used = std::find_if(inputs.begin(), inputs.end(), [&](const auto& input) {
            return input.transfer == function.node.get();
        });
        if (used != inputs.end()) {
            function.volume = std::static_pointer_cast<const nodes::VolumeData>(
                used->volume->shared_from_this());
        } else if (!first.empty()) {
            function.volume =
                std::static_pointer_cast<const nodes::VolumeData>(first.front().tail());
        }
    }
}

std::vector<glm::vec2> TransferFunctionEditor::pointsOf(const Original& original) {
    std::vector<glm::vec2> points;
    if (original.opacityValues.size() == original.opacities.size()) {
        for (std::size_t index = 0; index < original.opacities.size(); ++index) {
            points.emplace_back(original.opacityValues[index], original.opacities[index]);
        }
    }
    return points;
}

std::string TransferFunctionEditor::label(std::size_t index) const {
    const std::string& name = mFunctions.at(index).node->name();
    return name.empty() ? "TransferFunction " + std::to_string(index + 1) : name;
}

void TransferFunctionEditor::select(std::size_t index) {
    if (index >= mFunctions.size()) {
        throw DataError("transfer function editor: no function " + std::to_string(index) +
                        " (the scene has " + std::to_string(mFunctions.size()) + ")");
    }
    mSelected = index;
}

bool TransferFunctionEditor::editsRange() const {
    const nodes::TransferFunction& node = *current().node;
    return !node.range.isConnected() && !node.rangeMode.isConnected();
}

glm::vec2 TransferFunctionEditor::range() {
    Function& function = current();
    if (!function.range) {
        const nodes::TransferFunction& node = *function.node;
        function.range = function.volume ? node.dataScale(*function.volume->scalarGrid()).range
                                         : node.range.value();
    }
    return *function.range;
}

glm::vec2 TransferFunctionEditor::dataRange() {
    Function& function = current();
    if (!function.dataRange) {
        if (function.volume) {
            function.dataRange =
                glm::vec2(nodes::detail::valueRange(*function.volume->scalarGrid()));
        } else {
            const glm::vec2 own = function.original.range;
            const float half = 0.5f * std::abs(own.y - own.x);
            function.dataRange =
                glm::vec2(std::min(own.x, own.y) - half, std::max(own.x, own.y) + half);
        }
    }
    return *function.dataRange;
}

glm::vec2 TransferFunctionEditor::rangeBounds() {
    const glm::vec2 data = dataRange();
    const glm::vec2 now = range();
    return {std::min(data.x, now.x), std::max(data.y, now.y)};
}

void TransferFunctionEditor::setRange(glm::vec2 range) {
    if (!std::isfinite(range.x) || !std::isfinite(range.y) || !(range.x < range.y)) {
        throw DataError("transfer function editor: a range must be finite and increasing, got " +
                        std::to_string(range.x) + " " + std::to_string(range.y));
    }
    Function& function = current();
    function.node->rangeMode.setValue(nodes::RangeMode::Fixed);
    function.node->range.setValue(range);
    function.range = range;
}

bool TransferFunctionEditor::editsOpacity() const {
    const Function& function = current();
    return !function.points.empty() && !function.node->opacities.isConnected() &&
           !function.node->opacityValues.isConnected();
}

void TransferFunctionEditor::moveOpacityPoint(std::size_t index, glm::vec2 point) {
    checkFinite(point);
    std::vector<glm::vec2>& points = current().points;
    if (index >= points.size()) {
        throw DataError("transfer function editor: no opacity point " + std::to_string(index));
    }
    const float lowest = index > 0 ? points[index - 1].x : 0.0f;
    const float highest = index + 1 < points.size() ? points[index + 1].x : 1.0f;
    points[index] = glm::vec2(std::clamp(point.x, lowest, highest), std::max(point.y, 0.0f));
    writeOpacities();
}

std::size_t TransferFunctionEditor::addOpacityPoint(glm::vec2 point) {
    checkFinite(point);
    std::vector<glm::vec2>& points = current().points;
    const glm::vec2 added(std::clamp(point.x, 0.0f, 1.0f), std::max(point.y, 0.0f));
    const auto after = std::upper_bound(points.begin(), points.end(), added,
                                        [](glm::vec2 a, glm::vec2 b) { return a.x < b.x; });
    const auto index = static_cast<std::size_t>(after - points.begin());
    points.insert(after, added);
    writeOpacities();
    return index;
}

void TransferFunctionEditor::removeOpacityPoint(std::size_t index) {
    std::vector<glm::vec2>& points = current().points;
    if (index >= points.size()) {
        throw DataError("transfer function editor: no opacity point " + std::to_string(index));
    }
    if (points.size() > 1) {
        points.erase(points.begin() + static_cast<std::ptrdiff_t>(index));
        writeOpacities();
    }
}

float TransferFunctionEditor::opacityFactor() const { return current().opacityFactor; }

void TransferFunctionEditor::setOpacityFactor(float factor) {
    if (!std::isfinite(factor) || !(factor > 0.0f)) {
        throw DataError("transfer function editor: an opacity factor must be finite and > 0, got " +
                        std::to_string(factor));
    }
    current().opacityFactor = factor;
    writeOpacities();
}

void TransferFunctionEditor::writeOpacities() {
    Function& function = current();
    std::vector<float> positions;
    std::vector<float> opacities;
    for (const glm::vec2 point : function.points) {
        positions.push_back(point.x);
        opacities.push_back(point.y * function.opacityFactor);
    }
    // Both fields before the function is used again: it checks that their sizes match then.
    if (function.node->opacityValues.values() != positions) {
        function.node->opacityValues.setValue(std::move(positions));
    }
    function.node->opacities.setValue(std::move(opacities));
}

const std::vector<std::uint64_t>& TransferFunctionEditor::histogram(std::size_t bins) {
    Function& function = current();
    if (function.histogram.size() != bins) {
        const glm::vec2 data = dataRange();
        function.histogram =
            function.volume
                ? volume::valueHistogram(*function.volume->scalarGrid(), data.x, data.y, bins)
                : std::vector<std::uint64_t>(bins, 0);
    }
    return function.histogram;
}

bool TransferFunctionEditor::editsPreset() const {
    const nodes::TransferFunction& node = *current().node;
    return node.colors.isEmpty() && node.colorMapFile.value().empty() && !node.preset.isConnected();
}

nodes::ColorPreset TransferFunctionEditor::preset() const {
    return current().node->preset.as<nodes::ColorPreset>();
}

void TransferFunctionEditor::setPreset(nodes::ColorPreset preset) {
    current().node->preset.setValue(preset);
}

std::string TransferFunctionEditor::sceneText() const {
    std::string text = sg::WriteAction::writeString(*current().node);
    // The writer starts a file: "#Inventor V2.1 ascii" and a blank line.
    const std::size_t body = text.find_first_not_of('\n', text.find('\n'));
    return body == std::string::npos ? text : text.substr(body);
}

bool TransferFunctionEditor::isEdited() const {
    const Function& function = current();
    const nodes::TransferFunction& node = *function.node;
    const Original& original = function.original;
    return node.range.value() != original.range || node.rangeMode.value() != original.rangeMode ||
           node.opacityValues.values() != original.opacityValues ||
           node.opacities.values() != original.opacities || node.preset.value() != original.preset;
}

void TransferFunctionEditor::reset() {
    Function& function = current();
    nodes::TransferFunction& node = *function.node;
    const Original& original = function.original;
    // Only what changed is set (each set notifies); the default flags come back with the
    // values, since AUTO takes the range from the data while `range` is default.
    if (node.range.value() != original.range || node.range.isDefault() != original.rangeIsDefault) {
        node.range.setValue(original.range);
        node.range.setDefault(original.rangeIsDefault);
    }
    if (node.rangeMode.value() != original.rangeMode ||
        node.rangeMode.isDefault() != original.rangeModeIsDefault) {
        node.rangeMode.setValue(original.rangeMode);
        node.rangeMode.setDefault(original.rangeModeIsDefault);
    }
    if (node.opacityValues.values() != original.opacityValues) {
        node.opacityValues.setValue(original.opacityValues);
        node.opacityValues.setDefault(original.opacityValuesIsDefault);
    }
    if (node.opacities.values() != original.opacities) {
        node.opacities.setValue(original.opacities);
        node.opacities.setDefault(original.opacitiesIsDefault);
    }
    if (node.preset.value() != original.preset) {
        node.preset.setValue(original.preset);
        node.preset.setDefault(original.presetIsDefault);
    }
    function.points = pointsOf(original);
    function.opacityFactor = 1.0f;
    function.range.reset();
}

} // namespace texsplat::apps
