#pragma once

#include "nodes/ScalarSplat.h"
#include "nodes/render/MarkDrawing.h"
#include "nodes/volume/Grid.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"

namespace texsplat::kernel {
class VectorSplatTable;
struct VectorTableParameters;
} // namespace texsplat::kernel

namespace texsplat::nodes {

/// @brief Scene-file names of render::MarkOperator.
inline const sg::EnumNames kMarkOperatorNames{{"MODULATE", render::MarkOperator::Modulate},
                                              {"BLEND", render::MarkOperator::Blend}};

/// @brief Base of the splats that draw a vector field as marks (VectorSplat, CombinedSplat;
/// Crawfis & Max 1993, "Combined Vector and Scalar Textures"): each splat carries the vector
/// of the current VolumeData at its voxel (the mean vector of its octree node on coarse cuts)
/// and picks a texture of the vector splat table (kernel::VectorSplatTable, figure 3): its
/// column from how much the vector points at the eye, its row at random (from `seed`) plus the
/// animation `phase`. The square is turned so that the marks run along the projected vector.
///
/// The vector field is the VolumeData's vector grid (a raw file with 3 components, an OpenVDB
/// vec3s grid, or a vector generator); a VolumeData of scalars is an error. Vectors that are
/// NaN or infinite are empty voxels.
///
/// Animation: `phase` is in cycles of the table's rows (1 = every row once); connect it to an
/// engine, `phase = ElapsedTime { speed 0.5 } . timeOut`, whose speed is the paper's slider on
/// the timer. Advancing the phase by 1/tableRows moves every mark one table row along its vector.
///
/// Mask (figure 8, winds only where it is cloudy): with `maskData` set to a scalar VolumeData
/// of the same dimensions, only voxels whose mask value lies in `maskRange` draw marks.
///
/// File format (the fields this base adds to ScalarSplat's):
/// @code
/// operator      MODULATE   # MODULATE, BLEND: the paper's texture operators
/// blendColor    1 1 1      # C_const of BLEND
/// phase         0          # animation phase, in cycles of the table's rows
/// tableRows     16         # animation phases of the table, 1 .. 256
/// tableColumns  8          # foreshortening levels of the table, 1 .. 64
/// markType      PARTICLES  # PARTICLES, SCRATCHES
/// markDensity   1          # marks per square voxel, (0, 64]
/// windowScale   1.15       # the marks' window relative to the scalar splat, [1, 4]
/// seed          1          # random marks and rows, reproducible
/// maskData      NULL       # a scalar VolumeData, or NULL for no mask
/// maskRange     0 1        # mask values that draw, inclusive (used with maskData)
/// @endcode
class VectorMarkSplat : public sg::Declare<VectorMarkSplat, ScalarSplat> {
public:
    /// @brief The abstract type's name.
    static constexpr const char* kTypeName = "VectorMarkSplat";

    sg::SFEnum textureOperator; ///< render::MarkOperator ("operator" in files)
    sg::SFColor blendColor;     ///< C_const of BLEND
    sg::SFFloat phase;          ///< animation phase, cycles of the rows
    sg::SFInt32 tableRows;      ///< animation phases of the table
    sg::SFInt32 tableColumns;   ///< foreshortening levels of the table
    sg::SFEnum markType;        ///< kernel::MarkType
    sg::SFFloat markDensity;    ///< marks per square voxel
    sg::SFFloat windowScale;    ///< window half-width over the scalar splat's
    sg::SFInt32 seed;           ///< marks and random rows
    sg::SFNode maskData;        ///< scalar VolumeData masking the marks, or none
    sg::SFVec2f maskRange;      ///< mask values that draw

    ~VectorMarkSplat() override;

    /// @brief The table parameters of the current field values.
    kernel::VectorTableParameters tableParameters() const;

    /// @brief The vector splat table of the current field values, made on first use and shared
    /// with every node of the same table parameters (kernel::VectorSplatTable::shared()); the
    /// node keeps it while its parameters stay the same. A scene without vector splats makes none.
    /// @throws DataError naming the node when a table field is out of range.
    std::shared_ptr<const kernel::VectorSplatTable> table() const;

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

    std::optional<octree::VectorEmission> vectorEmission() const override;
    /// @brief False: the vector and combined grids are classified here, with their vectors.
    bool previewsEdits() const override { return false; }
    render::MarkDrawing markDrawing() const override;
    bool isDrawingField(const sg::Field* field) const override;
    bool isClassificationField(const sg::Field* field) const override;
    void checkFields() const override;

private:
    mutable std::shared_ptr<const kernel::VectorSplatTable> mTable;
};

} // namespace texsplat::nodes
