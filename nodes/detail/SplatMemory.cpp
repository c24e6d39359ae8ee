#include "nodes/detail/SplatMemory.h"

#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "octree/ClassifiedGrid.h"
#include "octree/OctreeNode.h"
#include "octree/Splat.h"
#include "octree/ValueRanges.h"
#include "scenegraph/MemoryLimit.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <string>

namespace texsplat::nodes::detail {
namespace {

// Per splat: the list, and its depth ordering (two 64-bit keys and the sorted copy of the list,
// octree/DepthSort.cpp), and one camera depth.
constexpr std::uint64_t kBytesPerSplat =
    2 * sizeof(octree::Splat) + 2 * sizeof(std::uint64_t) + sizeof(float);
// Per vector splat, the same twice: its mark offset and, as a bound, one mark (the marks cover the
// image markDensity times over, which takes fewer than one per voxel but for data a few voxels
// deep).
constexpr std::uint64_t kBytesPerVectorSplat =
    2 * (sizeof(std::uint32_t) + sizeof(octree::SplatMark));

std::string dimsText(const glm::i64vec3& dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

std::string sizeText(std::uint64_t bytes) {
    // bytesText() without the exact count: the parts of a sum, read beside it.
    const std::string text = bytesText(bytes);
    return text.substr(text.find('(') + 1, text.size() - text.find('(') - 2);
}

} // namespace

SplatMemory estimateClassification(const VolumeData& volume, bool withVectors) {
    // The vector field when there is one: scalarGrid() of vector data would make a component.
    const volume::VectorGridPtr vectors = volume.vectorGrid();
    SplatMemory memory;
    std::uint64_t stored = 0;
    if (vectors) {
        memory.dims = vectors->geometry().dims();
        stored = vectors->storedVoxelCount();
    } else {
        const volume::ScalarGridPtr scalars = volume.scalarGrid();
        memory.dims = scalars->geometry().dims();
        stored = scalars->storedVoxelCount();
    }
    // Saturating: a sparse grid's box may hold 2^60 voxels, whose bytes would wrap.
    const glm::u64vec3 dims(memory.dims);
    const std::uint64_t boxBlocks = octree::ClassifiedGrid::boxBlockCount(dims);
    // Each stored voxel can make at most one classified block non-empty, and a voxel that is
    // not stored classifies to nothing.
    // Scalars classify into a palette (2 bytes a voxel); vector splats hold their media.
    memory.classified = octree::ClassifiedGrid::memoryBytesFor(
        dims, std::min(boxBlocks, stored), withVectors,
        withVectors ? 0 : static_cast<std::size_t>(TransferFunction::kLevels) + 1);
    if (!withVectors) {
        // Scalar classification also keeps the grid's value ranges (docs/octree.md).
        memory.classified = byteSum(memory.classified, octree::ValueRanges::memoryBytesFor(
                                                           dims, std::min(boxBlocks, stored)));
    }
    return memory;
}

void checkClassificationMemory(const SplatMemory& memory, const std::string& purpose) {
    checkMemory("classifying " + dimsText(memory.dims) + " voxels" + purpose, memory.classified,
                "use a volume of lower resolution or a larger --memory-limit");
}

SplatMemory estimateSplats(SplatMemory memory, std::uint64_t classifiedBytes,
                           std::uint64_t nonEmptyVoxels, bool withVectors, bool withOctree,
                           std::uint64_t maxSplats, bool listed, std::uint64_t shadingBytes) {
    memory.classified = classifiedBytes;
    memory.shading = shadingBytes;
    // Records exist for non-empty nodes of level >= 1: at most one per 7 non-empty voxels
    // (1/8 + 1/64 + ...).
    memory.octree =
        withOctree ? byteProduct(nonEmptyVoxels / 7 + 1, sizeof(octree::OctreeNode)) : 0;
    const std::uint64_t splats =
        !listed ? 0 : maxSplats > 0 ? std::min(nonEmptyVoxels, maxSplats) : nonEmptyVoxels;
    memory.splats =
        byteProduct(splats, kBytesPerSplat + (withVectors ? kBytesPerVectorSplat : 0));
    return memory;
}

std::uint64_t shadingBytesFor(const octree::ClassifiedGrid& classified) {
    return byteSum(byteProduct(byteProduct(classified.blockCount(),
                                           octree::ClassifiedGrid::kBlockVoxels),
                               sizeof(glm::vec3)),
                   classified.memoryBytes());
}

void checkSplatMemory(const SplatMemory& memory) {
    checkMemory("classifying and splatting " + dimsText(memory.dims) + " voxels", memory.total(),
                "the classified grid takes " + sizeText(memory.classified) + ", the octree " +
                    sizeText(memory.octree) + ", the splats " + sizeText(memory.splats) +
                    (memory.shading > 0 ? ", the shading " + sizeText(memory.shading) : "") +
                    "; " + kSplatMemoryAdvice);
}

} // namespace texsplat::nodes::detail
