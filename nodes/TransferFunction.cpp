#include "nodes/TransferFunction.h"

#include "nodes/detail/ColorText.h"
#include "nodes/detail/NodeContext.h"
#include "nodes/detail/TransferTable.h"
#include "nodes/elements/TransferFunctionElement.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/fields/ValueFormat.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace texsplat::nodes {

TransferFunction::TransferFunction() {
    addField(preset, "preset", ColorPreset::Gray, kColorPresetNames);
    addField(colorValues, "colorValues", std::vector<float>{});
    addField(colors, "colors", std::vector<glm::vec3>{});
    addField(opacityValues, "opacityValues", std::vector<float>{0.0f, 1.0f});
    addField(opacities, "opacities", std::vector<float>{0.0f, 1.0f});
    addField(range, "range", glm::vec2(0.0f, 1.0f));
    addField(emission, "emission", 0.0f);
}

namespace {

std::string element(const sg::Field& field, std::size_t index) {
    return field.name() + "[" + std::to_string(index) + "]";
}

// Checks a pair of control-point fields and returns them as one piecewise-linear map.
template <class Y, class Field, class CheckValue>
detail::PiecewiseLinear<Y> controlPoints(const std::string& context, const sg::MFFloat& positions,
                                         const Field& values, CheckValue checkValue) {
    if (positions.size() != values.size()) {
        throw DataError(context + ": " + positions.name() + " has " +
                        std::to_string(positions.size()) + " values but " + values.name() +
                        " has " + std::to_string(values.size()));
    }
    if (positions.isEmpty()) {
        throw DataError(context + ": " + positions.name() + " and " + values.name() +
                        " are empty; give at least one control point");
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const float x = positions[i];
        if (!std::isfinite(x)) {
            throw DataError(context + ": " + element(positions, i) + " must be finite, got " +
                            sg::formatFloat(x));
        }
        if (i > 0 && x < positions[i - 1]) {
            throw DataError(context + ": " + positions.name() + " must not decrease, but " +
                            element(positions, i) + " = " + sg::formatFloat(x) + " follows " +
                            sg::formatFloat(positions[i - 1]));
        }
        checkValue(i);
    }
    return {positions.values(), values.values()};
}

} // namespace

std::shared_ptr<const detail::TransferTable> TransferFunction::buildTable() const {
    const std::string context = detail::nodeContext(*this);
    auto table = std::make_shared<detail::TransferTable>();

    const glm::vec2 bounds = range.value();
    if (!std::isfinite(bounds.x) || !std::isfinite(bounds.y) || !(bounds.x < bounds.y)) {
        throw DataError(context + ": range must be finite with range[0] < range[1], got " +
                        range.valueText());
    }
    table->rangeMin = bounds.x;
    table->rangeMax = bounds.y;

    if (colorValues.isEmpty() && colors.isEmpty()) {
        table->colors = detail::presetColors(preset.value());
    } else {
        table->colors = controlPoints<glm::vec3>(context, colorValues, colors, [&](std::size_t i) {
            const glm::vec3& color = colors[i];
            if (!detail::isFiniteColor(color) || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) {
                throw DataError(context + ": " + element(colors, i) +
                                " must be finite and not negative, got " +
                                detail::formatColor(color));
            }
        });
    }
    table->opacities = controlPoints<float>(context, opacityValues, opacities, [&](std::size_t i) {
        const float tau = opacities[i];
        if (!std::isfinite(tau) || tau < 0.0f) {
            throw DataError(context + ": " + element(opacities, i) +
                            " must be finite and not negative (opacity per unit length), got " +
                            sg::formatFloat(tau));
        }
    });

    const float glow = emission.value();
    if (!std::isfinite(glow) || glow < 0.0f) {
        throw DataError(context + ": emission must be finite and not negative, got " +
                        sg::formatFloat(glow));
    }
    table->emission = glow;
    return table;
}

std::shared_ptr<const detail::TransferTable> TransferFunction::table() const {
    const std::lock_guard<std::mutex> lock(mTableMutex);
    if (!mTable) {
        mTable = buildTable();
    }
    return mTable;
}

void TransferFunction::validate() const { table(); }

namespace {

// `value` normalized over the range and clamped to [0, 1]; NaN stays NaN.
float normalized(const detail::TransferTable& table, float value) {
    // In double: the difference of two large floats may overflow float.
    const double t = (double(value) - table.rangeMin) / (double(table.rangeMax) - table.rangeMin);
    return std::isnan(t) ? t : static_cast<float>(std::clamp(t, 0.0, 1.0));
}

Classification classifyWith(const detail::TransferTable& table, float value) {
    if (std::isnan(value)) {
        return {};
    }
    const float clamped = normalized(table, value);
    const float tau = table.opacities(clamped);
    return {table.colors(clamped) * (tau + table.emission), tau};
}

} // namespace

Classification TransferFunction::classify(float value) const {
    return classifyWith(*table(), value);
}

glm::vec3 TransferFunction::color(float value) const {
    if (std::isnan(value)) {
        return glm::vec3(0.0f);
    }
    const std::shared_ptr<const detail::TransferTable> checked = table();
    return checked->colors(normalized(*checked, value));
}

std::shared_ptr<octree::ClassifiedGrid>
TransferFunction::classify(const volume::ScalarGrid& grid) const {
    const std::shared_ptr<const detail::TransferTable> checked = table();
    const volume::GridGeometry& geometry = grid.geometry();
    auto classified = std::make_shared<octree::ClassifiedGrid>(
        glm::u64vec3(geometry.dims()), geometry.spacing(), geometry.origin());
    grid.forEachActive([&](const glm::i64vec3& index, float value) {
        const Classification result = classifyWith(*checked, value);
        if (result.extinction != 0.0f || result.color != glm::vec3(0.0f)) {
            classified->setVoxel(glm::u64vec3(index), result.color, result.extinction);
        }
    });
    return classified;
}

void TransferFunction::doAction(sg::Action& action) {
    action.state().modify<TransferFunctionElement>().transferFunction = this;
}

void TransferFunction::notify(const sg::Field* source) {
    {
        const std::lock_guard<std::mutex> lock(mTableMutex);
        mTable.reset();
    }
    sg::Node::notify(source);
}

} // namespace texsplat::nodes
