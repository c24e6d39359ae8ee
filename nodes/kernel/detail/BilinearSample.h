#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace texsplat::kernel::detail {

/// The lookup GL makes with GL_LINEAR and GL_CLAMP_TO_EDGE in an n × n texture covering the
/// square [−extent, extent]² (texel centres at −extent + (k + ½)·2·extent/n), and 0 outside the
/// square: what a footprint texture answers a CPU backend.
/// `texel(i, j)` gives the texel of column i (along x) and row j (along y).
template <class Real, class Texel>
auto bilinearSample(Real x, Real y, Real extent, int n, const Texel& texel)
    -> std::decay_t<decltype(texel(0, 0))> {
    using Value = std::decay_t<decltype(texel(0, 0))>;
    if (!(std::fabs(x) <= extent && std::fabs(y) <= extent)) {
        return Value{};
    }
    const auto texelCoordinate = [&](Real value) {
        return (value + extent) / (Real(2) * extent) * static_cast<Real>(n) - Real(0.5);
    };
    const Real u = texelCoordinate(x);
    const Real v = texelCoordinate(y);
    const Real i = std::floor(u);
    const Real j = std::floor(v);
    const Real fu = u - i;
    const Real fv = v - j;
    const auto at = [&](Real column, Real row) {
        const auto clamp = [&](Real index) {
            return static_cast<int>(std::clamp(index, Real(0), static_cast<Real>(n - 1)));
        };
        return texel(clamp(column), clamp(row));
    };
    return (Real(1) - fv) * ((Real(1) - fu) * at(i, j) + fu * at(i + 1, j)) +
           fv * ((Real(1) - fu) * at(i, j + 1) + fu * at(i + 1, j + 1));
}

} // namespace texsplat::kernel::detail
