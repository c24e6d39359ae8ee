#include "nodes/volume/JetStream.h"

#include "nodes/volume/detail/Format.h"
#include "scenegraph/Random.h"
#include "nodes/volume/detail/Sampling.h"
#include "nodes/volume/detail/ValueNoise.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace texsplat::volume {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// One jet: a wind maximum around an axis whose latitude meanders with longitude.
struct Jet {
    double baseLatitude;  // degrees north
    double amplitude;     // meander amplitude, degrees of latitude
    double waveNumber;    // meanders per 360 degrees of longitude
    double drift;         // eastward drift of the meanders, degrees of longitude per day
    double coreAltitude;  // km
    double peakSpeed;     // m/s
    double halfWidth;     // degrees of latitude
    double depth;         // km
    double phase;         // radians, from the seed
    double harmonicPhase; // radians, from the seed

    double wavePhase(double longitude, double time) const {
        return waveNumber * (longitude - drift * time) * kDegree + phase;
    }
    // Axis latitude, and its slope d(latitude)/d(longitude) for the wind direction. A weaker
    // harmonic at 2.3 times the wave number keeps the meanders from looking like a pure sine.
    double axisLatitude(double longitude, double time, double& slope) const {
        const double main = wavePhase(longitude, time);
        const double harmonic = 2.3 * waveNumber * (longitude - 0.5 * drift * time) * kDegree +
                                harmonicPhase;
        slope = amplitude * kDegree * waveNumber *
                (std::cos(main) + 0.35 * 2.3 * std::cos(harmonic));
        return baseLatitude + amplitude * (std::sin(main) + 0.35 * std::sin(harmonic));
    }
};

std::array<Jet, 2> makeJets(std::uint64_t seed) {
    sg::Random random(seed);
    const double twoPi = 2.0 * kPi;
    Jet polar{50.0, 7.0, 5.0, 8.0, 9.5, 55.0, 4.0, 2.5, 0.0, 0.0};
    Jet subtropical{30.0, 2.5, 4.0, 5.0, 12.0, 45.0, 3.0, 2.0, 0.0, 0.0};
    for (Jet* jet : {&polar, &subtropical}) {
        jet->phase = random.uniform(0.0, twoPi);
        jet->harmonicPhase = random.uniform(0.0, twoPi);
    }
    return {polar, subtropical};
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

void checkBox(const JetStreamParameters& p) {
    const auto bad = [](const char* what, double low, double high) {
        return DataError(std::string("jet-stream: ") + what + " range must be finite and " +
                         "increasing, got " + detail::formatNumber(low) + " to " +
                         detail::formatNumber(high));
    };
    if (!(p.longitudeMin < p.longitudeMax) || !std::isfinite(p.longitudeMax - p.longitudeMin))
        throw bad("longitude", p.longitudeMin, p.longitudeMax);
    if (!(p.latitudeMin < p.latitudeMax) || !std::isfinite(p.latitudeMax - p.latitudeMin))
        throw bad("latitude", p.latitudeMin, p.latitudeMax);
    if (!(0.0 < p.altitudeMax) || !std::isfinite(p.altitudeMax))
        throw bad("altitude", 0.0, p.altitudeMax);
    if (!std::isfinite(p.time))
        throw DataError("jet-stream: time must be finite, got " + detail::formatNumber(p.time));
}

} // namespace

JetStreamField generateJetStream(const JetStreamParameters& parameters,
                                 const std::optional<IndexBox>& region) {
    checkBox(parameters);
    const GridGeometry geometry = detail::generatorGeometry(
        "jet-stream", parameters.dims,
        glm::dvec3(parameters.longitudeMin, parameters.latitudeMin, 0.0),
        glm::dvec3(parameters.longitudeMax, parameters.latitudeMax, parameters.altitudeMax));
    const std::array<Jet, 2> jets = makeJets(parameters.seed);
    const double time = parameters.time;

    // Wind: the jets along their meandering axes plus westerlies growing with height (thermal
    // wind). Vertical motion is two orders of magnitude weaker at this scale; it is left out.
    const auto wind = [&](const glm::dvec3& p) {
        glm::dvec3 velocity(10.0 * std::min(p.z / 12.0, 1.0), 0.0, 0.0);
        for (const Jet& jet : jets) {
            double slope = 0.0;
            const double offset = p.y - jet.axisLatitude(p.x, time, slope);
            const double height = (p.z - jet.coreAltitude) / jet.depth;
            const double speed = jet.peakSpeed *
                                 std::exp(-(offset * offset) / (jet.halfWidth * jet.halfWidth)) *
                                 std::exp(-height * height);
            velocity += speed * glm::dvec3(1.0, slope, 0.0) / std::sqrt(1.0 + slope * slope);
        }
        return glm::vec3(velocity);
    };

    // Cloudiness: moist air rising ahead of the troughs, on the equatorward side of the polar
    // jet (the polar front), plus a tropical band; moisture falls off with height.
    const std::uint64_t noiseSeed = sg::Random::mix(parameters.seed ^ 0xC10D5ull);
    const auto cloudiness = [&](const glm::dvec3& p) {
        const Jet& polar = jets[0];
        double slope = 0.0;
        const double front = polar.axisLatitude(p.x, time, slope) - 5.0;
        const double ascent = 0.5 + 0.5 * std::cos(polar.wavePhase(p.x, time));
        const double frontal = std::exp(-std::pow((p.y - front) / 6.0, 2.0)) * ascent;
        const double tropical = 0.8 * std::exp(-std::pow((p.y - 18.0) / 4.0, 2.0));
        const double moisture = std::exp(-std::pow(p.z / 6.0, 2.0));
        const double noise = detail::valueNoise(
            glm::dvec3(p.x / 10.0 - 0.5 * time, p.y / 6.0, p.z / 3.0), noiseSeed);
        const double humidity = moisture * std::max(frontal, tropical) * (0.5 + 0.8 * noise);
        return 100.0 * smoothstep(0.25, 0.6, humidity);
    };

    return {detail::sampleGrid<glm::vec3>(geometry, wind, region),
            detail::sampleGrid<float>(geometry, cloudiness, region)};
}

} // namespace texsplat::volume
