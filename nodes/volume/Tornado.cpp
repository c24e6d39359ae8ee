#include "nodes/volume/Tornado.h"

#include "nodes/volume/detail/Format.h"
#include "nodes/volume/detail/Sampling.h"
#include "scenegraph/Error.h"

#include <cmath>

namespace texsplat::volume {

glm::dvec3 tornadoVelocity(const glm::dvec3& position, double time) {
    // Crawfis's tornadoSrc.c, term for term; his names are kept so the two can be compared.
    constexpr double kSmall = 1e-11;
    const double x = position.x;
    const double y = position.y;
    const double z = position.z;
    const double xc = 0.5 + 0.1 * std::sin(0.04 * time + 10.0 * z);
    const double yc = 0.5 + 0.1 * std::cos(0.03 * time + 3.0 * z);
    const double r = 0.1 + 0.4 * z * z + 0.1 * z * std::sin(8.0 * z);
    const double r2 = 0.2 + 0.1 * z;
    double temp = std::sqrt((y - yc) * (y - yc) + (x - xc) * (x - xc));
    double scale = std::fabs(r - temp);
    // The original's own comment: this step makes the magnitude discontinuous at |r - temp| = r2.
    // Kept, because the point of this generator is to reproduce the classic data set.
    scale = scale > r2 ? 0.8 - scale : 1.0;
    double z0 = 0.1 * (0.1 - temp * z);
    if (z0 < 0.0)
        z0 = 0.0;
    temp = std::sqrt(temp * temp + z0 * z0);
    scale = (r + r2 - temp) * scale / (temp + kSmall);
    scale = scale / (1.0 + z);
    return {scale * (y - yc) + 0.1 * (x - xc), scale * -(x - xc) + 0.1 * (y - yc), scale * z0};
}

VectorGridPtr generateTornado(const TornadoParameters& parameters,
                              const std::optional<IndexBox>& region) {
    if (!std::isfinite(parameters.time))
        throw DataError("tornado: time must be finite, got " +
                        detail::formatNumber(parameters.time));
    const GridGeometry geometry = detail::generatorGeometry(
        "tornado", parameters.dims, glm::dvec3(0.0), glm::dvec3(1.0));
    return detail::sampleGrid<glm::vec3>(
        geometry,
        [&](const glm::dvec3& position) {
            return glm::vec3(tornadoVelocity(position, parameters.time));
        },
        region);
}

} // namespace texsplat::volume
