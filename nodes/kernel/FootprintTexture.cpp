#include "nodes/kernel/FootprintTexture.h"

#include "nodes/image/GrayPfm.h"
#include "nodes/kernel/detail/BilinearSample.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/Error.h"
#include "scenegraph/FileExtension.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace texsplat::kernel {

namespace {

constexpr int kMaxResolution = 8192;

} // namespace

void FootprintTexture::checkExtent(double extent) {
    if (!(extent > 0.0 && extent <= kMaxExtent)) {
        std::ostringstream message;
        message << "footprint texture: extent " << extent << " must be in (0, " << kMaxExtent
                << "] voxels";
        throw DataError(message.str());
    }
}

void FootprintTexture::checkPath(const std::string& path) {
    requireFileExtension(path, {".pfm", ".exr", ".png"}, "texture");
    if (fileExtension(path) != ".pfm")
        image::supportedImageFormatOf(path);
}

FootprintTexture::FootprintTexture(int resolution, double extent, std::vector<float> texels)
    : mResolution(resolution), mExtent(extent), mTexels(std::move(texels)),
      mReach(farthestReach()) {}

FootprintTexture::FootprintTexture(const RadialKernel& kernel, int resolution, double extent)
    : mResolution(resolution), mExtent(extent) {
    if (resolution < 2 || resolution > kMaxResolution) {
        std::ostringstream message;
        message << "footprint texture: resolution " << resolution << " must be in [2, "
                << kMaxResolution << "]";
        throw DataError(message.str());
    }
    checkExtent(extent);
    const double texel = 2.0 * extent / resolution;
    mTexels.resize(static_cast<size_t>(resolution) * resolution);
    for (int row = 0; row < resolution; ++row)
        for (int column = 0; column < resolution; ++column)
            mTexels[static_cast<size_t>(row) * resolution + column] = static_cast<float>(
                kernel.footprint(std::hypot(-extent + (column + 0.5) * texel,
                                            -extent + (row + 0.5) * texel)));
    mReach = farthestReach();
}

double FootprintTexture::farthestReach() const {
    const double texel = 2.0 * mExtent / mResolution;
    double farthest = -std::numeric_limits<double>::infinity();
    for (int row = 0; row < mResolution; ++row)
        for (int column = 0; column < mResolution; ++column)
            if (mTexels[static_cast<size_t>(row) * mResolution + column] != 0.0f)
                farthest = std::max(farthest, std::hypot(-mExtent + (column + 0.5) * texel,
                                                         -mExtent + (row + 0.5) * texel));
    // A lookup blends the four texels around it, so it reaches a diagonal past their centres.
    return std::clamp(farthest + texel * std::sqrt(2.0), 0.0, mExtent * std::sqrt(2.0));
}

FootprintTexture FootprintTexture::gouraudFan(const RadialKernel& kernel, double extent,
                                              int radialSamples, int azimuthSamples,
                                              int resolution) {
    if (radialSamples < 2 || azimuthSamples < 3) {
        throw DataError("polygonal splat: needs at least 2 radial and 3 azimuth samples, got " +
                        std::to_string(radialSamples) + " and " + std::to_string(azimuthSamples));
    }
    // Start from the exact footprint texture: it checks the resolution and extent.
    FootprintTexture result(kernel, resolution, extent);
    const int rings = radialSamples - 1;
    std::vector<double> ringValue(static_cast<std::size_t>(rings) + 1);
    for (int ring = 0; ring <= rings; ++ring) {
        ringValue[static_cast<std::size_t>(ring)] =
            kernel.footprint(extent * static_cast<double>(ring) / rings);
    }
    const double sector = 2.0 * std::acos(-1.0) / azimuthSamples;
    // Vertex (ring, spoke) of the fan in units of the extent, with its footprint.
    struct Vertex {
        double x, y, value;
    };
    const auto vertex = [&](int ring, int spoke) {
        const double radius = static_cast<double>(ring) / rings;
        const double angle = sector * (spoke % azimuthSamples);
        return Vertex{radius * std::cos(angle), radius * std::sin(angle),
                      ringValue[static_cast<std::size_t>(ring)]};
    };
    // The linear interpolation over triangle abc at (x, y), when (x, y) lies in it.
    const auto interpolate = [](const Vertex& a, const Vertex& b, const Vertex& c, double x,
                                double y) -> std::optional<double> {
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const double u = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / area;
        const double v = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / area;
        const double w = 1.0 - u - v;
        constexpr double kEdge = -1e-12;
        if (u < kEdge || v < kEdge || w < kEdge) {
            return std::nullopt;
        }
        return u * a.value + v * b.value + w * c.value;
    };
    const double texel = 2.0 / resolution;
    for (int row = 0; row < resolution; ++row) {
        for (int column = 0; column < resolution; ++column) {
            const double x = -1.0 + (column + 0.5) * texel;
            const double y = -1.0 + (row + 0.5) * texel;
            double angle = std::atan2(y, x);
            angle += angle < 0.0 ? 2.0 * std::acos(-1.0) : 0.0;
            const int spoke = std::min(static_cast<int>(angle / sector), azimuthSamples - 1);
            std::optional<double> value =
                interpolate(vertex(0, 0), vertex(1, spoke), vertex(1, spoke + 1), x, y);
            for (int ring = 1; ring < rings && !value; ++ring) {
                value = interpolate(vertex(ring, spoke), vertex(ring + 1, spoke),
                                    vertex(ring + 1, spoke + 1), x, y);
                if (!value) {
                    value = interpolate(vertex(ring, spoke), vertex(ring + 1, spoke + 1),
                                        vertex(ring, spoke + 1), x, y);
                }
            }
            result.mTexels[static_cast<std::size_t>(row) * resolution + column] =
                static_cast<float>(value.value_or(0.0));
        }
    }
    result.mReach = result.farthestReach();
    return result;
}

FootprintTexture FootprintTexture::quantizedTo8Bits() const {
    const float peak = *std::max_element(mTexels.begin(), mTexels.end());
    std::vector<float> levels(mTexels.size());
    std::transform(mTexels.begin(), mTexels.end(), levels.begin(), [peak](float value) {
        return peak > 0.0f ? std::round(value / peak * 255.0f) / 255.0f * peak : value;
    });
    return FootprintTexture(mResolution, mExtent, std::move(levels));
}

double FootprintTexture::sample(const std::array<double, 2>& point) const {
    return detail::bilinearSample(point[0], point[1], mExtent, mResolution, [&](int i, int j) {
        return static_cast<double>(mTexels[static_cast<std::size_t>(j) * mResolution +
                                           static_cast<std::size_t>(i)]);
    });
}

TextureRipple FootprintTexture::measureLayerRipple(const RadialKernel& kernel,
                                                   int samplesPerSide) const {
    if (kernel.support() > kMaxExtent) {
        std::ostringstream message;
        message << "footprint texture: kernel support " << kernel.support() << " must be at most "
                << kMaxExtent << " voxels to measure the layer ripple";
        throw DataError(message.str());
    }
    TextureRipple ripple{-HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, 0.0};
    const int reach = static_cast<int>(std::ceil(std::max(mExtent, kernel.support()))) + 1;
    for (int a = 0; a < samplesPerSide; ++a)
        for (int b = 0; b < samplesPerSide; ++b) {
            // Points of [0, ½]², the fundamental region of the layer sum's symmetry.
            const double x = 0.5 * a / (samplesPerSide - 1);
            const double y = 0.5 * b / (samplesPerSide - 1);
            double textured = 0.0;
            double exact = 0.0;
            for (int i = -reach; i <= reach; ++i)
                for (int j = -reach; j <= reach; ++j) {
                    textured += sample({x - i, y - j});
                    exact += kernel.footprint(std::hypot(x - i, y - j));
                }
            ripple.max = std::max(ripple.max, textured);
            ripple.min = std::min(ripple.min, textured);
            ripple.exactMax = std::max(ripple.exactMax, exact);
            ripple.exactMin = std::min(ripple.exactMin, exact);
            ripple.maxError = std::max(ripple.maxError, std::fabs(textured - exact));
        }
    return ripple;
}

void FootprintTexture::write(const std::string& path) const {
    checkPath(path);
    if (fileExtension(path) == ".pfm") {
        image::writeGrayPfm(path, mResolution, mResolution, mTexels);
        return;
    }
    image::Image image(mResolution, mResolution);
    for (int row = 0; row < mResolution; ++row)
        for (int column = 0; column < mResolution; ++column)
            image.setPixel(column, mResolution - 1 - row,
                           glm::vec4(mTexels[static_cast<size_t>(row) * mResolution + column]));
    image::writeImage(image, path);
}

} // namespace texsplat::kernel
