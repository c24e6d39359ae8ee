#pragma once

#include "nodes/image/Image.h"
#include "nodes/image/ImageRegion.h"
#include "scenegraph/Node.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <string>

namespace texsplat::annotation {

/// @brief Where a ColorLegend sits in the image: a vertical bar at the right or left edge, or a
/// horizontal one at the top or bottom edge.
enum class LegendPosition { Right, Left, Top, Bottom };

/// @brief The position named `name` ("right", "left", "top", "bottom").
/// @throws DataError naming the accepted names.
LegendPosition parseLegendPosition(const std::string& name);

/// @brief A colour legend of a transfer function: a bar of its colour map S(t) over t in [0, 1]
/// and the data values of the ends and the middle, drawn into a rendered image (after the
/// render, so every backend gets the same legend).
///
/// The bar is opaque (alpha 1, colour S(t) as the image stores colour: linear, so a PNG encodes
/// the bar like an opaque medium of that colour); lower values are at the bottom (vertical) or
/// left (horizontal). Labels are white with a black shadow, `%.3g` of the value, in the
/// LabelFont (DejaVu Sans, anti-aliased; the built-in NumberFont when the font file is missing),
/// on the right of a vertical bar and below a horizontal one. Sizes follow the image
/// (LabelFont::forImage(); margins grow by a step every 256 pixels of the smaller side).
class ColorLegend {
public:
    /// @brief The colour map S(t), t in [0, 1].
    using ColorMap = std::function<glm::vec3(float t)>;

    /// @brief A legend of `colorMap` labelled over `range` (range[0] at t = 0).
    ColorLegend(ColorMap colorMap, glm::vec2 range, LegendPosition position);

    /// @brief The legend of what the scene's first splat node draws (in traversal order): the
    /// TransferFunction in effect there over the range it uses for the data of the VolumeData in
    /// effect there (TransferFunction::dataScale; nodes::splatInputs()). Without such a splat
    /// node: the first TransferFunction over the first VolumeData's data, or over its `range`
    /// field when there is no VolumeData.
    /// @throws DataError when the scene has no TransferFunction; what reading the volume throws.
    static ColorLegend ofScene(sg::Node& root, LegendPosition position);

    /// @brief The labelled range.
    glm::vec2 range() const { return mRange; }

    /// @brief The rectangle of the bar in an image of `width` × `height`.
    image::ImageRegion barRegion(int width, int height) const;

    /// @brief Draws the legend into `image`, replacing the pixels it covers.
    void draw(image::Image& image) const;

    /// @brief The label text of `value`: `%.3g`, with "-0" written "0".
    static std::string label(double value);

private:
    ColorMap mColorMap;
    glm::vec2 mRange;
    LegendPosition mPosition;
};

} // namespace texsplat::annotation
