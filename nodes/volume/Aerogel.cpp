#include "nodes/volume/Aerogel.h"

#include "nodes/volume/detail/Format.h"
#include "scenegraph/Random.h"
#include "nodes/volume/detail/Sampling.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace texsplat::volume {
namespace {

constexpr double kPi = 3.14159265358979323846;

void checkRange(const char* what, double low, double high) {
    if (!(low > 0.0) || !(low <= high) || !std::isfinite(high))
        throw DataError(std::string("aerogel: ") + what +
                        " range must be positive and increasing, got " +
                        detail::formatNumber(low) + " to " + detail::formatNumber(high));
}

} // namespace

std::vector<Fiber> aerogelFibers(const AerogelParameters& parameters) {
    if (parameters.fiberCount < 0)
        throw DataError("aerogel: fiber count must be at least 0, got " +
                        std::to_string(parameters.fiberCount));
    checkRange("radius", parameters.minRadius, parameters.maxRadius);
    checkRange("length", parameters.minLength, parameters.maxLength);
    sg::Random random(parameters.seed);
    std::vector<Fiber> fibers(static_cast<std::size_t>(parameters.fiberCount));
    for (Fiber& fiber : fibers) {
        const glm::dvec3 center(random.uniform(), random.uniform(), random.uniform());
        // Uniform direction on the sphere: uniform cos(theta) and azimuth.
        const double cosTheta = random.uniform(-1.0, 1.0);
        const double azimuth = random.uniform(0.0, 2.0 * kPi);
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        const glm::dvec3 direction(sinTheta * std::cos(azimuth), sinTheta * std::sin(azimuth),
                                   cosTheta);
        const double length = random.uniform(parameters.minLength, parameters.maxLength);
        fiber.start = center - 0.5 * length * direction;
        fiber.end = center + 0.5 * length * direction;
        fiber.radius = random.uniform(parameters.minRadius, parameters.maxRadius);
    }
    return fibers;
}

glm::dvec3 aerogelVelocity(const glm::dvec3& position, const std::vector<Fiber>& fibers,
                           const glm::dvec3& inflow) {
    glm::dvec3 velocity = inflow;
    double noSlip = 1.0;
    for (const Fiber& fiber : fibers) {
        const glm::dvec3 axisVector = fiber.end - fiber.start;
        const double length = glm::length(axisVector);
        TEXSPLAT_ASSERT(length > 0.0, "aerogelVelocity(): fiber of zero length");
        const glm::dvec3 axis = axisVector / length;
        const glm::dvec3 relative = position - fiber.start;
        const double along = glm::dot(relative, axis);
        const double beyond = std::max({0.0, -along, along - length}); // past an end cap
        const glm::dvec3 radial = relative - along * axis;
        const double rho = glm::length(radial);
        const double radius = fiber.radius;
        if (rho < radius && beyond == 0.0)
            return glm::dvec3(0.0);
        // Squared distance to the solid cylinder's surface (side or cap). Past 40 R² the factor
        // 1 - exp(-40) rounds to exactly 1, so skipping it there changes no bit.
        const double side = std::max(rho - radius, 0.0);
        const double gapSquared = (side * side + beyond * beyond) / (radius * radius);
        if (gapSquared < 40.0)
            noSlip *= -std::expm1(-gapSquared);
        if (rho == 0.0)
            continue; // on the axis beyond a cap, where the faded doublet below tends to 0
        // Potential flow past a cylinder, u = U + (R/rho)² (U - 2 (U.r) r) in the plane normal
        // to the axis. Beyond the caps it fades: by rho²/(rho² + beyond²), which keeps it
        // continuous across the axis, and by a Gaussian in the distance past the cap.
        const glm::dvec3 across = inflow - glm::dot(inflow, axis) * axis;
        const glm::dvec3 outward = radial / rho;
        const double reach = std::max(rho, radius);
        double strength = (radius * radius) / (reach * reach);
        if (beyond > 0.0) {
            const double past = beyond / (2.0 * radius);
            strength *= rho * rho / (rho * rho + beyond * beyond) * std::exp(-past * past);
        }
        velocity += strength * (across - 2.0 * glm::dot(across, outward) * outward);
    }
    return velocity * noSlip;
}

AerogelField generateAerogel(const AerogelParameters& parameters,
                             const std::optional<IndexBox>& region) {
    const glm::dvec3& inflow = parameters.inflow;
    if (!std::isfinite(inflow.x) || !std::isfinite(inflow.y) || !std::isfinite(inflow.z))
        throw DataError("aerogel: inflow must be finite, got " + detail::formatNumber(inflow.x) +
                        " " + detail::formatNumber(inflow.y) + " " +
                        detail::formatNumber(inflow.z));
    std::vector<Fiber> fibers = aerogelFibers(parameters);
    const GridGeometry geometry = detail::generatorGeometry("aerogel", parameters.dims,
                                                            glm::dvec3(0.0), glm::dvec3(1.0));
    VectorGridPtr velocity = detail::sampleGrid<glm::vec3>(
        geometry,
        [&](const glm::dvec3& p) { return glm::vec3(aerogelVelocity(p, fibers, inflow)); }, region);
    return {std::move(velocity), std::move(fibers)};
}

} // namespace texsplat::volume
