#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace texsplat::image {
class Image;
}

namespace texsplat::bench {

/// @brief A gray image as a legibility measure reads it: `width` x `height` values, row-major,
/// the top row first.
struct GrayImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;

    /// @brief The value at column x, row y.
    float at(int x, int y) const {
        return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

/// @brief A flow in the image's pixel space: its direction at a pixel centre (x to the right, y
/// down, pixel (i, j) covering [i, i + 1) × [j, j + 1)); any length, (0, 0) where there is none.
using ImageFlow = std::function<glm::vec2(float x, float y)>;

/// @brief The luminance (Rec. 709 weights on the display values) of `image` composited over an
/// opaque `background`: what a reader sees of a PNG.
GrayImage displayedLuminance(const image::Image& image, glm::vec3 background = glm::vec3(0.0f));

/// @brief How closely the streaks of a picture follow a flow: per pixel, the angle between the
/// image's local streak direction and the flow there, in degrees (0 to 90; a line has no sign).
struct StreakAngles {
    double median = 0.0;       ///< of the pixels measured
    double percentile90 = 0.0; ///< 90 % of the pixels are within this
    std::size_t pixels = 0;    ///< how many were measured
};

/// @brief The streak angles of `image` against `flow` over the pixels where `isMeasured(x, y)`
/// (pixel indices) and the flow is not zero.
///
/// The measure (docs/results.md, "Legibility of vector marks"): the structure tensor of the
/// image, J = G_σ * (∇I ∇Iᵀ), with ∇I by central differences and G_σ a Gaussian of standard
/// deviation `smoothing` pixels (half a voxel's width on screen smooths over about a voxel);
/// the streaks run across J's strongest direction θ = ½ atan2(2J_xy, J_xx − J_yy). Central
/// differences read thin lines turned towards the diagonals (a line 1.5 pixels wide at 30° reads
/// as about 34°), so the measure is a hard one; a line integral convolution of the same flow
/// (lineIntegralConvolution()) scores about 8° on it.
StreakAngles streakAngles(const GrayImage& image, const ImageFlow& flow, double smoothing,
                          const std::function<bool(int x, int y)>& isMeasured);

/// @brief The direction of the streaks of `image` over the pixels where `isMeasured(x, y)`, in
/// degrees in [0, 180), counter-clockwise from +x with y up (as on a page): the structure
/// tensor of central differences summed over them, for a uniform flow.
double streakOrientation(const GrayImage& image,
                         const std::function<bool(int x, int y)>& isMeasured);

/// @brief Which way the marks of `image` point along `flow`, over the pixels where
/// `isMeasured(x, y)`: −skewness of the derivative of the image along the flow's unit direction
/// (central differences). Marks whose intensity rises slowly downstream and falls sharply at
/// their head (oriented line integral convolution; render::markProfile()) give a positive value;
/// symmetric marks about 0; marks pointing upstream a negative one.
double downstreamSkew(const GrayImage& image, const ImageFlow& flow,
                      const std::function<bool(int x, int y)>& isMeasured);

/// @brief A line integral convolution of `flow` (Cabral & Leedom 1993), the reference a reader
/// compares flow textures with: white noise (uniform in [0, 1], one value per pixel, from
/// `seed`) averaged along the flow's streamline through each pixel, `halfLength` unit steps each
/// way (Euler steps, nearest-pixel lookups). Where the flow is zero the noise is left as it is.
GrayImage lineIntegralConvolution(int width, int height, const ImageFlow& flow, int halfLength,
                                  std::uint32_t seed = 1);

} // namespace texsplat::bench
