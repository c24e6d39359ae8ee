#pragma once

#include "nodes/volume/Aerogel.h"
#include "nodes/volume/Grid.h"
#include "nodes/volume/IndexBox.h"
#include "nodes/volume/RawHeader.h"
#include "nodes/volume/WholeGrid.h"
#include "scenegraph/Box3.h"
#include "scenegraph/Declare.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/io/RelativeFileNames.h"

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace texsplat::volume::detail {
struct RawDataView;
using RawDataDecoder = std::function<void(const RawDataView& data)>;
} // namespace texsplat::volume::detail

namespace texsplat::nodes {

/// @brief Where VolumeData takes its grid from.
enum class VolumeSource {
    FileRaw,       ///< a texsplat-raw file (`fileName`), scalar or vector
    FileVdb,       ///< grid `gridName` of an OpenVDB file (`fileName`), scalar or vector
    FileRawHeaderless, ///< raw values without a header (`fileName`), laid out as `dimensions`,
                       ///< `dataType`, `byteOrder`, `headerBytes` and `components` say
    FileNpy,           ///< a NumPy .npy array (`fileName`): (z, y, x) scalars, (z, y, x, 3) vectors
    FileNrrd,          ///< a NRRD volume (`fileName`: .nrrd, or a detached .nhdr header)
    FileNetCdf,        ///< variable `gridName` of a NetCDF file (`fileName`), step `timeStep`
    Tornado,       ///< Crawfis's tornado (vectors; `resolution`, `time`)
    MarschnerLobb, ///< the Marschner-Lobb test signal (scalar; `resolution`)
    Blob,          ///< a sum of seeded Gaussians (scalar; `resolution`)
    JetStream,     ///< synthetic climate data: wind vectors, scalar "cloudiness" (`time` in days)
    Aerogel,       ///< flow through random fibers (vectors; fibers())
    Memory,        ///< a grid a program made in memory and gave with setGrid() (no file)
};

/// @brief Scene-file names of VolumeSource.
inline const sg::EnumNames kVolumeSourceNames{{"FILE_RAW", VolumeSource::FileRaw},
                                              {"FILE_VDB", VolumeSource::FileVdb},
                                              {"FILE_RAW_HEADERLESS",
                                               VolumeSource::FileRawHeaderless},
                                              {"FILE_NPY", VolumeSource::FileNpy},
                                              {"FILE_NRRD", VolumeSource::FileNrrd},
                                              {"FILE_NETCDF", VolumeSource::FileNetCdf},
                                              {"TORNADO", VolumeSource::Tornado},
                                              {"MARSCHNER_LOBB", VolumeSource::MarschnerLobb},
                                              {"BLOB", VolumeSource::Blob},
                                              {"JET_STREAM", VolumeSource::JetStream},
                                              {"AEROGEL", VolumeSource::Aerogel},
                                              {"MEMORY", VolumeSource::Memory}};

/// @brief Scene-file names of the value types of FILE_RAW_HEADERLESS (`dataType`).
inline const sg::EnumNames kVolumeDataTypeNames{{"UINT8", volume::RawValueType::UInt8},
                                                {"INT8", volume::RawValueType::Int8},
                                                {"UINT16", volume::RawValueType::UInt16},
                                                {"INT16", volume::RawValueType::Int16},
                                                {"UINT32", volume::RawValueType::UInt32},
                                                {"INT32", volume::RawValueType::Int32},
                                                {"FLOAT32", volume::RawValueType::Float32},
                                                {"FLOAT64", volume::RawValueType::Float64}};

/// @brief Scene-file names of the byte orders of FILE_RAW_HEADERLESS (`byteOrder`).
inline const sg::EnumNames kVolumeByteOrderNames{{"LITTLE", volume::RawEndian::Little},
                                                 {"BIG", volume::RawEndian::Big}};

/// @brief How VolumeData makes the scalar that scalar splats classify, from vector data.
enum class VolumeComponent {
    Magnitude, ///< |v| (paper, Figures 5-7: opacity from the vector magnitude)
    Scalar,    ///< a scalar grid of the source, named by `gridName` (JET_STREAM: "cloudiness")
};

/// @brief Scene-file names of VolumeComponent.
inline const sg::EnumNames kVolumeComponentNames{{"MAGNITUDE", VolumeComponent::Magnitude},
                                                 {"SCALAR", VolumeComponent::Scalar}};

/// @brief A volume for the splat nodes that follow: a grid read from a file or made by a
/// generator (nodes/volume/, docs/data.md), loaded on first use and cached.
///
/// Nothing is read or generated until something asks (scalarGrid(), vectorGrid(), fibers(), a
/// bounding box): a scene pays only for the grids it references. Any change of a field drops the
/// cache, and the next use loads again. Nodes that read the same file with the same fields share
/// one load and one grid while any of them holds it (a changed file is read again); the grid is
/// released when the last holder drops it. Errors name the node and then the source:
/// "VolumeData 'cloud': cloud.raw: cannot open file (No such file or directory)".
/// Splat nodes load through load() with their action's sg::WorkProgress, which is told how
/// reading the file goes and may cancel it. A load without one (the accessors below, called first)
/// logs its progress at LogLevel::Info when it is long, named like the errors
/// ("VolumeData 'cloud': cloud.raw: reading 40%"; when, see volume::logProgress()).
///
/// Fields:
/// - `source`: see VolumeSource.
/// - `fileName`: the file of the FILE_ sources. A relative name is relative to the folder of the
///   scene file the node was read from (sg::RelativeFileNames), or to the working directory for
///   a node made in C++; errors name the path tried.
/// - `gridName`: FILE_VDB: the grid in the file (may stay empty when the file has one grid);
///   FILE_NETCDF: the variable (may stay empty when one variable is 3-D or 4-D), or three
///   variables separated by spaces, the x, y and z components of vectors ("u v w"); with
///   `component SCALAR`: the generator's scalar grid (JET_STREAM: "cloudiness").
/// - `resolution`: samples along x, y, z for the generators, as an SFVec3f of whole numbers >= 1
///   (Inventor has no integer vector field); files bring their own.
/// - `time`: animation time of TORNADO (frames) and JET_STREAM (days).
/// - `timeStep`: FILE_NETCDF: the step of a 4-D variable's first (time) dimension, from 0.
/// - `component`: how scalarGrid() is made from vector data (VolumeComponent); scalar data is
///   used as it is with either value.
/// - `dimensions`, `dataType`, `byteOrder`, `headerBytes`, `components`: the layout of a
///   FILE_RAW_HEADERLESS file: voxels along x, y, z (whole numbers >= 1, x fastest in the file),
///   the value type, the byte order of multi-byte values, bytes to skip before the values, and
///   1 (scalars) or 3 (vectors, x y z interleaved per voxel). The file must hold exactly
///   `headerBytes` plus the values.
/// - `origin`, `spacing`: where the voxels lie, for any source: the centre of voxel (0,0,0) and
///   the distance between voxel centres along x, y and z (finite, and > 0 for spacing). Empty
///   (the default): the source's own (a file's header or coordinates; 0 and 1 for raw and NumPy
///   files). One value places the grid there without a copy (volume::PlacedGrid), so that data
///   without geometry lines up with data that has it: winds from a `.npy` over clouds from a
///   NetCDF file.
///
/// The node's bounding box is the box the grid's voxel cells cover (GridGeometry bounds) under
/// the model matrix. During a traversal the node puts itself into VolumeElement. The accessors
/// may be called from several threads; each answers a consistent grid.
///
/// File format:
/// @code
/// VolumeData {
///     source      BLOB   # FILE_RAW, FILE_VDB, FILE_RAW_HEADERLESS, FILE_NPY, FILE_NRRD,
///                        # FILE_NETCDF, TORNADO, MARSCHNER_LOBB, BLOB, JET_STREAM, AEROGEL,
///                        # MEMORY (setGrid() in C++)
///     fileName    ""
///     gridName    ""
///     resolution  64 64 64
///     time        0
///     timeStep    0
///     component   MAGNITUDE   # MAGNITUDE, SCALAR
///     dimensions  0 0 0
///     dataType    FLOAT32     # UINT8, INT8, UINT16, INT16, UINT32, INT32, FLOAT32, FLOAT64
///     byteOrder   LITTLE      # LITTLE, BIG
///     headerBytes 0
///     components  1
///     origin      [ ]         # one x y z, or none: the source's
///     spacing     [ ]         # one x y z (> 0), or none: the source's
/// }
/// @endcode
class VolumeData : public sg::Declare<VolumeData, sg::Node>, public sg::RelativeFileNames {
public:
    /// @brief The scene-file name.
    static constexpr const char* kTypeName = "VolumeData";

    sg::SFEnum source;      ///< VolumeSource
    sg::SFString fileName;  ///< the file of the FILE_ sources
    sg::SFString gridName;  ///< VDB grid, NetCDF variable, or the generator's scalar grid
    sg::SFVec3f resolution; ///< generator samples per axis (whole numbers)
    sg::SFFloat time;       ///< generator time
    sg::SFInt32 timeStep;   ///< FILE_NETCDF step of a (time, z, y, x) variable
    sg::SFEnum component;   ///< VolumeComponent
    sg::SFVec3f dimensions; ///< FILE_RAW_HEADERLESS voxels per axis (whole numbers)
    sg::SFEnum dataType;    ///< FILE_RAW_HEADERLESS value type (volume::RawValueType)
    sg::SFEnum byteOrder;   ///< FILE_RAW_HEADERLESS byte order (volume::RawEndian)
    sg::SFInt32 headerBytes; ///< FILE_RAW_HEADERLESS bytes before the values
    sg::SFInt32 components; ///< FILE_RAW_HEADERLESS values per voxel: 1 or 3
    sg::MFVec3f origin;     ///< centre of voxel (0,0,0), or none: the source's
    sg::MFVec3f spacing;    ///< distance between voxel centres, or none: the source's

    /// @brief The scalar field for scalar splats: scalar data as it is, vector data as
    /// `component` says. Loads on first use.
    /// @throws IoError, ParseError or DataError (prefixed with the node) when loading fails or
    /// the component cannot be made.
    volume::ScalarGridPtr scalarGrid() const;

    /// @brief The vector field, or nullptr when the source gives scalar data. Loads on first use.
    /// @throws as scalarGrid().
    volume::VectorGridPtr vectorGrid() const;

    /// @brief The fibers of the AEROGEL source (polygon geometry inside the volume, paper
    /// Figure 7); empty for the other sources. Loads on first use.
    /// @throws as scalarGrid().
    std::vector<volume::Fiber> fibers() const;

    /// @brief The box the voxel cells cover, in the node's local space. Loads on first use.
    /// @throws as scalarGrid().
    sg::Box3 bounds() const;

    /// @brief Draws `grid`, which the program made in memory: a volume::ExternalGrid over its
    /// own array (no copy), volume::gridFromVdb() of an OpenVDB grid, or any volume::Grid. Sets
    /// `source` to MEMORY and notifies, so the next render draws it. The node holds the grid
    /// until the next setGrid() or its own end (volume::ExternalGrid says how long the array
    /// must live). A scene file cannot hold such a grid: written out, the node says `source
    /// MEMORY`, and reading it back gives a node whose use throws DataError.
    void setGrid(volume::AnyGrid grid);

    /// @brief Loads the source now unless the node holds it already: what the accessors would
    /// do on first use, but reporting to `progress` (a traversal's Action::workProgress()).
    ///
    /// Reading a file tells `progress` the reader's step and the file's name ("reading from
    /// cloud.raw", "reading grid 'density' from cloud.vdb", then "copying grid 'density' from
    /// cloud.vdb") with the fraction done, from 0 to 1, at most once per percent (docs/data.md says
    /// how finely each format reports). Generators and a grid that another node sharing the
    /// file holds report nothing. Without `progress` (empty) the load logs as the accessors do.
    /// Calls `progress` only on the calling thread, with the node locked: the callback must not
    /// use this node.
    /// @throws sg::Cancelled ("VolumeData 'cloud': reading from cloud.raw: cancelled") when
    /// `progress` answered false: nothing read is kept, here or in the grids shared with other
    /// nodes, so the next use loads again; else as scalarGrid().
    void load(const sg::WorkProgress& progress) const;

    /// @brief Whether the source is loaded now (the cache holds it).
    bool isLoaded() const;

    /// @brief Makes this node serve one brick of its grid, for a render split over processes
    /// (nodes/distributed, docs/distributed.md): from now on a load reads or generates only the
    /// voxels of `region` (a box of the whole grid, wholeGeometry(); an empty one: none, the
    /// accessors then answer one empty voxel), and the accessors answer bricks
    /// (volume::BrickGrid) that know the whole grid's figures, once setWholeGrids() has given
    /// them. bounds() stays the whole grid's box. `std::nullopt` makes the node whole again.
    /// Drops the cache when the region changes.
    void setBrick(const std::optional<volume::IndexBox>& region);

    /// @brief The region setBrick() set, or `std::nullopt` for a whole node.
    std::optional<volume::IndexBox> brick() const;

    /// @brief The whole grid's dimensions, origin and spacing, from the file's header or the
    /// generator's fields without reading the voxels (one voxel of a generator is made): what a
    /// distributed render splits into bricks. For MEMORY, the grid's.
    /// @throws as scalarGrid().
    volume::GridGeometry wholeGeometry() const;

    /// @brief For a brick (setBrick()): its grids as loaded, loading first (reporting to
    /// `progress` as load() does): the source's grid, then a generator's further scalar grids in
    /// the order of their names. What the whole grid's figures are gathered from.
    /// @throws as load(); DataError when the node is whole.
    std::vector<volume::AnyGrid> brickGrids(const sg::WorkProgress& progress = {}) const;

    /// @brief For a brick: what the whole grid knows of each of brickGrids(), in that order,
    /// gathered over the processes. From now on (until the next load) the accessors answer
    /// bricks with these figures; a vector grid's magnitudes share its figures. Before this, the
    /// accessors of a brick throw DataError.
    /// @throws DataError when the node is whole, not loaded, or `wholes` does not match
    /// brickGrids().
    void setWholeGrids(const std::vector<std::shared_ptr<const volume::WholeGrid>>& wholes);

    /// @brief Puts this node into VolumeElement and extends the action's box by bounds().
    void getBoundingBox(sg::BoundingBoxAction& action) override;

    /// @brief Puts this node into VolumeElement.
    void doAction(sg::Action& action) override;

    /// @brief Drops the cached grids, then notifies as every node does.
    void notify(const sg::Field* source) override;

protected:
    VolumeData();

private:
    struct Loaded;

    // The cached data, loaded first when there is none (reporting to `progress`); called with
    // mMutex held.
    std::shared_ptr<const Loaded> loaded(const sg::WorkProgress& progress = {}) const;
    // The source's data: a file load shared with other nodes loading the same (detail::sharedLoad),
    // or read().
    std::shared_ptr<const Loaded> loadShared(const sg::WorkProgress& progress) const;
    // Reads or generates the source's data: the whole grid, or the voxels of `region` (not
    // empty, inside the grid).
    std::shared_ptr<const Loaded> read(const sg::WorkProgress& progress,
                                       const std::optional<volume::IndexBox>& region = {}) const;
    glm::i64vec3 dims() const;
    volume::RawHeader headerlessLayout() const;
    // The geometry `origin` and `spacing` give a grid of geometry `own` that starts at voxel
    // `offset` of the whole grid (a brick's).
    volume::GridGeometry placedGeometry(const volume::GridGeometry& own,
                                        const glm::i64vec3& offset) const;
    // `grid` where `origin` and `spacing` put it: itself when both are empty. A brick's grid
    // starts at voxel `offset` of the whole grid, which the fields place.
    template <typename T>
    std::shared_ptr<const volume::Grid<T>> placed(std::shared_ptr<const volume::Grid<T>> grid,
                                                  const glm::i64vec3& offset) const;
    // The data of a brick (setBrick()) of a source whose whole grid is `whole`.
    std::shared_ptr<const Loaded> readBrick(const sg::WorkProgress& progress,
                                            const volume::GridGeometry& whole) const;
    // wholeGeometry(); called with mMutex held.
    volume::GridGeometry wholeGeometryHeld() const;
    // What hands the raw values of `path` to a decoder, for the sources of raw values
    // (texsplat-raw, headerless raw, NumPy, NRRD).
    std::function<void(const volume::detail::RawDataDecoder&)>
    rawData(const std::string& path) const;
    // The grid of an OpenVDB file to read: gridName, or the file's only grid.
    std::string vdbGridName(const std::string& path) const;
    // The loaded data, checked to be ready for the accessors (a brick's whole figures given).
    std::shared_ptr<const Loaded> servedData() const;

    mutable std::mutex mMutex;
    mutable std::shared_ptr<const Loaded> mLoaded;
    mutable volume::ScalarGridPtr mScalar;  // placed, made once per load
    mutable volume::VectorGridPtr mVectors; // placed, made once per load
    volume::AnyGrid mMemoryGrid; // source MEMORY: setGrid()'s grid (guarded by mMutex)
    std::optional<volume::IndexBox> mBrick; // setBrick()'s region (guarded by mMutex)
};

} // namespace texsplat::nodes
