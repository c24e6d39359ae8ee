#pragma once

namespace texsplat::render::detail {

/// The placement of a vector mark by the vertex shader (render::ScreenMark, laid out by
/// ScreenMarks on the CPU for both backends): the template square [−1, 1]² stretched to the
/// mark's rectangle in image pixels, halfLength along its axis and halfWidth across, at the
/// mark's depth. `markCoord` is the offset from the centre in pixels along and across the axis.
constexpr const char* kMarkPlacement = R"(
uniform mat4 imageToClip; // image pixels (x right, y down, depth z_ndc) to clip space

out vec2 markCoord;
flat out vec4 markShape; // halfLength, halfWidth, head, alpha
flat out vec3 markColor;

// centreAxis: centre (pixels), unit axis; shape: halfLength, halfWidth, head, depth;
// colorAlpha: colour, peak opacity.
void placeMark(vec2 corner, vec4 centreAxis, vec4 shape, vec4 colorAlpha) {
    vec2 axis = centreAxis.zw;
    vec2 across = vec2(-axis.y, axis.x);
    markCoord = corner * shape.xy;
    vec2 pixel = centreAxis.xy + markCoord.x * axis + markCoord.y * across;
    gl_Position = imageToClip * vec4(pixel, shape.w, 1.0);
    markShape = vec4(shape.xyz, colorAlpha.a);
    markColor = colorAlpha.rgb;
}
)";

/// The shading of a mark's fragment: render::markProfile() at (s, t) = markCoord / (halfLength,
/// halfWidth), the mark's colour (BLEND: mixed towards blendColor by the profile), premultiplied.
constexpr const char* kMarkShade = R"(
in vec2 markCoord;
flat in vec4 markShape;
flat in vec3 markColor;

uniform bool particles;
uniform float particleTail; // MarkDrawing::kParticleTail
uniform bool blend;
uniform vec3 blendColor;

vec4 shadeMark() {
    float s = markCoord.x / markShape.x;
    float t = markCoord.y / markShape.y;
    float head = markShape.z;
    float ramp = clamp(min((s + 1.0) / (2.0 - head), (1.0 - s) / head), 0.0, 1.0);
    float taper = particles ? particleTail + (1.0 - particleTail) * 0.5 * (s + 1.0) : 1.0;
    float across = max(taper - t * t, 0.0);
    float profile = ramp * across * across;
    float alpha = markShape.w * profile;
    vec3 color = blend ? markColor + (blendColor - markColor) * profile : markColor;
    // Light is drawn scaled by lightScale (gl/LightScale.h), as the splats are.
    return vec4(min(color * (alpha * lightScale), vec3(3.4028235e38 * lightScale)), alpha);
}
)";

/// The vertex shader of a mark batch: one instance per element. Vector splats' elements are
/// marks; combined splats' (COMBINED defined) are each splat followed by its marks, in the
/// list's order, told apart by `kind` (0: a splat, its octree::Splat in the first two vectors;
/// 1: a mark), so that one draw keeps the order "over" needs.
constexpr const char* kMarkVertexShader = R"(
layout(location = 0) in vec3 corner;
layout(location = 1) in vec4 element0;
layout(location = 2) in vec4 element1;
layout(location = 3) in vec4 element2;
#ifdef COMBINED
layout(location = 4) in float kind;
flat out int isMark;
#endif

void main() {
#ifdef COMBINED
    isMark = kind > 0.5 ? 1 : 0;
    if (isMark == 0) {
        placeSplat(corner, element0, element1);
        return;
    }
#endif
    placeMark(corner.xy, element0, element1, element2);
}
)";

/// The fragment shader of a mark batch (after kMarkShade, and kSplatShade for COMBINED).
constexpr const char* kMarkFragmentShader = R"(
#ifdef COMBINED
flat in int isMark;
#endif

out vec4 fragColor;

void main() {
#ifdef COMBINED
    if (isMark == 0) {
        fragColor = shadeFootprint();
        return;
    }
#endif
    fragColor = shadeMark();
    if (fragColor.a == 0.0) discard; // beside the mark: nothing to blend
}
)";

} // namespace texsplat::render::detail
