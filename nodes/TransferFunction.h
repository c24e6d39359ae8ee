#pragma once

#include "nodes/volume/Grid.h"
#include "octree/ClassifiedGrid.h"
#include "octree/Fwd.h"
#include "scenegraph/Declare.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/io/RelativeFileNames.h"

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
    Magma,    ///< matplotlib's magma: black, purple, orange, pale yellow
    Inferno,  ///< matplotlib's inferno: black, purple, orange, yellow
    Plasma,   ///< matplotlib's plasma: blue, purple, orange, yellow
    Cividis,  ///< cividis: viridis for colour-vision deficiency, blue to yellow
    Turbo,    ///< Google's turbo: an improved rainbow
};

/// @brief Scene-file names of ColorPreset.
inline const sg::EnumNames kColorPresetNames{{"GRAY", ColorPreset::Gray},
                                             {"HOT", ColorPreset::Hot},
                                             {"VIRIDIS", ColorPreset::Viridis},
                                             {"BROWNS", ColorPreset::Browns},
                                             {"COOL_WARM", ColorPreset::CoolWarm},
                                             {"MAGMA", ColorPreset::Magma},
                                             {"INFERNO", ColorPreset::Inferno},
                                             {"PLASMA", ColorPreset::Plasma},
                                             {"CIVIDIS", ColorPreset::Cividis},
                                             {"TURBO", ColorPreset::Turbo}};

/// @brief Where TransferFunction::range comes from (TransferFunction::rangeMode).
enum class RangeMode {
    Auto,       ///< FIXED when `range` is written (set), DATA when it is not
    Fixed,      ///< the `range` field as it is
    Data,       ///< the smallest and largest finite value of the data
    Percentile, ///< the `percentiles` of the data's finite values (robust to outliers)
};

/// @brief Scene-file names of RangeMode.
inline const sg::EnumNames kRangeModeNames{{"AUTO", RangeMode::Auto},
                                           {"FIXED", RangeMode::Fixed},
                                           {"DATA", RangeMode::Data},
                                           {"PERCENTILE", RangeMode::Percentile}};

/// @brief What a TransferFunction takes from the data it classifies: the value range that maps
/// onto t in [0, 1] and the world length its opacities are meant for.
struct DataScale {
    glm::vec2 range{0.0f, 1.0f}; ///< values mapped to t = 0 and t = 1
    float unitDistance = 1.0f;   ///< world length over which `opacities` are given, > 0
};

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
/// A value v is first normalized over the range [a, b]: t = (v - a) / (b - a), clamped to
/// [0, 1], so values outside the range classify like its ends (±infinity too); NaN classifies as
/// fully transparent (no emission, no extinction). The range comes from `rangeMode`: FIXED uses
/// `range`; DATA the smallest and largest finite value of the data the splat node draws (for
/// vectors: of their magnitudes; for a brick of data split over processes, of the whole data);
/// PERCENTILE the `percentiles` (in percent) of those values;
/// AUTO, the default, is FIXED when `range` has been written (or connected) and DATA when it has
/// not, so scenes that give a range keep it and new ones fit their data. Data of one value v gets
/// [v - 0.5, v + 0.5]. Then
/// - the colour S(t) interpolates `colors` at the positions `colorValues` (in t), piecewise
///   linearly, constant beyond the first and last point; when both fields are empty the colour
///   map of `colorMapFile` (a ParaView colour-map JSON file, colormap::ParaViewColorMap; relative
///   to the scene file's folder) gives the control points, and when that is empty too the named
///   `preset`;
/// - the opacity τ(t) interpolates `opacities` at `opacityValues` (in t) the same way; τ is an
///   extinction coefficient, opacity per `unitDistance` of world length. `unitDistance` 1 (the
///   default) makes τ plain extinction per world unit, so a grid twice as finely spaced over the
///   same box looks the same; `unitDistance` 0 means one voxel of the data (the geometric mean of
///   its spacing), so the same voxel values look the same at any spacing, as ParaView's
///   "scalar opacity unit distance" set to the cell length does;
/// - the emission per unit length is C = S · (τ + emission), over the same unit distance. With
///   `emission` 0 a voxel glows as much as it absorbs (the usual "colour times opacity" medium);
///   `emission` adds glow that does not absorb, so fully transparent glowing voxels (opacities
///   0, emission 1: C = S, τ = 0) are expressible, as the paper's Figure 2 experiment needs.
///
/// `shade` lights the medium as VTK's and ParaView's "Shade" do (render::VolumeLighting): the
/// gradient of the classified extinction is a surface normal, and the colour becomes
/// `ambient`·C + `diffuse`·|n·l|·C + `specular`·|n·h|^`specularPower`·τ per light of the scene
/// (DirectionalLight; none: a headlight), so surfaces inside the volume show their shape; where
/// the extinction does not change (no gradient) only the ambient part is left. The defaults are
/// vtkVolumeProperty's. These fields shade the classified grid, they do not classify it again.
///
/// `title` and `units` say what the values are ("Temperature", "K"): the colour bar
/// (annotation::ColorLegend) is titled "Temperature (K)"; they do not change the classification.
///
/// Control positions may repeat (a step) but must not decrease. Every check happens on first use
/// after a change and throws DataError naming the field ("TransferFunction 'tf': colorValues has
/// 3 values but colors has 2"). During a traversal the node puts itself into
/// TransferFunctionElement. classify() may be called from several threads at once.
///
/// File format:
/// @code
/// TransferFunction {
///     preset         GRAY      # GRAY, HOT, VIRIDIS, BROWNS, COOL_WARM, MAGMA, INFERNO,
///                              # PLASMA, CIVIDIS, TURBO
///     colorMapFile   ""        # a ParaView colour-map .json; replaces the preset
///     colorValues    [ ]
///     colors         [ ]
///     opacityValues  [ 0, 1 ]
///     opacities      [ 0, 1 ]
///     range          0 1
///     rangeMode      AUTO      # AUTO, FIXED, DATA, PERCENTILE
///     percentiles    1 99
///     unitDistance   1         # world length of the opacities; 0: one voxel
///     emission       0
///     title          ""        # what the values are, for the colour bar
///     units          ""        # their unit, for the colour bar
///     shade          FALSE     # gradient lighting by the scene's lights (VTK's ShadeOn)
///     ambient        0.1
///     diffuse        0.7
///     specular       0.2
///     specularPower  10
/// }
/// @endcode
class TransferFunction : public sg::Declare<TransferFunction, sg::Node>,
                         public sg::RelativeFileNames {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "TransferFunction";

    sg::SFEnum preset;          ///< colour map used when `colors` and `colorMapFile` are empty
    sg::SFString colorMapFile;  ///< a ParaView colour-map JSON file; replaces `preset`
    sg::MFFloat colorValues;    ///< positions of `colors`, in normalized t
    sg::MFColor colors;         ///< explicit colour control points; override the colour map
    sg::MFFloat opacityValues;  ///< positions of `opacities`, in normalized t
    sg::MFFloat opacities;      ///< extinction τ at the control points, per unitDistance, >= 0
    sg::SFVec2f range;          ///< data values mapped to t = 0 and t = 1 (rangeMode FIXED)
    sg::SFEnum rangeMode;       ///< where the range comes from (RangeMode)
    sg::SFVec2f percentiles;    ///< the percentiles rangeMode PERCENTILE takes, in [0, 100]
    sg::SFFloat unitDistance;   ///< world length the opacities are given for; 0: one voxel
    sg::SFFloat emission;       ///< emission per unit length not tied to opacity, >= 0
    sg::SFString title;         ///< what the classified values are: the colour bar's title
    sg::SFString units;         ///< the unit of the values, shown after the title
    sg::SFBool shade;           ///< light the medium by its extinction's gradient
    sg::SFFloat ambient;        ///< shade: the part of the colour shown unlit, >= 0
    sg::SFFloat diffuse;        ///< shade: the Lambertian part, >= 0
    sg::SFFloat specular;       ///< shade: the highlight's strength, >= 0
    sg::SFFloat specularPower;  ///< shade: the highlight's sharpness (Phong exponent), > 0

    /// @brief Checks every field now (and reads `colorMapFile`).
    /// @throws DataError naming the first bad field; what reading `colorMapFile` throws.
    void validate() const;

    /// @brief The range and unit distance this node uses for `grid` (see rangeMode and
    /// unitDistance); scans the grid's values unless rangeMode resolves to FIXED.
    /// @throws DataError when the fields are invalid.
    DataScale dataScale(const volume::ScalarGrid& grid) const;
    /// @brief dataScale() of a vector grid: the range of its magnitudes.
    DataScale dataScale(const volume::VectorGrid& grid) const;

    /// @brief Emission and extinction of one value, with `range` and a unit distance of 1 when
    /// `unitDistance` is 0 (no data, no voxel): the fields as written, whatever `rangeMode`.
    /// @throws DataError when the fields are invalid (see validate()).
    Classification classify(float value) const;
    /// @brief Emission and extinction of one value over `scale` (from dataScale()), per world
    /// length.
    Classification classify(float value, const DataScale& scale) const;

    /// @brief Levels of the normalized position t that a classified grid tells apart: t =
    /// k/(kLevels − 1), k < kLevels (a sixteenth of a thousandth of the range apart).
    static constexpr int kLevels = 32769;

    /// @brief What a classified grid holds for a voxel of `value` (classify(grid)): classify() at
    /// the nearest level of its normalized position, so 2 bytes a voxel name it (an index into
    /// the grid's palette). It differs from classify(value, scale) by what the function changes
    /// over half a level, 1/65536 of the range, at most (where the function steps, a value within
    /// that of the step takes the step's other side).
    Classification classifyLevel(float value, const DataScale& scale) const;

    /// @brief The colour map S(t) alone at `value` (normalized over `range` as classify() does;
    /// NaN gives black): the polygon colour of vector splats, which take their opacity from the
    /// extinction and the mark table rather than from an emission-absorption slab.
    /// @throws DataError when the fields are invalid.
    glm::vec3 color(float value) const;
    /// @brief color() over the range of `scale`.
    glm::vec3 color(float value, const DataScale& scale) const;
    /// @brief The colour map S at normalized position `t` (clamped to [0, 1]): what a colour
    /// legend draws.
    glm::vec3 colorAt(float t) const;

    /// @brief Classifies every non-empty voxel of `grid` (same dimensions, spacing and origin)
    /// over dataScale(grid), as classifyLevel() does, into a grid of palette indices
    /// (octree::ClassifiedGrid::Storage::Palette: 2 bytes a voxel); empty voxels, and voxels that
    /// classify to zero, stay empty, so they produce no splats.
    /// @throws DataError when the fields are invalid.
    std::shared_ptr<octree::ClassifiedGrid> classify(const volume::ScalarGrid& grid) const;
    /// @brief classify(grid), the same grid bit for bit, but with `ranges` (the value range of
    /// each block of `grid`, made once for the grid): a block whose range classifies to nothing
    /// (isTransparentBetween()) is skipped, and a DATA range is read from `ranges` instead of
    /// scanning the grid. What a transfer-function edit costs follows the blocks it shows.
    /// `progress` (when set) hears "classifying" and the fraction of the grid walked.
    /// @throws DataError when the fields are invalid; sg::Cancelled when `progress` cancels.
    std::shared_ptr<octree::ClassifiedGrid> classify(const volume::ScalarGrid& grid,
                                                     const octree::ValueRanges& ranges,
                                                     const sg::WorkProgress& progress = {}) const;
    /// @brief classify(grid), adding every non-empty voxel's value to `ranges` (new, for a grid
    /// of `grid`'s dimensions) in the same pass: how a grid's first classification makes the
    /// value ranges that later ones read. `progress` as for classify(grid, ranges).
    /// @throws DataError when the fields are invalid; sg::Cancelled when `progress` cancels.
    std::shared_ptr<octree::ClassifiedGrid>
    classifyRecording(const volume::ScalarGrid& grid, octree::ValueRanges& ranges,
                      const sg::WorkProgress& progress = {}) const;
    /// @brief A grid with one voxel per 8³ block of `grid`, at the block's centre (the grid's
    /// origin moved by 3.5 voxels, its spacing 8 times `grid`'s), holding the block's mean
    /// classification as the octree's node of the block does (empty voxels count as zero; a
    /// block clipped by the grid's upper faces is taken whole: its voxels' sum over 512, at the
    /// whole block's centre), computed from the block's value histogram without reading a
    /// voxel: the bins' counts times the function at the bins' mean values
    /// (octree::ValueHistograms says how close that is). `ranges` and `histograms` are
    /// `grid`'s (classifyRecording(), volume::blockValueHistograms()). What an interactive frame
    /// draws right after an edit: 16 evaluations of the function per block instead of 512.
    /// @throws DataError when the fields are invalid.
    std::shared_ptr<octree::ClassifiedGrid>
    classifyBlockMeans(const volume::ScalarGrid& grid, const octree::ValueRanges& ranges,
                       const octree::ValueHistograms& histograms) const;
    /// @brief Whether every value in [`minimum`, `maximum`] classifies over `scale` to no
    /// emission and no extinction, by classify() and by classifyLevel() alike. Exact where it
    /// answers true (never true for a range holding a visible value); it may answer false for a
    /// range whose values are all transparent only through float underflow, a step exactly at an
    /// end, or a level of an end that shows what the end itself does not.
    bool isTransparentBetween(float minimum, float maximum, const DataScale& scale) const;

    /// @brief Whether `field` (one of this node's) says how values are labelled rather than
    /// how they are classified (`title`, `units`): a change of it needs no new classification.
    bool isLabelField(const sg::Field* field) const {
        return field == &title || field == &units;
    }

    /// @brief Whether `field` is one of the shading fields (`shade`, `ambient`, `diffuse`,
    /// `specular`, `specularPower`): a change of it lights the classified grid again, it does
    /// not classify it again.
    bool isShadingField(const sg::Field* field) const {
        return field == &shade || field == &ambient || field == &diffuse ||
               field == &specular || field == &specularPower;
    }

    /// @brief The lighting coefficients of the shading fields, checked.
    /// @throws DataError naming the first field that is negative or not finite (specularPower:
    /// not positive).
    glm::vec4 shadingCoefficients() const;

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
