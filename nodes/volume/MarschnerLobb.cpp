#include "nodes/volume/MarschnerLobb.h"

#include "nodes/volume/detail/Format.h"
#include "nodes/volume/detail/Sampling.h"
#include "scenegraph/Error.h"

#include <cmath>

namespace texsplat::volume {

double marschnerLobb(const glm::dvec3& position, double modulationFrequency, double alpha) {
    constexpr double kPi = 3.14159265358979323846;
    const double radius = std::sqrt(position.x * position.x + position.y * position.y);
    const double radial = std::cos(2.0 * kPi * modulationFrequency * std::cos(kPi * radius / 2.0));
    return (1.0 - std::sin(kPi * position.z / 2.0) + alpha * (1.0 + radial)) /
           (2.0 * (1.0 + alpha));
}

ScalarGridPtr generateMarschnerLobb(const MarschnerLobbParameters& parameters,
                                    const std::optional<IndexBox>& region) {
    if (!std::isfinite(parameters.modulationFrequency))
        throw DataError("marschner-lobb: modulation frequency must be finite, got " +
                        detail::formatNumber(parameters.modulationFrequency));
    if (!std::isfinite(parameters.alpha) || parameters.alpha < 0.0)
        throw DataError("marschner-lobb: alpha must be finite and at least 0, got " +
                        detail::formatNumber(parameters.alpha));
    const GridGeometry geometry = detail::generatorGeometry(
        "marschner-lobb", parameters.dims, glm::dvec3(-1.0), glm::dvec3(1.0));
    return detail::sampleGrid<float>(
        geometry,
        [&](const glm::dvec3& position) {
            return marschnerLobb(position, parameters.modulationFrequency, parameters.alpha);
        },
        region);
}

} // namespace texsplat::volume
