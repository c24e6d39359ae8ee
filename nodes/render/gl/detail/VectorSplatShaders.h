#pragma once

namespace texsplat::render::detail {

/// The vector splat vertex shader (Crawfis & Max 1993, "Combined Vector and Scalar Textures"):
/// the textured square of the scalar splats (see kSplatVertexShader for the voxel-space layout
/// and lengthScale), turned in its plane so that its x axis, along which the table's marks are
/// made, lies along the splat's vector as the camera projects it.
///
/// The plane through the line of sight at the splat centre and the vector projects onto one
/// image line, the vector's projected direction (for a perspective camera too: the plane holds
/// the eye). Its intersection with the square's plane is therefore the square's x axis, exact at
/// any place in the image, and needs no screen-space quantity. A vector along the line of sight
/// (or zero, or not finite) has no projected direction: the splat draws no marks (hasMarks 0).
/// `stretch` elongates the square along x, marks and window with it (figure 6's streaks).
constexpr const char* kVectorSplatVertexShader = R"(
layout(location = 0) in vec3 corner;          // the square's corner, in units of the extent
layout(location = 1) in vec4 positionSize;    // octree::Splat: centre (local space), size in voxels
layout(location = 2) in vec4 colorExtinction; // octree::Splat: colour, extinction tau
layout(location = 3) in vec3 flow;            // octree::SplatVector: the vector (local space)
layout(location = 4) in uvec2 rowColumn;      // octree::SplatVector: random row, column

uniform mat4 localToClip;
uniform vec3 spacing;
uniform bool perspective;
uniform vec3 eye;
uniform vec3 direction;
uniform float extent;          // the table's half-width in voxels at size 1
#ifdef COMBINED
uniform float footprintExtent; // the scalar footprint texture's half-width
#endif
uniform float stretch;
uniform int rowShift;          // the animation phase, in rows
uniform int rows;
uniform int columns;

out vec2 tableCoord;
#ifdef COMBINED
out vec2 footprintCoord;
#endif
out float lengthScale;
flat out vec4 medium;
flat out float layer;
flat out int hasMarks;
flat out float polygonAlpha; // vector splats: the opacity A of one voxel's depth of the medium

void main() {
    vec3 centre = positionSize.xyz;
    float size = positionSize.w;
    SplatFrame frame = splatFrame(centre, perspective, eye, direction, spacing);
    vec3 d = frame.sight;
    float eLength = frame.eLength;
    vec3 axis = frame.axis;
    vec3 u = frame.u;
    vec3 scalarU = u; // the scalar splats' basis: combined splats sample their footprint in it
    hasMarks = 0;
    // Scaled by the largest component first: a huge vector's length overflows, a tiny one's
    // underflows.
    float largest = max(abs(flow.x), max(abs(flow.y), abs(flow.z)));
    if (largest > 0.0 && !isinf(largest) && !isnan(largest)) {
        vec3 unitFlow = normalize(flow / largest);
        vec3 sightPlane = cross(unitFlow, d);  // normal of the plane of sight line and vector
        vec3 squarePlane = axis / spacing;     // normal of the square's plane, local space
        vec3 along = cross(squarePlane, sightPlane);
        if (length(along) > 1e-6 * length(squarePlane)) {
            if (dot(along, unitFlow - dot(unitFlow, d) * d) < 0.0) along = -along;
            u = normalize(along / spacing);
            hasMarks = 1;
        }
    }
#ifndef COMBINED
    if (hasMarks == 0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // no marks, nothing to draw: no fragments
        return;
    }
#endif
    vec3 v = cross(axis, u);
    float halfWidth = extent * size;
    vec3 offset = (corner.x * (hasMarks == 1 ? stretch : 1.0) * u + corner.y * v) * halfWidth;
    gl_Position = localToClip * vec4(centre + spacing * offset, 1.0);
    tableCoord = corner.xy * 0.5 + 0.5;
#ifdef COMBINED
    // The same voxel offset in the TextureSplat's own square, so the scalar part samples the
    // footprint exactly where a TextureSplat would.
    vec2 scalarOffset = vec2(dot(offset, scalarU), dot(offset, cross(axis, scalarU))) / size;
    footprintCoord = scalarOffset / footprintExtent * 0.5 + 0.5;
#endif
    lengthScale = size / eLength;
    medium = colorExtinction;
    polygonAlpha = shadeSplat(vec3(0.0), colorExtinction.a, lengthScale).a;
    int row = (int(rowColumn.x) + rowShift) % rows;
    layer = float(row * columns + int(min(rowColumn.y, uint(columns - 1))));
}
)";

/// The vector splat fragment shader (COMBINED defined for combined splats: one program each,
/// so that neither pays for the other's texture lookups): the paper's two texture operators on the table's
/// (intensity I, opacity A_tex) at the splat's row and column.
/// - Vector splats: the polygon has the splat's colour RGB and the opacity A of one voxel's
///   slab of its medium, A = 1 − exp(−τ·lengthScale); MODULATE gives (RGB·I, A·A_tex), BLEND
///   gives (RGB·(1 − I) + C_const·I, A·A_tex), both premultiplied for "over" blending.
/// - Combined splats: the polygon is the scalar splat's own emission-absorption at the pixel
///   (shadeSplat with the kernel footprint), and the marks change only its colour, scaled by
///   `contrast`: BLEND dissolves towards C_const by c·I, MODULATE multiplies by 1 − c + c·I.
///   With contrast 0 (or no marks) the pixel is exactly the TextureSplat's.
constexpr const char* kVectorSplatFragmentShader = R"(
in vec2 tableCoord;
#ifdef COMBINED
in vec2 footprintCoord;
#endif
in float lengthScale;
flat in vec4 medium;
flat in float layer;
flat in int hasMarks;
flat in float polygonAlpha;

uniform sampler2DArray marks;
uniform bool blend;
uniform vec3 blendColor;
#ifdef COMBINED
uniform sampler2D footprint;
uniform float contrast;
#endif

out vec4 fragColor;

void main() {
    vec2 table = texture(marks, vec3(tableCoord, layer)).rg * float(hasMarks);
#ifdef COMBINED
    // Light is drawn scaled by lightScale (gl/LightScale.h), so that blending adds it up finite.
    vec4 scalar = shadeSplat(medium.rgb * lightScale, medium.a,
                             texture(footprint, footprintCoord).r * lengthScale);
    float intensity = contrast * table.r;
    fragColor = blend ? vec4(scalar.rgb * (1.0 - intensity) +
                             blendColor * (intensity * scalar.a * lightScale), scalar.a)
                      : vec4(scalar.rgb * (1.0 - contrast + intensity), scalar.a);
#else
    float alpha = polygonAlpha * table.g;
    if (alpha == 0.0) discard; // between the marks: nothing to blend
    vec3 color = blend ? medium.rgb * (1.0 - table.r) + blendColor * table.r
                       : medium.rgb * table.r;
    fragColor = vec4(color * (alpha * lightScale), alpha); // scaled: gl/LightScale.h
#endif
}
)";

} // namespace texsplat::render::detail
