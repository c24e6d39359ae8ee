#pragma once

#include "nodes/ScalarSplat.h"
#include "nodes/render/MarkDrawing.h"
#include "nodes/volume/Grid.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_float3.hpp>
#include <glm/ext/vector_uint3_sized.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::octree {
class VoxelShadows;
} // namespace texsplat::octree

namespace texsplat::nodes {

/// @brief Scene-file names of render::MarkOperator.
inline const sg::EnumNames kMarkOperatorNames{{"MODULATE", render::MarkOperator::Modulate},
                                              {"BLEND", render::MarkOperator::Blend}};

/// @brief Scene-file names of render::MarkType.
inline const sg::EnumNames kMarkTypeNames{{"PARTICLES", render::MarkType::Particles},
                                          {"SCRATCHES", render::MarkType::Scratches}};

/// @brief Base of the splats that draw a vector field as marks (VectorSplat, CombinedSplat;
/// Crawfis & Max 1993, "Combined Vector and Scalar Textures": "tiny vector particles, or
/// scratch marks"): marks drawn at random among the non-empty voxels (octree::MarkSource), each
/// at a random point of its voxel's cell with that voxel's vector, drawn as a streak along the vector's projection with a
/// sharp head downstream and a tail that fades upstream (docs/vector-splats.md).
///
/// How many marks: `markDensity` is how much of the image the marks cover (their area over the
/// image area under the data, counting overlaps), whatever the data's depth and the zoom: the
/// node divides it by a mark's area on screen and by the mean number of voxels behind a pixel
/// (octree::VoxelShadows) to get the marks per voxel. How large: `markLength` and `markWidth`
/// voxels, but never narrower than 5 pixels (2.7 at half opacity) nor, in the image plane, shorter
/// than 20 pixels, so that marks stay legible when the voxels are small on screen.
///
/// The vector field is the VolumeData's vector grid (a raw file with 3 components, an OpenVDB
/// vec3s grid, or a vector generator); a VolumeData of scalars is an error. Vectors that are
/// NaN or infinite are empty voxels.
///
/// Animation: `phase` is in life cycles of the marks; connect it to an engine, `phase =
/// ElapsedTime { speed 0.5 } . timeOut`, whose speed is the paper's slider on the timer. In one
/// cycle each mark moves one mark length along its vector, fading in at the start and out at
/// the end: the marks flow, and the animation loops seamlessly at every whole cycle.
///
/// Mask (figure 8, winds only where it is cloudy): with `maskData` set to a scalar VolumeData
/// of the same dimensions, only voxels whose mask value lies in `maskRange` draw marks.
///
/// File format (the fields this base adds to ScalarSplat's):
/// @code
/// operator      MODULATE   # MODULATE, BLEND: the marks' colour
/// blendColor    1 1 1      # the colour BLEND mixes towards
/// phase         0          # animation phase, in life cycles of the marks
/// markType      SCRATCHES  # SCRATCHES (streaks), PARTICLES (comets)
/// markDensity   0.6        # how much of the image the marks cover, (0, 4]
/// markLength    2.5        # voxels, (0, 64]
/// markWidth     0.08       # voxels, (0, 8]
/// seed          1          # random marks, reproducible
/// maskData      NULL       # a scalar VolumeData, or NULL for no mask
/// maskRange     0 1        # mask values that draw, inclusive (used with maskData)
/// @endcode
class VectorMarkSplat : public sg::Declare<VectorMarkSplat, ScalarSplat> {
public:
    /// @brief The abstract type's name.
    static constexpr const char* kTypeName = "VectorMarkSplat";

    sg::SFEnum textureOperator; ///< render::MarkOperator ("operator" in files)
    sg::SFColor blendColor;     ///< what BLEND mixes towards
    sg::SFFloat phase;          ///< animation phase, life cycles of the marks
    sg::SFEnum markType;        ///< render::MarkType
    sg::SFFloat markDensity;    ///< how much of the image the marks cover
    sg::SFFloat markLength;     ///< voxels
    sg::SFFloat markWidth;      ///< voxels
    sg::SFInt32 seed;           ///< the random marks
    sg::SFNode maskData;        ///< scalar VolumeData masking the marks, or none
    sg::SFVec2f maskRange;      ///< mask values that draw

    /// @brief The largest markDensity.
    static constexpr float kMaxMarkDensity = 4.0f;
    /// @brief The largest markLength, in voxels.
    static constexpr float kMaxMarkLength = 64.0f;
    /// @brief The largest markWidth, in voxels.
    static constexpr float kMaxMarkWidth = 8.0f;

    ~VectorMarkSplat() override;

    /// @brief How far from a voxel's centre its marks reach, in voxels (the cell's corner, a
    /// mark length for half a mark and half its travel, half a mark width).
    double markReach() const;

    /// @brief For a brick of a volume split over processes (nodes/distributed): the whole
    /// volume's figures that its marks follow instead of the brick's, so that every brick draws
    /// the whole's marks of its own voxels (octree::MarkSource: marks per cell of the whole).
    struct WholeVolume {
        std::shared_ptr<const octree::VoxelShadows> shadows; ///< of the whole classified grid
        glm::dvec3 centre{0.0};                              ///< its centre (local space)
        glm::vec3 low{0.0f};     ///< its box's smallest corner (local space): marks are cut to it
        glm::vec3 high{0.0f};    ///< its box's largest corner
        glm::u64vec3 offset{0}; ///< the brick's voxel (0, 0, 0) in the whole grid
    };
    /// @brief Sets the whole volume this node's grid is a brick of; nullptr: its own.
    void setWholeVolume(std::shared_ptr<const WholeVolume> whole) { mWhole = std::move(whole); }

protected:
    VectorMarkSplat();

    /// @brief The current vector grid; throws DataError when the VolumeData holds scalars.
    volume::VectorGridPtr vectorGrid(const VolumeData& volume) const;

    /// @brief The scalar grid of the VolumeData in `field` (`maskData`, VectorSplat's
    /// `colorData`), nullptr when the field is NULL; throws DataError when its dimensions differ
    /// from `geometry`'s (checkFields() made sure it is a VolumeData).
    volume::ScalarGridPtr companionGrid(const sg::SFNode& field,
                                        const volume::GridGeometry& geometry) const;

    /// @brief Throws DataError unless `field` is NULL or a VolumeData.
    static void checkVolumeField(const sg::SFNode& field);

    /// @brief Whether `value` of the mask lets a voxel draw.
    bool isInMask(float value) const;

    const std::vector<octree::SplatMark>*
    frameMarks(const std::shared_ptr<const octree::ClassifiedGrid>& classified,
               render::FrameSplats& batch, int width, int height) override;
    /// @brief False: the vector and combined grids are classified here, with their vectors.
    bool previewsEdits() const override { return false; }
    render::MarkDrawing markDrawing() const override;
    bool isDrawingField(const sg::Field* field) const override;
    bool isClassificationField(const sg::Field* field) const override;
    void checkFields() const override;

private:
    // What the marks of the last classified grid come from, kept while it is the one drawn, and
    // the marks drawn last, for that seed and marks per voxel (negative: none drawn yet).
    struct MarkCache {
        std::weak_ptr<const octree::ClassifiedGrid> of;
        glm::u64vec3 offset{0};
        std::shared_ptr<const octree::VoxelShadows> shadows;
        std::shared_ptr<const octree::MarkSource> source;
        std::uint32_t seed = 0;
        double marksPerVoxel = -1.0;
        std::vector<octree::SplatMark> marks;
    };
    MarkCache mMarks;
    std::shared_ptr<const WholeVolume> mWhole; // setWholeVolume()
};

} // namespace texsplat::nodes
