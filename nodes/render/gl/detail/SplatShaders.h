#pragma once

namespace texsplat::render::detail {

/// The placement of a splat by the vertex shader: one instanced template (a textured square,
/// or the polygonal Gaussian's fan) turned to face the eye per splat.
///
/// The kernel is isotropic in voxel-index space (the ellipsoidal kernel h(S⁻¹x) for voxel
/// spacing S, as docs/kernel.md recommends for anisotropic grids), so the template is laid out
/// there: in the plane perpendicular to e = S⁻¹d (d the unit viewing direction of the splat
/// centre, in the volume's local space), `extent · size` voxels from the centre, and mapped back
/// with S. Projection is linear, so the square's image is exactly the projected ellipse and its
/// texture coordinates are the voxel-space offsets the footprint texture is tabulated over.
/// The line integral of h(S⁻¹x) along the unit direction d is f(r)/|e| (in local length units),
/// and a coarse splat of `size` k (h(x/k)) integrates to k·f(r/k): lengthScale = size / |e|.
constexpr const char* kSplatPlacement = R"(
uniform mat4 localToClip;
uniform vec3 spacing;
uniform bool perspective;
uniform vec3 eye;        // local space, perspective
uniform vec3 direction;  // local space, unit
uniform float extent;    // template half-width in voxels at size 1
uniform bool gouraud;    // polygonal template: shade per vertex (Crawfis & Max 1993, figure 4a)

out vec2 texCoord;
out float lengthScale;
flat out vec4 medium;
out vec4 vertexColor;
flat out float colorScale;

// corner: xy the template vertex in units of the extent, z its footprint (polygon template);
// positionSize, colorExtinction: octree::Splat (centre in local space, size in voxels; emission
// C per unit length, extinction tau).
void placeSplat(vec3 corner, vec4 positionSize, vec4 colorExtinction) {
    vec3 centre = positionSize.xyz;
    float size = positionSize.w;
    SplatFrame frame = splatFrame(centre, perspective, eye, direction, spacing);
    vec3 d = frame.sight;
    float eLength = frame.eLength;
    vec3 axis = frame.axis;
    vec3 u = frame.u;
    vec3 v = cross(axis, u);
    vec3 offset = (corner.x * u + corner.y * v) * (extent * size);
    gl_Position = localToClip * vec4(centre + spacing * offset, 1.0);
    texCoord = corner.xy * 0.5 + 0.5;
    lengthScale = size / eLength;
    medium = colorExtinction;
    // The Gouraud colour is interpolated divided by the emission's largest component: the
    // rasterizer's interpolation of colours near FLT_MAX overflows (Inf - Inf = NaN); shading
    // is linear in the emission, so the fragment multiplies it back.
    colorScale = max(max(colorExtinction.r, colorExtinction.g), max(colorExtinction.b, 1e-30));
    vertexColor = gouraud ? shadeSplat(colorExtinction.rgb / colorScale, colorExtinction.a,
                                       corner.z * lengthScale)
                          : vec4(0.0);
}
)";

/// The splat vertex shader's main: one instance per octree::Splat (after kSplatPlacement).
constexpr const char* kSplatVertexShader = R"(
layout(location = 0) in vec3 corner;          // template vertex (see placeSplat)
layout(location = 1) in vec4 positionSize;    // octree::Splat
layout(location = 2) in vec4 colorExtinction; // octree::Splat

void main() { placeSplat(corner, positionSize, colorExtinction); }
)";

/// The facing frame of a splat, shared by the vertex shaders (put in front of them by
/// SplatBatch): the unit line of sight `sight` to the centre (or the viewing direction), in the
/// volume's local space; e = sight / spacing, its length `eLength` and direction `axis` (the
/// normal of the splat's plane in voxel space); and a first unit axis `u` of that plane (any
/// basis does for a radial kernel; the helper switches before it degenerates).
constexpr const char* kSplatFrame = R"(
struct SplatFrame {
    vec3 sight;
    float eLength;
    vec3 axis;
    vec3 u;
};

SplatFrame splatFrame(vec3 centre, bool perspective, vec3 eye, vec3 direction, vec3 spacing) {
    SplatFrame frame;
    frame.sight = direction;
    if (perspective) {
        vec3 toCentre = centre - eye;
        float distance = length(toCentre);
        if (distance > 0.0) frame.sight = toCentre / distance;
    }
    vec3 e = frame.sight / spacing;
    frame.eLength = length(e);
    frame.axis = e / frame.eLength;
    vec3 helper = abs(frame.axis.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    frame.u = normalize(cross(helper, frame.axis));
    return frame;
}
)";

/// The shading of a splat's fragment: the footprint texture's value, or the Gouraud-interpolated
/// color of the polygonal template.
constexpr const char* kSplatShade = R"(
in vec2 texCoord;
in float lengthScale;
flat in vec4 medium;
in vec4 vertexColor;
flat in float colorScale;

uniform sampler2D footprint;
uniform bool gouraud;

vec4 shadeFootprint() {
    // Light is drawn scaled by lightScale (gl/LightScale.h), so that blending adds it up finite.
    vec4 color = gouraud ? vec4(vertexColor.rgb * (colorScale * lightScale), vertexColor.a)
                         : shadeSplat(medium.rgb * lightScale, medium.a,
                                      texture(footprint, texCoord).r * lengthScale);
    // Light beyond FLT_MAX stays FLT_MAX, as on the CPU backend and in the ray caster.
    return vec4(min(color.rgb, vec3(3.4028235e38 * lightScale)), color.a);
}
)";

/// The splat fragment shader's main (after kSplatShade).
constexpr const char* kSplatFragmentShader = R"(
out vec4 fragColor;

void main() { fragColor = shadeFootprint(); }
)";

/// Emission-absorption through one splat (put in front of every stage by SplatBatch): a slab of
/// length f (the footprint) with emission C and extinction tau has opacity
/// alpha = 1 - exp(-tau f) and premultiplied color C f phi(tau f), phi(x) = (1 - exp(-x)) / x.
/// For tau f < 1/8 the series of phi is used (1 - exp(-x) cancels in float); above,
/// C (1 - exp(-x)) / tau, which never forms 0/0 or inf*0: tau -> 0 leaves pure emission C f,
/// tau f >> 1 saturates to C / tau, alpha = 1.
constexpr const char* kSplatShading = R"(#version 330 core
vec4 shadeSplat(vec3 emission, float tau, float footprint) {
    float f = max(footprint, 0.0);
    float x = tau * f;
    if (x < 0.125) {
        float phi = 1.0 - x / 2.0 * (1.0 - x / 3.0 * (1.0 - x / 4.0 * (1.0 - x / 5.0 *
                    (1.0 - x / 6.0 * (1.0 - x / 7.0)))));
        return vec4(emission * (f * phi), x * phi);
    }
    float alpha = 1.0 - exp(-x);
    return vec4(emission * (alpha / tau), alpha);
}
)";

} // namespace texsplat::render::detail
