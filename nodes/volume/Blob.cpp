#include "nodes/volume/Blob.h"

#include "scenegraph/Random.h"
#include "nodes/volume/detail/Sampling.h"
#include "scenegraph/Error.h"

#include <cmath>
#include <string>

namespace texsplat::volume {

std::vector<GaussianTerm> blobTerms(const BlobParameters& parameters) {
    if (parameters.termCount < 1)
        throw DataError("blob: term count must be at least 1, got " +
                        std::to_string(parameters.termCount));
    sg::Random random(parameters.seed);
    std::vector<GaussianTerm> terms(static_cast<std::size_t>(parameters.termCount));
    for (GaussianTerm& term : terms) {
        for (int axis = 0; axis < 3; ++axis)
            term.center[axis] = random.uniform(-0.5, 0.5);
        term.sigma = random.uniform(0.15, 0.35);
        term.amplitude = random.uniform(0.5, 1.0);
    }
    return terms;
}

double blobValue(const glm::dvec3& position, const std::vector<GaussianTerm>& terms) {
    double sum = 0.0;
    for (const GaussianTerm& term : terms) {
        const glm::dvec3 offset = position - term.center;
        sum += term.amplitude *
               std::exp(-glm::dot(offset, offset) / (2.0 * term.sigma * term.sigma));
    }
    return sum;
}

ScalarGridPtr generateBlob(const BlobParameters& parameters,
                           const std::optional<IndexBox>& region) {
    const std::vector<GaussianTerm> terms = blobTerms(parameters);
    const GridGeometry geometry = detail::generatorGeometry(
        "blob", parameters.dims, glm::dvec3(-1.0), glm::dvec3(1.0));
    return detail::sampleGrid<float>(
        geometry, [&terms](const glm::dvec3& position) { return blobValue(position, terms); },
        region);
}

} // namespace texsplat::volume
