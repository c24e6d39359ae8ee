#include "nodes/volume/VdbVolume.h"

#include "scenegraph/Error.h"

#ifdef TEXSPLAT_WITH_OPENVDB
#include "nodes/volume/SparseGrid.h"
#include "nodes/volume/VdbGrid.h"
#include "nodes/volume/detail/Printable.h"
#include "nodes/volume/detail/ReportingFileStream.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "nodes/volume/detail/VdbHeader.h"
#include "scenegraph/MemoryLimit.h"

#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>

#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <utility>
#include <vector>
#endif

namespace texsplat::volume {

#ifdef TEXSPLAT_WITH_OPENVDB
namespace {

constexpr std::int64_t kProgressInterval = std::int64_t{1} << 16;

glm::vec3 toGlm(const openvdb::Vec3f& v) { return {v.x(), v.y(), v.z()}; }
float toGlm(float v) { return v; }

// Runs a call into OpenVDB's reader. A damaged file makes it throw its own exceptions
// ("KeyError: Map is not registered"), std::bad_alloc for sizes it believes, or other standard
// exceptions; each becomes IoError(failure(reason)), so the message names the file. OpenVDB's
// reason quotes what it read, from a damaged file any bytes and up to kilobytes of them: it is
// escaped and cut.
template <typename Call, typename Failure>
auto callOpenVdb(Call&& call, Failure&& failure) {
    try {
        return call();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw IoError(failure("it declares more data than fits in memory (std::bad_alloc)"));
    } catch (const std::exception& error) {
        constexpr std::size_t kMaxReasonLength = 160;
        throw IoError(failure(detail::printable(error.what(), kMaxReasonLength)));
    }
}

std::string corrupt(const std::string& path, const std::string& reason) {
    return path + ": truncated or corrupt VDB file: " + reason;
}

// "1 internal node of 32^3, 8 of 16^3 and 40 leaves": what a tree's memory goes to.
std::string nodesText(const detail::VdbNodeCounts& nodes) {
    return std::to_string(nodes.upper) + " internal node" + (nodes.upper == 1 ? "" : "s") +
           " of 32^3, " + std::to_string(nodes.lower) + " of 16^3 and " +
           std::to_string(nodes.leaves) + (nodes.leaves == 1 ? " leaf" : " leaves");
}

// Opens with OpenVDB after checking the path ourselves, so a missing file gets the same message
// as from the raw reader instead of OpenVDB's wording, and every size and count the file
// declares (header, metadata, transforms, trees) against the file before OpenVDB allocates or
// loops for them. A file written as a stream has its trees read on opening: what they need is
// checked against the memory limit first. `trees` receives what the walk found.
std::unique_ptr<openvdb::io::File> openVdb(const std::string& path,
                                           detail::VdbFileTrees& trees) {
    openvdb::initialize();
    detail::openForReading(path);
    trees = detail::checkVdbDeclaredSizes(path);
    if (trees.streamed) {
        std::uint64_t bytes = 0;
        for (const auto& grid : trees.grids)
            bytes = byteSum(bytes, grid.second.bytes);
        const std::size_t grids = trees.grids.size();
        detail::checkFitsInMemory(path + ": reading the trees of its " + std::to_string(grids) +
                                      (grids == 1 ? " grid" : " grids") +
                                      " into OpenVDB, which reads them all on opening a file "
                                      "written as a stream,",
                                  bytes);
    }
    auto file = std::make_unique<openvdb::io::File>(path);
    callOpenVdb([&] { return file->open(false); },
                [&](const std::string& reason) {
                    return path + ": cannot read OpenVDB file (" + reason + ")";
                });
    return file;
}

std::vector<VdbGridInfo> gridInfos(openvdb::io::File& file, const std::string& path) {
    std::vector<VdbGridInfo> infos;
    const openvdb::GridPtrVecPtr grids = callOpenVdb(
        [&] { return file.readAllGridMetadata(); },
        [&](const std::string& reason) { return corrupt(path, reason); });
    for (const openvdb::GridBase::Ptr& grid : *grids)
        infos.push_back({grid->getName(), grid->valueType()});
    return infos;
}

// Reads one grid as openvdb::io::File::readGrid() does, through a ReportingFileStream, so that
// `progress` learns how much of the grid's bytes OpenVDB has read and can stop it: io::File reads
// from an ifstream of its own that no one else sees. For a file written with grid offsets (by
// io::File), which lets it skip the other grids; io::File reads a file written as a stream whole
// on opening.
class ReportingGridReader : public openvdb::io::Archive {
public:
    openvdb::GridBase::Ptr read(const std::string& path, const std::string& gridName,
                                const ProgressCallback& progress, const std::string& message) {
        detail::ReportingFileStream in(path, progress, message);
        readHeader(in);
        // What io::File::open() tells the stream about the file, for the grid's readers.
        auto metadata = std::make_shared<openvdb::io::StreamMetadata>();
        metadata->setSeekable(true);
        openvdb::io::setStreamMetadataPtr(in, metadata, /*transfer=*/false);
        setFormatVersion(in);
        setLibraryVersion(in);
        setDataCompression(in);
        openvdb::MetaMap().readMeta(in);
        std::vector<openvdb::io::GridDescriptor> descriptors;
        for (std::int32_t i = 0, count = readGridCount(in); i < count; ++i) {
            descriptors.emplace_back().read(in);
            descriptors.back().seekToEnd(in);
        }
        const openvdb::io::GridDescriptor& descriptor = find(descriptors, gridName);
        if (!descriptor.isInstance()) {
            in.reportRange(descriptor.getGridPos(), descriptor.getEndPos());
            return readOne(in, descriptor);
        }
        // An instance holds its metadata and transform; the tree is its parent's.
        openvdb::GridBase::Ptr grid = readOne(in, descriptor);
        const openvdb::io::GridDescriptor& parent =
            findUnique(descriptors, descriptor.instanceParentName());
        in.reportRange(parent.getGridPos(), parent.getEndPos());
        grid->setTree(readOne(in, parent)->baseTreePtr());
        return grid;
    }

private:
    static openvdb::GridBase::Ptr readOne(std::istream& in,
                                          const openvdb::io::GridDescriptor& descriptor) {
        openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(descriptor.gridType());
        grid->setSaveFloatAsHalf(descriptor.saveFloatAsHalf());
        descriptor.seekToGrid(in);
        Archive::readGrid(grid, descriptor, in);
        return grid;
    }

    // The descriptor io::File::readGrid() takes for `name`: the first grid of that name, or the
    // one with that unique name ("density[1]", the second grid named "density").
    static const openvdb::io::GridDescriptor&
    find(const std::vector<openvdb::io::GridDescriptor>& descriptors, const std::string& name) {
        const openvdb::Name unique = openvdb::io::GridDescriptor::stringAsUniqueName(name);
        for (const openvdb::io::GridDescriptor& descriptor : descriptors)
            if (name == unique ? descriptor.gridName() == name
                               : descriptor.uniqueName() == unique)
                return descriptor;
        return findUnique(descriptors, unique);
    }

    static const openvdb::io::GridDescriptor&
    findUnique(const std::vector<openvdb::io::GridDescriptor>& descriptors,
               const openvdb::Name& unique) {
        for (const openvdb::io::GridDescriptor& descriptor : descriptors)
            if (descriptor.uniqueName() == unique)
                return descriptor;
        throw openvdb::KeyError("no grid named \"" +
                                openvdb::io::GridDescriptor::nameAsString(unique) + "\"");
    }
};

// Index (0,0,0) of our grid is the low corner of the active bounding box; its world position and
// the voxel size come from the OpenVDB transform, which must be diagonal.
GridGeometry geometryOf(const openvdb::GridBase& grid, const openvdb::CoordBBox& box,
                        const std::string& where) {
    const openvdb::math::Transform& transform = grid.transform();
    // A damaged scale (0, NaN) makes OpenVDB throw while it makes the affine map.
    const openvdb::Mat4d matrix = callOpenVdb(
        [&] { return transform.baseMap()->getAffineMap()->getMat4(); },
        [&](const std::string& reason) {
            return where + " has a transform OpenVDB cannot use (" + reason + ")";
        });
    bool axisAligned = transform.isLinear();
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            axisAligned = axisAligned && (row == column ? matrix(row, column) > 0.0
                                                        : matrix(row, column) == 0.0);
    if (!axisAligned)
        throw DataError(where + " has a rotated, sheared, mirrored or non-linear transform; "
                                "only axis-aligned scale and translation are supported");
    const openvdb::Vec3d origin = transform.indexToWorld(box.min());
    // In 64 bits: a box from -2^31 to 2^31 - 1 has more voxels a side than an int holds.
    const glm::i64vec3 dims = glm::i64vec3(box.max().x(), box.max().y(), box.max().z()) -
                              glm::i64vec3(box.min().x(), box.min().y(), box.min().z()) +
                              std::int64_t{1};
    try {
        return GridGeometry(dims,
                            glm::dvec3(origin.x(), origin.y(), origin.z()),
                            glm::dvec3(matrix(0, 0), matrix(1, 1), matrix(2, 2)));
    } catch (const DataError& error) {
        throw DataError(where + ": " + error.what());
    }
}

// `treeBytes`: what OpenVDB's tree holds while it is copied, where this read made it. With
// `clip` (a brick's box of OpenVDB's voxels), the grid is that box's voxels (whose active voxels
// may be none), unchecked for finite values (the whole grid's are checked by the render that
// split it).
template <typename VdbGrid>
auto convert(const VdbGrid& source, const std::string& path, const std::string& gridName,
             const ProgressCallback& progress, std::uint64_t treeBytes,
             const std::optional<openvdb::CoordBBox>& clip = std::nullopt) {
    using Value = decltype(toGlm(source.background()));
    const std::string where = path + ": grid '" + gridName + "'";
    const openvdb::CoordBBox box = clip ? *clip : source.evalActiveVoxelBoundingBox();
    if (box.empty())
        throw DataError(where + " has no active voxels");
    const GridGeometry geometry = geometryOf(source, box, where);
    // Align our 8^3 blocks with OpenVDB's leaf nodes, whose origins are multiples of 8: our
    // index is OpenVDB's minus `low`, so an offset of (low mod 8) puts block boundaries on
    // leaf boundaries and each leaf becomes exactly one block.
    constexpr std::int64_t kBlock = SparseGrid<Value>::kBlockSize;
    const glm::i64vec3 low(box.min().x(), box.min().y(), box.min().z());
    const glm::i64vec3 blockOffset = ((low % kBlock) + kBlock) % kBlock;
    auto grid = std::make_shared<SparseGrid<Value>>(geometry, toGlm(source.background()),
                                                    blockOffset);
    // Active tiles become voxels: a 594-byte file may hold one tile of 4096^3. Each OpenVDB leaf
    // becomes one block, and tiles (multiples of 8^3, on leaf boundaries) whole blocks.
    const std::uint64_t active = source.activeVoxelCount();
    const std::uint64_t blocks =
        source.tree().leafCount() +
        (active - source.tree().activeLeafVoxelCount()) / std::uint64_t(kBlock * kBlock * kBlock);
    detail::checkFitsInMemory(where + ": copying its " + std::to_string(active) +
                                  " active voxels (tiles included)",
                              byteSum(treeBytes, SparseGrid<Value>::memoryBytesForBlocks(blocks)));
    const auto total = static_cast<double>(active);
    const std::string message = "copying grid '" + gridName + "'";
    std::int64_t copied = 0;
    std::int64_t reported = 0;
    const auto count = [&](std::int64_t voxels) {
        copied += voxels;
        if (copied - reported >= kProgressInterval) {
            reported = copied;
            reportProgress(progress, path, double(copied) / total, message);
        }
    };
    reportProgress(progress, path, 0.0, message);
    // Leaves a block at a time. OpenVDB orders a leaf's voxels z fastest, a block x fastest.
    typename SparseGrid<Value>::BlockVoxels block;
    for (auto leaf = source.tree().cbeginLeaf(); leaf; ++leaf) {
        if (clip && !clip->hasOverlap(leaf->getNodeBoundingBox()))
            continue;
        block.active.reset();
        for (auto on = leaf->cbeginValueOn(); on; ++on) {
            if (clip && !clip->isInside(on.getCoord()))
                continue;
            const openvdb::Index n = on.pos();
            const std::size_t slot = ((n >> 6U) & 7U) + 8 * (((n >> 3U) & 7U) + 8 * (n & 7U));
            block.values[slot] = toGlm(*on);
            block.active.set(slot);
        }
        const openvdb::Coord origin = leaf->origin();
        grid->setBlock(glm::i64vec3(origin.x(), origin.y(), origin.z()) - low, block);
        count(static_cast<std::int64_t>(leaf->onVoxelCount()));
    }
    // Then active tiles (the iterator stops above the leaves), each the size of whole leaves
    // and on their boundaries: a block of its value at a time. A file of 16 KB may hold 50 M
    // voxels of tiles (fuzz_vdb_reader); voxel by voxel that took 22 s under ASan.
    block.active.set();
    auto tile = source.tree().cbeginValueOn();
    tile.setMaxDepth(tile.getLeafDepth() - 1);
    for (; tile; ++tile) {
        openvdb::CoordBBox voxels;
        tile.getBoundingBox(voxels);
        block.values.fill(toGlm(*tile));
        // In 64 bits: OpenVDB's box iterator steps past the largest int to the smallest, and
        // goes on, for a voxel at index 2^31 - 1.
        if (clip) {
            // A brick takes the tile's blocks that lie in its box, each cut to it.
            voxels.intersect(*clip);
            if (voxels.empty())
                continue;
            voxels = openvdb::CoordBBox(voxels.min() & ~(kBlock - 1), voxels.max() | (kBlock - 1));
        }
        const glm::i64vec3 first(voxels.min().x(), voxels.min().y(), voxels.min().z());
        const glm::i64vec3 last(voxels.max().x(), voxels.max().y(), voxels.max().z());
        for (std::int64_t z = first.z; z <= last.z; z += kBlock)
            for (std::int64_t y = first.y; y <= last.y; y += kBlock)
                for (std::int64_t x = first.x; x <= last.x; x += kBlock) {
                    if (clip) {
                        block.active.reset();
                        for (std::size_t slot = 0; slot < block.active.size(); ++slot) {
                            const openvdb::Coord voxel(
                                static_cast<openvdb::Int32>(x + std::int64_t(slot % 8)),
                                static_cast<openvdb::Int32>(y + std::int64_t(slot / 8 % 8)),
                                static_cast<openvdb::Int32>(z + std::int64_t(slot / 64)));
                            block.active.set(slot, clip->isInside(voxel));
                        }
                    }
                    grid->setBlock(glm::i64vec3(x, y, z) - low, block);
                    count(kBlock * kBlock * kBlock);
                }
    }
    reportProgress(progress, path, 1.0, message);
    if (!clip)
        detail::checkFiniteVoxels(where, grid->statistics());
    return grid;
}

// OpenVDB's box of the voxels of `region` of the grid readVdbGrid() makes of `grid`, whose
// active voxels' box is `whole`.
openvdb::CoordBBox regionBox(const openvdb::CoordBBox& whole, const IndexBox& region) {
    const auto coord = [](const glm::i64vec3& index) {
        return openvdb::Coord(static_cast<openvdb::Int32>(index.x),
                              static_cast<openvdb::Int32>(index.y),
                              static_cast<openvdb::Int32>(index.z));
    };
    return {whole.min() + coord(region.lo), whole.min() + coord(region.hi - std::int64_t{1})};
}

} // namespace

bool isOpenVdbAvailable() { return true; }

std::vector<VdbGridInfo> listVdbGrids(const std::string& path) {
    detail::VdbFileTrees trees;
    auto file = openVdb(path, trees);
    return gridInfos(*file, path);
}

// An application's grid has no file: messages name it so.
constexpr const char* kInMemory = "in-memory OpenVDB grid";

ScalarGridPtr gridFromVdb(const openvdb::FloatGrid& grid) {
    return convert(grid, kInMemory, grid.getName(), {}, 0);
}

VectorGridPtr gridFromVdb(const openvdb::Vec3SGrid& grid) {
    return convert(grid, kInMemory, grid.getName(), {}, 0);
}

namespace {

// Throws unless the file has a float or vec3s grid named `gridName`, naming the grids it has.
void requireGrid(openvdb::io::File& file, const std::string& path, const std::string& gridName) {
    const bool hasGrid =
        callOpenVdb([&] { return file.hasGrid(gridName); },
                    [&](const std::string& reason) { return corrupt(path, reason); });
    if (!hasGrid) {
        const std::vector<VdbGridInfo> infos = gridInfos(file, path);
        std::string available;
        for (const VdbGridInfo& info : infos)
            available += (available.empty() ? "" : ", ") + info.name + " (" + info.valueType + ")";
        throw DataError(path + ": no grid named '" + gridName + "'; " +
                        (infos.empty() ? "the file has no grids" : "the file has: " + available));
    }
    const std::string where = path + ": grid '" + gridName + "'";
    const auto cannotRead = [&](const std::string& reason) {
        return where + " cannot be read (" + reason + ")";
    };
    // The type first, from the grid's metadata: the tree of a grid of another type (bool, mask,
    // points) is not one that the header walk checked, and is not read.
    const std::string valueType =
        callOpenVdb([&] { return file.readGridMetadata(gridName)->valueType(); }, cannotRead);
    if (valueType != "float" && valueType != "vec3s")
        throw DataError(where + " holds " + valueType + " values; expected float or vec3s");
}

// The grid's metadata and transform, and its active voxels' box as OpenVDB writes it with every
// grid (file_bbox_min, file_bbox_max), without reading the tree.
std::pair<openvdb::GridBase::Ptr, openvdb::CoordBBox>
gridBox(openvdb::io::File& file, const std::string& path, const std::string& gridName) {
    requireGrid(file, path, gridName);
    const std::string where = path + ": grid '" + gridName + "'";
    const openvdb::GridBase::Ptr metadata = callOpenVdb(
        [&] { return file.readGridMetadata(gridName); },
        [&](const std::string& reason) { return where + " cannot be read (" + reason + ")"; });
    const auto low = (*metadata)[openvdb::GridBase::META_FILE_BBOX_MIN];
    const auto high = (*metadata)[openvdb::GridBase::META_FILE_BBOX_MAX];
    const auto* min = dynamic_cast<const openvdb::Vec3IMetadata*>(low.get());
    const auto* max = dynamic_cast<const openvdb::Vec3IMetadata*>(high.get());
    if (!min || !max)
        throw DataError(where + " has no bounding box in its metadata (file_bbox_min, "
                                "file_bbox_max, which OpenVDB writes with each grid): a render "
                                "split over processes cannot read it by bricks; render it in one "
                                "process");
    const openvdb::CoordBBox box(openvdb::Coord(min->value()), openvdb::Coord(max->value()));
    if (box.empty())
        throw DataError(where + " has no active voxels");
    return {metadata, box};
}

} // namespace

GridGeometry vdbGridGeometry(const std::string& path, const std::string& gridName) {
    detail::VdbFileTrees trees;
    auto file = openVdb(path, trees);
    const auto [metadata, box] = gridBox(*file, path, gridName);
    return geometryOf(*metadata, box, path + ": grid '" + gridName + "'");
}

AnyGrid readVdbRegion(const std::string& path, const std::string& gridName, const IndexBox& region,
                      const ProgressCallback& progress) {
    detail::VdbFileTrees trees;
    auto file = openVdb(path, trees);
    const auto [metadata, whole] = gridBox(*file, path, gridName);
    const std::string where = path + ": grid '" + gridName + "'";
    const GridGeometry wholeGeometry = geometryOf(*metadata, whole, where);
    if (region.isEmpty() || region.intersection(IndexBox::of(wholeGeometry)) != region)
        throw DataError(where + ": brick " + region.text() +
                        " is not a box of voxels of the "
                        "grid's " +
                        IndexBox::of(wholeGeometry).text());
    const openvdb::CoordBBox box = regionBox(whole, region);
    // OpenVDB reads the tree's topology and only the leaves that meet the brick's world box.
    const openvdb::BBoxd world = metadata->transform().indexToWorld(box);
    const std::string reading = "reading grid '" + gridName + "'";
    reportProgress(progress, path, 0.0, reading);
    const openvdb::GridBase::Ptr base = callOpenVdb(
        [&] { return file->readGrid(gridName, world); },
        [&](const std::string& reason) { return where + " cannot be read (" + reason + ")"; });
    reportProgress(progress, path, 1.0, reading);
    if (auto scalar = openvdb::gridPtrCast<openvdb::FloatGrid>(base))
        return ScalarGridPtr(convert(*scalar, path, gridName, progress, 0, box));
    if (auto vector = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base))
        return VectorGridPtr(convert(*vector, path, gridName, progress, 0, box));
    throw DataError(where + " holds " + base->valueType() + " values; expected float or vec3s");
}

AnyGrid readVdbGrid(const std::string& path, const std::string& gridName,
                    const ProgressCallback& progress) {
    detail::VdbFileTrees trees;
    auto file = openVdb(path, trees);
    requireGrid(*file, path, gridName);
    const std::string where = path + ": grid '" + gridName + "'";
    const auto cannotRead = [&](const std::string& reason) {
        return where + " cannot be read (" + reason + ")";
    };
    // A float or vec3s grid's tree was walked; a file written as a stream has been read whole.
    const detail::VdbTreeSize* walked = trees.find(gridName);
    const detail::VdbTreeSize tree = walked != nullptr ? *walked : detail::VdbTreeSize{};
    if (!trees.streamed)
        detail::checkFitsInMemory(where + ": reading its tree of " + nodesText(tree.nodes) +
                                      " into OpenVDB",
                                  tree.bytes);
    // OpenVDB reads and decompresses the whole grid in one call, often the longest step: read
    // through a stream that reports the grid's bytes as OpenVDB reads them. A file written as a
    // stream was read when it was opened.
    const std::string reading = "reading grid '" + gridName + "'";
    reportProgress(progress, path, 0.0, reading);
    const openvdb::GridBase::Ptr base = callOpenVdb(
        [&] {
            return trees.streamed ? file->readGrid(gridName)
                                  : ReportingGridReader().read(path, gridName, progress, reading);
        },
        cannotRead);
    reportProgress(progress, path, 1.0, reading);
    if (auto scalar = openvdb::gridPtrCast<openvdb::FloatGrid>(base))
        return ScalarGridPtr(convert(*scalar, path, gridName, progress, tree.bytes));
    if (auto vector = openvdb::gridPtrCast<openvdb::Vec3SGrid>(base))
        return VectorGridPtr(convert(*vector, path, gridName, progress, tree.bytes));
    throw DataError(where + " holds " + base->valueType() + " values; expected float or vec3s");
}

#else

namespace {
[[noreturn]] void notBuiltIn(const std::string& path) {
    throw IoError(path + ": cannot read OpenVDB files: texsplat was built without OpenVDB "
                         "(CMake option TEXSPLAT_WITH_OPENVDB=OFF)");
}
} // namespace

bool isOpenVdbAvailable() { return false; }

std::vector<VdbGridInfo> listVdbGrids(const std::string& path) { notBuiltIn(path); }

AnyGrid readVdbGrid(const std::string& path, const std::string&, const ProgressCallback&) {
    notBuiltIn(path);
}

GridGeometry vdbGridGeometry(const std::string& path, const std::string&) {
    notBuiltIn(path);
}

AnyGrid readVdbRegion(const std::string& path, const std::string&, const IndexBox&,
                      const ProgressCallback&) {
    notBuiltIn(path);
}

#endif

} // namespace texsplat::volume
