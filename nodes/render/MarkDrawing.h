#pragma once

#include <glm/vec3.hpp>

namespace texsplat::render {

/// @brief The texture operators of the paper's vector splats (Crawfis & Max 1993, after SGI
/// GL's texture environment): how the table's intensity I_tex and opacity A_tex change the
/// polygon's colour RGB and opacity A.
enum class MarkOperator {
    Modulate, ///< RGB·I_tex, A·A_tex: marks in the splat's own colour
    Blend,    ///< RGB·(1 − I_tex) + C_const·I_tex, A·A_tex: marks in the constant colour
};

/// @brief What a vector splat batch draws with in one frame, besides the view.
struct MarkDrawing {
    MarkOperator textureOperator = MarkOperator::Modulate; ///< the texture operator
    glm::vec3 blendColor{1.0f}; ///< C_const of MarkOperator::Blend
    int rowShift = 0;           ///< the animation phase in table rows, added to each splat's row
    float stretch = 1.0f;       ///< elongation of vector splats along their vector, >= 1
    float contrast = 1.0f;      ///< combined splats: how much the marks change the colour, [0, 1]
};

} // namespace texsplat::render
