// Compiled once per SIMD target by Highway's foreach_target; HWY_DYNAMIC_DISPATCH picks one.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "nodes/render/cpu/SplatSetupSpans.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "nodes/render/cpu/SplatRaster.h"
#include "octree/Splat.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace texsplat::render::cpu::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Sets up `lanes` splats from splats[0] on (the caller pads a short tail): SplatSetup's general
// case, one splat per lane. See SplatSetup for the geometry; every step is the scalar one's.
template <class D>
void SetUpLanes(D d, const ProjectiveRows& rows, const octree::Splat* splats, SplatRaster* out,
                std::size_t count) {
    using V = hn::Vec<D>;
    const hn::RebindToSigned<D> di;
    constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
    const std::size_t lanes = hn::Lanes(d);
    const V zero = hn::Zero(d);
    const V one = hn::Set(d, 1.0f);
    // The splat fields, one per lane (a splat is 8 floats: position, size, color, extinction).
    const auto index = hn::ShiftLeft<3>(hn::Iota(di, 0)); // 8 floats a splat
    const float* base = &splats[0].position.x;
    V field[8];
    for (int k = 0; k < 8; ++k) {
        field[k] = hn::GatherIndex(d, base + k, index);
    }
    const V cx = field[0], cy = field[1], cz = field[2], size = field[3];

    // The line of sight and the facing frame (detail/SplatShaders.h's splatFrame()).
    V sx = hn::Set(d, rows.direction[0]), sy = hn::Set(d, rows.direction[1]),
      sz = hn::Set(d, rows.direction[2]);
    if (rows.isPerspective) {
        const V dx = hn::Sub(cx, hn::Set(d, rows.eye[0]));
        const V dy = hn::Sub(cy, hn::Set(d, rows.eye[1]));
        const V dz = hn::Sub(cz, hn::Set(d, rows.eye[2]));
        const V distance = hn::Sqrt(hn::MulAdd(dx, dx, hn::MulAdd(dy, dy, hn::Mul(dz, dz))));
        const auto away = hn::Gt(distance, zero);
        const V inverse = hn::Div(one, hn::IfThenElse(away, distance, one));
        sx = hn::IfThenElse(away, hn::Mul(dx, inverse), sx);
        sy = hn::IfThenElse(away, hn::Mul(dy, inverse), sy);
        sz = hn::IfThenElse(away, hn::Mul(dz, inverse), sz);
    }
    const V ex = hn::Mul(sx, hn::Set(d, rows.inverseSpacing[0]));
    const V ey = hn::Mul(sy, hn::Set(d, rows.inverseSpacing[1]));
    const V ez = hn::Mul(sz, hn::Set(d, rows.inverseSpacing[2]));
    const V eLength = hn::Sqrt(hn::MulAdd(ex, ex, hn::MulAdd(ey, ey, hn::Mul(ez, ez))));
    const V inverseE = hn::Div(one, eLength);
    const V ax = hn::Mul(ex, inverseE), ay = hn::Mul(ey, inverseE), az = hn::Mul(ez, inverseE);
    // u = normalize(cross(helper, axis)): helper z = (0, 0, 1) unless |axis.z| ≥ 0.9, then x.
    const auto helperZ = hn::Lt(hn::Abs(az), hn::Set(d, 0.9f));
    V ux = hn::IfThenElse(helperZ, hn::Neg(ay), zero);
    V uy = hn::IfThenElse(helperZ, ax, hn::Neg(az));
    V uz = hn::IfThenElse(helperZ, zero, ay);
    const V inverseU =
        hn::Div(one, hn::Sqrt(hn::MulAdd(ux, ux, hn::MulAdd(uy, uy, hn::Mul(uz, uz)))));
    ux = hn::Mul(ux, inverseU);
    uy = hn::Mul(uy, inverseU);
    uz = hn::Mul(uz, inverseU);
    V vx = hn::Sub(hn::Mul(ay, uz), hn::Mul(az, uy));
    V vy = hn::Sub(hn::Mul(az, ux), hn::Mul(ax, uz));
    V vz = hn::Sub(hn::Mul(ax, uy), hn::Mul(ay, ux));
    const V reach = hn::Mul(hn::Set(d, rows.extent), size);

    // Homogeneous pixel rows (x·W, y·W, W, z_clip) of the centre and per unit a and b.
    V h0[4], hu[4], hv[4];
    for (int row = 0; row < 4; ++row) {
        const float* p = rows.pixelFromLocal[row];
        const float* q = rows.pixelFromVoxel[row];
        h0[row] = hn::MulAdd(
            hn::Set(d, p[0]), cx,
            hn::MulAdd(hn::Set(d, p[1]), cy, hn::MulAdd(hn::Set(d, p[2]), cz, hn::Set(d, p[3]))));
        hu[row] = hn::Mul(
            reach, hn::MulAdd(hn::Set(d, q[0]), ux,
                              hn::MulAdd(hn::Set(d, q[1]), uy, hn::Mul(hn::Set(d, q[2]), uz))));
        hv[row] = hn::Mul(
            reach, hn::MulAdd(hn::Set(d, q[0]), vx,
                              hn::MulAdd(hn::Set(d, q[1]), vy, hn::Mul(hn::Set(d, q[2]), vz))));
    }
    // The inverse of [hu hv h0] by the adjugate.
    const auto cross = [](V a, V b, V c, V e) { return hn::Sub(hn::Mul(a, b), hn::Mul(c, e)); };
    const V c00 = cross(hv[1], h0[2], h0[1], hv[2]);
    const V c01 = cross(h0[1], hu[2], hu[1], h0[2]);
    const V c02 = cross(hu[1], hv[2], hv[1], hu[2]);
    const V determinant = hn::MulAdd(hu[0], c00, hn::MulAdd(hv[0], c01, hn::Mul(h0[0], c02)));
    const auto invertible = hn::And(hn::Ne(determinant, zero),
                                    hn::Lt(hn::Abs(determinant), hn::Set(d, FLT_MAX)));
    const V s = hn::Div(one, hn::IfThenElse(invertible, determinant, one));
    V inverse[3][3] = {
        {hn::Mul(c00, s), hn::Mul(cross(h0[0], hv[2], hv[0], h0[2]), s),
         hn::Mul(cross(hv[0], h0[1], h0[0], hv[1]), s)},
        {hn::Mul(c01, s), hn::Mul(cross(hu[0], h0[2], h0[0], hu[2]), s),
         hn::Mul(cross(h0[0], hu[1], hu[0], h0[1]), s)},
        {hn::Mul(c02, s), hn::Mul(cross(hv[0], hu[2], hu[0], hv[2]), s),
         hn::Mul(cross(hu[0], hv[1], hv[0], hu[1]), s)}};
    const V half = hn::Set(d, 0.5f);
    for (auto& row : inverse) {
        row[2] = hn::MulAdd(half, hn::Add(row[0], row[1]), row[2]); // pixel centres
    }
    V depth[3];
    for (int column = 0; column < 3; ++column) {
        depth[column] = hn::MulAdd(hu[3], inverse[0][column],
                                   hn::MulAdd(hv[3], inverse[1][column],
                                              hn::Mul(h0[3], inverse[2][column])));
    }

    // The pixel box from the corners; the near/far planes.
    const V width = hn::Set(d, static_cast<float>(rows.width));
    const V height = hn::Set(d, static_cast<float>(rows.height));
    V low[2] = {width, height};
    V high[2] = {zero, zero};
    auto behindEye = hn::Lt(one, zero); // all false
    auto anyNear = behindEye, anyFar = behindEye;
    auto allNear = hn::Not(behindEye), allFar = allNear;
    for (const float a : {-1.0f, 1.0f}) {
        for (const float b : {-1.0f, 1.0f}) {
            const V va = hn::Set(d, a), vb = hn::Set(d, b);
            const V w = hn::MulAdd(va, hu[2], hn::MulAdd(vb, hv[2], h0[2]));
            const V z = hn::MulAdd(va, hu[3], hn::MulAdd(vb, hv[3], h0[3]));
            const auto beforeNear = hn::Lt(z, hn::Neg(w));
            const auto beyondFar = hn::Gt(z, w);
            anyNear = hn::Or(anyNear, beforeNear);
            anyFar = hn::Or(anyFar, beyondFar);
            allNear = hn::And(allNear, beforeNear);
            allFar = hn::And(allFar, beyondFar);
            const auto front = hn::Gt(w, zero);
            behindEye = hn::Or(behindEye, hn::Not(front));
            const V inverseW = hn::Div(one, hn::IfThenElse(front, w, one));
            const V x = hn::Mul(hn::MulAdd(va, hu[0], hn::MulAdd(vb, hv[0], h0[0])), inverseW);
            const V y = hn::Mul(hn::MulAdd(va, hu[1], hn::MulAdd(vb, hv[1], h0[1])), inverseW);
            low[0] = hn::IfThenElse(front, hn::Min(low[0], x), low[0]);
            low[1] = hn::IfThenElse(front, hn::Min(low[1], y), low[1]);
            high[0] = hn::IfThenElse(front, hn::Max(high[0], x), high[0]);
            high[1] = hn::IfThenElse(front, hn::Max(high[1], y), high[1]);
        }
    }
    // A footprint that is 0 beyond a disc of radius R (in the square's half-widths) inside the
    // square: the box of the ellipse the disc projects to, where that is tighter (an oblique
    // square's box is up to √2 wider, and its corners hold nothing). With H = [hu hv h0], the
    // ellipse's dual conic is C* = H·diag(1, 1, −1/R²)·Hᵀ; the vertical line x = k touches it
    // where C*00 − 2k·C*02 + k²·C*22 = 0, and likewise for y.
    if (rows.discRadius > 0.0f) {
        const V inverseR2 = hn::Set(d, -1.0f / (rows.discRadius * rows.discRadius));
        const auto dual = [&](int i, int j) {
            return hn::MulAdd(hu[i], hu[j], hn::MulAdd(hv[i], hv[j],
                                                       hn::Mul(hn::Mul(h0[i], h0[j]), inverseR2)));
        };
        const V dualWW = dual(2, 2);
        for (int axis = 0; axis < 2; ++axis) {
            const V dualAW = dual(axis, 2);
            const V root =
                hn::Sqrt(hn::NegMulAdd(dual(axis, axis), dualWW, hn::Mul(dualAW, dualAW)));
            const V inverseWW = hn::Div(one, dualWW);
            const V first = hn::Mul(hn::Sub(dualAW, root), inverseWW);
            const V second = hn::Mul(hn::Add(dualAW, root), inverseWW);
            // NaN (no real tangent) compares false and keeps the square's bound.
            const V discLow = hn::Min(first, second);
            const V discHigh = hn::Max(first, second);
            low[axis] = hn::IfThenElse(hn::Gt(discLow, low[axis]), discLow, low[axis]);
            high[axis] = hn::IfThenElse(hn::Lt(discHigh, high[axis]), discHigh, high[axis]);
        }
    }
    // Part of the square behind the eye: its visible part may reach any pixel.
    low[0] = hn::IfThenElse(behindEye, zero, low[0]);
    low[1] = hn::IfThenElse(behindEye, zero, low[1]);
    high[0] = hn::IfThenElse(behindEye, width, high[0]);
    high[1] = hn::IfThenElse(behindEye, height, high[1]);
    // Pixel bounds, clamped before they become ints (NaN compares false: it clamps to 0).
    const auto toPixel = [&](V value, V limit) {
        const V clamped = hn::IfThenElse(hn::Gt(value, zero), hn::Min(value, limit), zero);
        return hn::ConvertTo(di, clamped);
    };
    const auto columnBegin = toPixel(hn::Floor(low[0]), width);
    const auto columnEnd = toPixel(hn::Add(hn::Ceil(high[0]), one), width);
    const auto rowBegin = toPixel(hn::Floor(low[1]), height);
    const auto rowEnd = toPixel(hn::Add(hn::Ceil(high[1]), one), height);
    const auto empty = hn::Or(hn::Not(invertible), hn::Or(allNear, allFar));
    const auto clipped = hn::Or(behindEye, hn::Or(anyNear, anyFar));
    const V lengthScale = hn::Div(size, eLength);

    // Out, one splat per lane.
    HWY_ALIGN float square[9][kMaxLanes], depthOut[3][kMaxLanes], scale[kMaxLanes];
    HWY_ALIGN std::int32_t bounds[4][kMaxLanes], emptyOut[kMaxLanes], clippedOut[kMaxLanes];
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            hn::Store(inverse[row][column], d, square[3 * row + column]);
        }
        hn::Store(depth[row], d, depthOut[row]);
    }
    hn::Store(lengthScale, d, scale);
    hn::Store(columnBegin, di, bounds[0]);
    hn::Store(columnEnd, di, bounds[1]);
    hn::Store(rowBegin, di, bounds[2]);
    hn::Store(rowEnd, di, bounds[3]);
    hn::Store(hn::VecFromMask(di, hn::RebindMask(di, empty)), di, emptyOut);
    hn::Store(hn::VecFromMask(di, hn::RebindMask(di, clipped)), di, clippedOut);
    for (std::size_t lane = 0; lane < std::min(lanes, count); ++lane) {
        SplatRaster& raster = out[lane];
        raster = SplatRaster{};
        if (emptyOut[lane] != 0) {
            continue;
        }
        for (int k = 0; k < 9; ++k) {
            raster.square[k] = square[k][lane];
        }
        for (int k = 0; k < 3; ++k) {
            raster.depth[k] = depthOut[k][lane];
        }
        const octree::Splat& splat = splats[lane];
        raster.color[0] = splat.color.r;
        raster.color[1] = splat.color.g;
        raster.color[2] = splat.color.b;
        raster.extinction = splat.extinction;
        raster.lengthScale = scale[lane];
        raster.columnBegin = bounds[0][lane];
        raster.columnEnd = bounds[1][lane];
        raster.rowBegin = bounds[2][lane];
        raster.rowEnd = bounds[3][lane];
        raster.flags = (rows.isPerspective ? SplatRaster::kProjective : 0) |
                       (clippedOut[lane] != 0 ? SplatRaster::kClipped : 0);
    }
}

void SetUpProjective(const ProjectiveRows& rows, const octree::Splat* splats, std::size_t count,
                     SplatRaster* out) {
    const hn::ScalableTag<float> d;
    const std::size_t lanes = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + lanes <= count; i += lanes) {
        SetUpLanes(d, rows, splats + i, out + i, lanes);
    }
    if (i < count) {
        // The tail through a full vector of copies (the last splat repeated), not past the list.
        constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
        std::array<octree::Splat, kMaxLanes> tail;
        std::fill(tail.begin(), tail.end(), splats[count - 1]);
        std::copy(splats + i, splats + count, tail.begin());
        SetUpLanes(d, rows, tail.data(), out + i, count - i);
    }
}

} // namespace texsplat::render::cpu::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace texsplat::render::cpu {

HWY_EXPORT(SetUpProjective);

void setUpProjective(const ProjectiveRows& rows, const octree::Splat* splats, std::size_t count,
                     SplatRaster* out) {
    HWY_DYNAMIC_DISPATCH(SetUpProjective)(rows, splats, count, out);
}

} // namespace texsplat::render::cpu
#endif
