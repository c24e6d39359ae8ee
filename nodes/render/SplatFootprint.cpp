#include "nodes/render/SplatFootprint.h"

#include "nodes/kernel/FootprintTexture.h"

#include <cmath>

namespace texsplat::render {

double SplatFootprint::reach() const {
    const bool radial = shape == SplatShape::TexturedSquare || shape == SplatShape::GouraudPolygon;
    return radial && texture ? texture->reach() : extent * std::sqrt(2.0);
}

} // namespace texsplat::render
