#include "nodes/render/SplatFootprint.h"

#include "nodes/kernel/FootprintTexture.h"

#include <algorithm>
#include <cmath>

namespace texsplat::render {

double SplatFootprint::reach() const {
    const double footprint = texture ? texture->reach() : extent * std::sqrt(2.0);
    switch (shape) {
    case SplatShape::VectorMarks:
        return markReach;
    case SplatShape::CombinedMarks:
        return std::max(footprint, markReach);
    default:
        return footprint;
    }
}

} // namespace texsplat::render
