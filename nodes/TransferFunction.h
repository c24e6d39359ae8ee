#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ClassifiedGrid.h"
#include "scenegraph/Declare.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Node.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/SFEnum.h"

#include <glm/glm.hpp>

#include <memory>
#include <mutex>

namespace texsplat::nodes {

namespace detail {
struct TransferTable;
}

/// @brief The named colour maps of TransferFunction::preset.
enum class ColorPreset {
    Gray,     ///< black to white
    Hot,      ///< black, red, yellow, white
    Viridis,  ///< matplotlib's perceptually uniform blue-green-yellow
    Browns,   ///< a noisy dark-to-light brown ramp (paper, Figure 5: the tornado)
    CoolWarm, ///< Moreland's diverging blue-white-red
};

/// @brief Scene-file names of ColorPreset.
inline const sg::EnumNames kColorPresetNames{{"GRAY", ColorPreset::Gray},
                                             {"HOT", ColorPreset::Hot},
                                             {"VIRIDIS", ColorPreset::Viridis},
                                             {"BROWNS", ColorPreset::Browns},
                                             {"COOL_WARM", ColorPreset::CoolWarm}};

/// @brief What classification gives one voxel value: the emission-absorption medium the splats
/// carry (paper, section 2).
struct Classification {
    /// @brief Emission per unit length C (RGB): the colour a slab of unit length adds before
    /// absorption; what octree::ClassifiedGrid and octree::Splat::color hold.
    glm::vec3 color{0.0f};
    /// @brief Extinction coefficient τ: opacity per unit length (1 / world length).
    float extinction = 0.0f;
};

/// @brief Maps scalar voxel values to emission and extinction (the transfer function of the
/// paper's volume-rendering model), for the splat nodes that follow it.
///
/// A value v is first normalized over `range`: t = (v - range[0]) / (range[1] - range[0]),
/// clamped to [0, 1], so values outside the range classify like its ends (±infinity too); NaN
/// classifies as fully transparent (no emission, no extinction). Then
/// - the colour S(t) interpolates `colors` at the positions `colorValues` (in t), piecewise
///   linearly, constant beyond the first and last point; when both fields are empty the named
///   `preset` gives the control points;
/// - the opacity τ(t) interpolates `opacities` at `opacityValues` (in t) the same way; τ is an
///   extinction coefficient, opacity per unit length in units of 1 / world length, so the result
///   does not depend on the voxel spacing;
/// - the emission per unit length is C = S · (τ + emission). With `emission` 0 a voxel glows as
///   much as it absorbs (the usual "colour times opacity" medium); `emission` adds glow that does
///   not absorb, so fully transparent glowing voxels (opacities 0, emission 1: C = S, τ = 0) are
///   expressible, as the paper's Figure 2 experiment needs.
///
/// Control positions may repeat (a step) but must not decrease. Every check happens on first use
/// after a change and throws DataError naming the field ("TransferFunction 'tf': colorValues has
/// 3 values but colors has 2"). During a traversal the node puts itself into
/// TransferFunctionElement. classify() may be called from several threads at once.
///
/// File format:
/// @code
/// TransferFunction {
///     preset         GRAY      # GRAY, HOT, VIRIDIS, BROWNS, COOL_WARM
///     colorValues    [ ]
///     colors         [ ]
///     opacityValues  [ 0, 1 ]
///     opacities      [ 0, 1 ]
///     range          0 1
///     emission       0
/// }
/// @endcode
class TransferFunction : public sg::Declare<TransferFunction, sg::Node> {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "TransferFunction";

    sg::SFEnum preset;          ///< colour map used when `colors` is empty (ColorPreset)
    sg::MFFloat colorValues;    ///< positions of `colors`, in normalized t
    sg::MFColor colors;         ///< explicit colour control points; override the preset
    sg::MFFloat opacityValues;  ///< positions of `opacities`, in normalized t
    sg::MFFloat opacities;      ///< extinction τ at the control points, 1 / world length, >= 0
    sg::SFVec2f range;          ///< data values mapped to t = 0 and t = 1
    sg::SFFloat emission;       ///< emission per unit length not tied to opacity, >= 0

    /// @brief Checks every field now.
    /// @throws DataError naming the first bad field.
    void validate() const;

    /// @brief Emission and extinction of one value.
    /// @throws DataError when the fields are invalid (see validate()).
    Classification classify(float value) const;

    /// @brief The colour map S(t) alone at `value` (normalized over `range` as classify() does;
    /// NaN gives black): the polygon colour of vector splats, which take their opacity from the
    /// extinction and the mark table rather than from an emission-absorption slab.
    /// @throws DataError when the fields are invalid.
    glm::vec3 color(float value) const;

    /// @brief Classifies every non-empty voxel of `grid` (same dimensions, spacing and origin);
    /// empty voxels, and voxels that classify to zero, stay empty, so they produce no splats.
    /// @throws DataError when the fields are invalid.
    std::shared_ptr<octree::ClassifiedGrid> classify(const volume::ScalarGrid& grid) const;

    /// @brief Puts this node into TransferFunctionElement.
    void doAction(sg::Action& action) override;

    /// @brief Forgets the checked tables, then notifies as every node does.
    void notify(const sg::Field* source) override;

protected:
    TransferFunction();

private:
    std::shared_ptr<const detail::TransferTable> table() const;
    std::shared_ptr<const detail::TransferTable> buildTable() const;

    mutable std::mutex mTableMutex;
    mutable std::shared_ptr<const detail::TransferTable> mTable;
};

} // namespace texsplat::nodes
