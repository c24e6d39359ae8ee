#pragma once

#include <glm/vec3.hpp>

#include <array>

namespace texsplat::colormap {

/// @brief A listed colour map: 256 RGB colours in [0, 1], entry i at t = i / 255.
using ColorTable = std::array<glm::vec3, 256>;

/// @brief matplotlib's magma (perceptually uniform, black through purple and orange to pale
/// yellow), its published table.
const ColorTable& magma();
/// @brief matplotlib's inferno (perceptually uniform, black through purple and orange to yellow).
const ColorTable& inferno();
/// @brief matplotlib's plasma (perceptually uniform, blue through purple and orange to yellow).
const ColorTable& plasma();
/// @brief cividis (Nuñez et al. 2018): viridis made readable with colour-vision deficiency.
const ColorTable& cividis();
/// @brief Google's turbo (Mikhailov 2019): an improved rainbow, dark blue through green to dark
/// red.
const ColorTable& turbo();

} // namespace texsplat::colormap
