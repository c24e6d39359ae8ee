#include "nodes/bench/FlowLegibility.h"

#include "nodes/image/Image.h"
#include "scenegraph/Random.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::bench {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// Central differences (one-sided at the borders), as NumPy's gradient.
glm::dvec2 gradient(const GrayImage& image, int x, int y) {
    const auto along = [&](int low, int high, float lowValue, float highValue) {
        return (double(highValue) - double(lowValue)) / std::max(high - low, 1);
    };
    const int left = std::max(x - 1, 0);
    const int right = std::min(x + 1, image.width - 1);
    const int up = std::max(y - 1, 0);
    const int down = std::min(y + 1, image.height - 1);
    return {along(left, right, image.at(left, y), image.at(right, y)),
            along(up, down, image.at(x, up), image.at(x, down))};
}

// `values` (width x height, row-major) convolved with a Gaussian of standard deviation `sigma`
// pixels, truncated at 3σ and normalized there; the borders clamp.
std::vector<double> gaussianBlur(const std::vector<double>& values, int width, int height,
                                 double sigma) {
    const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
    std::vector<double> weights(static_cast<std::size_t>(2 * radius + 1));
    double total = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        const double weight = std::exp(-0.5 * k * k / (sigma * sigma));
        weights[static_cast<std::size_t>(k + radius)] = weight;
        total += weight;
    }
    for (double& weight : weights) {
        weight /= total;
    }
    const auto at = [&](const std::vector<double>& source, int x, int y) {
        return source[static_cast<std::size_t>(std::clamp(y, 0, height - 1)) *
                          static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(std::clamp(x, 0, width - 1))];
    };
    std::vector<double> across(values.size());
    std::vector<double> result(values.size());
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<double>& source = pass == 0 ? values : across;
        std::vector<double>& target = pass == 0 ? across : result;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                double sum = 0.0;
                for (int k = -radius; k <= radius; ++k) {
                    sum += weights[static_cast<std::size_t>(k + radius)] *
                           (pass == 0 ? at(source, x + k, y) : at(source, x, y + k));
                }
                target[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                       static_cast<std::size_t>(x)] = sum;
            }
        }
    }
    return result;
}

// The value below which `fraction` of `values` lie (nearest rank).
double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) {
        return 0.0;
    }
    const auto rank = static_cast<std::ptrdiff_t>(
        std::min(values.size() - 1, static_cast<std::size_t>(fraction * values.size())));
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    return values[static_cast<std::size_t>(rank)];
}

} // namespace

GrayImage displayedLuminance(const image::Image& image, glm::vec3 background) {
    GrayImage gray;
    gray.width = image.width();
    gray.height = image.height();
    gray.values.resize(image.pixelCount());
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const glm::vec4& pixel = image.pixel(x, y);
            const glm::vec3 shown =
                glm::clamp(glm::vec3(pixel) + (1.0f - pixel.a) * background, 0.0f, 1.0f);
            gray.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(gray.width) +
                        static_cast<std::size_t>(x)] =
                0.2126f * shown.r + 0.7152f * shown.g + 0.0722f * shown.b;
        }
    }
    return gray;
}

StreakAngles streakAngles(const GrayImage& image, const ImageFlow& flow, double smoothing,
                          const std::function<bool(int x, int y)>& isMeasured) {
    const std::size_t count =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    std::vector<double> xx(count);
    std::vector<double> yy(count);
    std::vector<double> xy(count);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec2 g = gradient(image, x, y);
            const std::size_t at =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                static_cast<std::size_t>(x);
            xx[at] = g.x * g.x;
            yy[at] = g.y * g.y;
            xy[at] = g.x * g.y;
        }
    }
    xx = gaussianBlur(xx, image.width, image.height, smoothing);
    yy = gaussianBlur(yy, image.width, image.height, smoothing);
    xy = gaussianBlur(xy, image.width, image.height, smoothing);
    std::vector<double> angles;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec2 along(
                flow(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
            const double length = glm::length(along);
            if (!isMeasured(x, y) || !(length > 0.0)) {
                continue;
            }
            const std::size_t at =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                static_cast<std::size_t>(x);
            // The streaks run across the strongest gradient direction θ.
            const double theta = 0.5 * std::atan2(2.0 * xy[at], xx[at] - yy[at]);
            const glm::dvec2 streak(-std::sin(theta), std::cos(theta));
            const double cosine = std::abs(glm::dot(streak, along / length));
            angles.push_back(std::acos(std::min(cosine, 1.0)) * kDegrees);
        }
    }
    StreakAngles result;
    result.pixels = angles.size();
    result.median = percentile(angles, 0.5);
    result.percentile90 = percentile(angles, 0.9);
    return result;
}

double streakOrientation(const GrayImage& image,
                         const std::function<bool(int x, int y)>& isMeasured) {
    glm::dvec3 tensor(0.0); // xx, yy, xy
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (isMeasured(x, y)) {
                const glm::dvec2 g = gradient(image, x, y);
                tensor += glm::dvec3(g.x * g.x, g.y * g.y, g.x * g.y);
            }
        }
    }
    // The strongest gradient direction with y down, the streaks across it; then y up.
    const double theta = 0.5 * std::atan2(2.0 * tensor.z, tensor.x - tensor.y);
    const double streak = -(theta * kDegrees + 90.0);
    return std::fmod(std::fmod(streak, 180.0) + 180.0, 180.0);
}

double downstreamSkew(const GrayImage& image, const ImageFlow& flow,
                      const std::function<bool(int x, int y)>& isMeasured) {
    double second = 0.0;
    double third = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec2 along(
                flow(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
            const double length = glm::length(along);
            if (!isMeasured(x, y) || !(length > 0.0)) {
                continue;
            }
            const double derivative = glm::dot(gradient(image, x, y), along / length);
            second += derivative * derivative;
            third += derivative * derivative * derivative;
            ++count;
        }
    }
    if (count == 0 || !(second > 0.0)) {
        return 0.0;
    }
    const double n = static_cast<double>(count);
    return -(third / n) / std::pow(second / n, 1.5);
}

GrayImage lineIntegralConvolution(int width, int height, const ImageFlow& flow, int halfLength,
                                  std::uint32_t seed) {
    GrayImage noise;
    noise.width = width;
    noise.height = height;
    noise.values.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    sg::Random random(seed);
    for (float& value : noise.values) {
        value = static_cast<float>(random.uniform());
    }
    GrayImage result = noise;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            double sum = noise.at(x, y);
            int samples = 1;
            for (const float way : {1.0f, -1.0f}) {
                glm::vec2 at(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                for (int step = 0; step < halfLength; ++step) {
                    const glm::vec2 along = flow(at.x, at.y);
                    const float length = glm::length(along);
                    if (!(length > 0.0f)) {
                        break;
                    }
                    at += way * along / length;
                    const int column = static_cast<int>(std::floor(at.x));
                    const int row = static_cast<int>(std::floor(at.y));
                    if (column < 0 || row < 0 || column >= width || row >= height) {
                        break;
                    }
                    sum += noise.at(column, row);
                    ++samples;
                }
            }
            result.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                          static_cast<std::size_t>(x)] = static_cast<float>(sum / samples);
        }
    }
    return result;
}

} // namespace texsplat::bench
