#pragma once

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "scenegraph/Node.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace texsplat::apps {

/// @brief What the viewer's panel edits of a scene's transfer functions: the value range, the
/// opacity control points (moved, added, removed), a factor on the opacities and the colour
/// preset of one TransferFunction at a time, and the data's histogram the panel draws them over.
///
/// It edits the nodes' fields, so the scene graph notices an edit like any other change and the
/// splat nodes re-classify from their grid's value ranges without rebuilding them
/// (docs/octree.md, "Transfer-function edits"). The range it shows and sets is in data values:
/// setting it makes the node's `rangeMode` FIXED. Its bounds are the value range of the data the
/// function classifies, read once, when first asked for: the VolumeData in effect at the first
/// splat node that the function is in effect at (the scene's first VolumeData for a function no
/// splat node uses). A field that is connected follows its connection and is
/// not offered; the preset only while neither `colors` nor `colorMapFile` replaces it. reset()
/// restores every field as it was when the editor was made, default flags included, so a range
/// that came from the data comes from the data again.
class TransferFunctionEditor {
public:
    /// @brief Finds the TransferFunction nodes under `root` (in traversal order, each once) and
    /// the scene's first VolumeData, and remembers the fields it may edit.
    explicit TransferFunctionEditor(sg::Node& root);

    /// @brief True when the scene has no TransferFunction.
    bool isEmpty() const { return mFunctions.empty(); }

    /// @brief How many transfer functions there are.
    std::size_t count() const { return mFunctions.size(); }

    /// @brief How the panel names function `index`: its node name, or its place in the scene.
    std::string label(std::size_t index) const;

    /// @brief The function the editing calls below apply to (0 at first).
    std::size_t selected() const { return mSelected; }

    /// @brief Selects function `index` (< count()).
    void select(std::size_t index);

    /// @brief Whether the range can be edited (`range` and `rangeMode` are not connected).
    bool editsRange() const;

    /// @brief The data values the selected function maps onto its colour map's ends now.
    /// @throws what reading the volume throws (the first call, for a range from the data).
    glm::vec2 range();

    /// @brief The values range() may take: the data's smallest and largest value (for a scene
    /// without VolumeData, the function's original range widened by half its width on each
    /// side), widened to hold the present range.
    /// @throws what reading the volume throws (the first call).
    glm::vec2 rangeBounds();

    /// @brief Maps `range` (low < high, finite) onto the colour map: `range` set, `rangeMode`
    /// FIXED. Throws DataError for a range that is not increasing or not finite.
    void setRange(glm::vec2 range);

    /// @brief Whether the opacities can be edited: `opacities` and `opacityValues` hold as many
    /// values (at least one) and neither is connected.
    bool editsOpacity() const;

    /// @brief The opacity control points the editor shapes, (position t in [0, 1] of the range,
    /// opacity before the factor), in order; the function's own at first. The function's
    /// `opacityValues` are their positions and its `opacities` their opacities times
    /// opacityFactor().
    const std::vector<glm::vec2>& opacityPoints() const { return current().points; }

    /// @brief Moves point `index` (< opacityPoints().size()) to `point`: its position clamped to
    /// [0, 1] and between its neighbours' (positions must not decrease), its opacity to >= 0.
    /// Throws DataError for a point that is not finite or an index out of range.
    void moveOpacityPoint(std::size_t index, glm::vec2 point);

    /// @brief Adds a control point at `point` (position clamped to [0, 1], opacity to >= 0),
    /// after the points at the same or a lower position; returns its index. Throws DataError for
    /// a point that is not finite.
    std::size_t addOpacityPoint(glm::vec2 point);

    /// @brief Removes point `index`, unless it is the last one left (a function needs one).
    /// Throws DataError for an index out of range.
    void removeOpacityPoint(std::size_t index);

    /// @brief The factor on the points' opacities (1 at first).
    float opacityFactor() const;

    /// @brief Sets `opacities` to `factor` (finite, > 0) times the points' opacities. Throws
    /// DataError for any other factor.
    void setOpacityFactor(float factor);

    /// @brief How many of the values of the data the selected function classifies fall into
    /// each of `bins` equal bins over dataRange(): made once per bin count (one walk over the
    /// grid's non-empty voxels), all zero without VolumeData.
    /// @throws what reading the volume throws.
    const std::vector<std::uint64_t>& histogram(std::size_t bins);

    /// @brief The data's smallest and largest value (see rangeBounds()).
    /// @throws what reading the volume throws (the first call).
    glm::vec2 dataRange();

    /// @brief Whether the colour preset is in effect and can be set.
    bool editsPreset() const;

    /// @brief The preset in effect.
    nodes::ColorPreset preset() const;

    /// @brief Sets the preset.
    void setPreset(nodes::ColorPreset preset);

    /// @brief The selected function's colour map S(t) at `t` in [0, 1] (RGB).
    /// @throws DataError when its fields are invalid.
    glm::vec3 colorAt(float t) const { return current().node->colorAt(t); }

    /// @brief The selected function as scene-file text (its node alone, without the file
    /// header), to paste into a scene file.
    std::string sceneText() const;

    /// @brief True when any field of the selected function differs from what it was at first.
    bool isEdited() const;

    /// @brief Restores the selected function's fields (values and default flags).
    void reset();

private:
    // What an editable field was when the editor was made.
    struct Original {
        glm::vec2 range;
        bool rangeIsDefault;
        int rangeMode;
        bool rangeModeIsDefault;
        std::vector<float> opacityValues;
        bool opacityValuesIsDefault;
        std::vector<float> opacities;
        bool opacitiesIsDefault;
        int preset;
        bool presetIsDefault;
    };
    struct Function {
        std::shared_ptr<nodes::TransferFunction> node;
        Original original;
        std::vector<glm::vec2> points; // the opacity control points, before the factor
        float opacityFactor = 1.0f;
        std::optional<glm::vec2> range; // the range in effect, once asked for
        std::shared_ptr<const nodes::VolumeData> volume; // the data it classifies, if any
        std::optional<glm::vec2> dataRange;               // the data's value range, once asked for
        std::vector<std::uint64_t> histogram;             // over dataRange, once asked for
    };

    Function& current() { return mFunctions[mSelected]; }
    const Function& current() const { return mFunctions[mSelected]; }
    // The control points of `original`'s opacities; none when their positions do not match them
    // (the function refuses such fields, so there is nothing to edit).
    static std::vector<glm::vec2> pointsOf(const Original& original);
    // Writes the selected function's points and factor into its fields.
    void writeOpacities();

    // Gives each function the volume it classifies.
    void findVolumes(sg::Node& root);

    std::vector<Function> mFunctions;
    std::size_t mSelected = 0;
};

} // namespace texsplat::apps
