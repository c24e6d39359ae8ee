#pragma once

#include "scenegraph/Assert.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::octree {

/// @brief A voxel grid after classification by a transfer function: per voxel a colour (RGB,
/// per unit length, ready to be premultiplied) and an extinction coefficient tau (opacity per
/// unit length). This is the input of the octree and of full-resolution splatting.
///
/// Voxel (i, j, k) is a sample at `origin + spacing * (i, j, k)`; its cell, the box a splat of
/// it stands for, is that point +- spacing / 2. Dimensions and indices are 64-bit; the linear
/// index `i + nx * (j + ny * k)` names a voxel (octree keys), but voxels are read by their
/// coordinates, or by storage index while walking blocks. A voxel whose colour and extinction
/// are all zero is empty and produces no splat (docs/design.md: "no splats for transparent
/// voxels").
///
/// Storage is block-sparse, so that memory follows what the transfer function leaves visible,
/// not the grid's box: voxels live in 8³ blocks aligned to voxel (0, 0, 0) (the octree's nodes
/// of level 3), and a block is allocated only when a non-empty value is set in it. A block
/// table of 4 bytes per block of the box says where each block is. A dense grid pays the table
/// and nothing else; an all-transparent one allocates no block.
///
/// A voxel is held in one of two forms, the same for the whole grid (storage()):
/// - Storage::Direct: its four floats (16 bytes), any values: what vector splats, previews and
///   the block means of an edit hold;
/// - Storage::Palette: a 16-bit index into the grid's palette of at most kPaletteSize media
///   (2 bytes a voxel, and one table), which a transfer function fills for each of 65 535
///   levels of its normalized value (TransferFunction::classify()): index 0 is the empty voxel.
class ClassifiedGrid {
public:
    /// @brief Edge length of a block in voxels (2^kBlockLevel).
    static constexpr std::uint64_t kBlockSize = 8;
    /// @brief The octree level whose nodes are the blocks.
    static constexpr int kBlockLevel = 3;
    /// @brief Voxels per block.
    static constexpr std::size_t kBlockVoxels = 512;

    /// @brief Where a voxel lies in the block storage (its block's slot, times kBlockVoxels,
    /// plus its place in the block, x fastest): a cheap handle for voxel() and vector() while
    /// walking blocks.
    using StorageIndex = std::uint64_t;

    /// @brief How voxels are held (see the class).
    enum class Storage { Direct, Palette };

    /// @brief The most media a palette holds (16-bit indices).
    static constexpr std::size_t kPaletteSize = 65536;

    /// @brief The palette indices of one block, x fastest.
    using PaletteBlock = std::array<std::uint16_t, kBlockVoxels>;

    /// @brief A grid of @p dims voxels, all empty (no block allocated), held directly.
    /// @throws DataError when a dimension is zero, the block table does not fit in memory
    /// addressing, a spacing is not finite and positive, or the origin is not finite.
    ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin);

    /// @brief A grid of @p dims voxels, all empty, held as indices into @p palette (at most
    /// kPaletteSize media, the first one empty: the index of an empty voxel).
    /// @throws DataError as the other constructor, and when the palette is empty, larger than
    /// kPaletteSize, its first medium is not empty or a medium is negative or not finite.
    ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin,
                   std::vector<glm::vec4> palette);

    /// @brief How the voxels are held.
    [[nodiscard]] Storage storage() const {
        return mPalette.empty() ? Storage::Direct : Storage::Palette;
    }

    /// @brief The palette (Storage::Palette; empty otherwise): colour (xyz) and extinction (w)
    /// per index.
    [[nodiscard]] const std::vector<glm::vec4>& palette() const { return mPalette; }

    /// @brief Sets voxel @p ijk (which must lie inside the grid). An empty value in a block
    /// that holds nothing yet allocates nothing.
    /// @throws DataError when a colour channel or the extinction is negative or not finite.
    void setVoxel(glm::u64vec3 ijk, glm::vec3 color, float extinction);

    /// @brief Sets every voxel of block @p block (block coordinates) at once, x fastest, as
    /// setVoxel() would one by one: the way to fill a grid from blocks made in parallel. Voxels
    /// of a block clipped by the grid's upper faces must be zero there. Storage::Direct only.
    /// @throws DataError as setVoxel().
    void setBlock(glm::u64vec3 block, const std::array<glm::vec4, kBlockVoxels>& voxels);

    /// @brief Sets every voxel of block @p block of a Storage::Palette grid to the medium of
    /// its palette index, x fastest (0: empty). Voxels of a block clipped by the grid's upper
    /// faces must be 0 there, and every index must lie inside the palette.
    void setBlock(glm::u64vec3 block, const PaletteBlock& indices);

    /// @brief Gives every voxel a vector, all zero until setVector(): the flow that vector splats
    /// draw as marks (Crawfis & Max 1993, "Combined Vector and Scalar Textures"). Scalar grids have
    /// none and pay nothing for it (12 more bytes per voxel of the allocated blocks when enabled).
    void enableVectors();

    /// @brief Whether enableVectors() was called.
    [[nodiscard]] bool hasVectors() const { return mHasVectors; }

    /// @brief Sets the vector of voxel @p ijk, in the grid's (local) space; needs hasVectors().
    /// An empty voxel draws no splat, so in a block that holds nothing the vector is not kept.
    /// @throws DataError when a component is not finite.
    void setVector(glm::u64vec3 ijk, glm::vec3 vector);

    /// @brief Colour (xyz) and extinction (w) of voxel @p ijk (zero outside allocated blocks).
    [[nodiscard]] glm::vec4 voxel(glm::u64vec3 ijk) const {
        const std::uint32_t slot = blockSlot(ijk);
        return slot == kNoBlock ? glm::vec4(0.0f) : storedVoxel(storageIndex(slot, ijk));
    }

    /// @brief Colour and extinction of the voxel stored at @p storage (from forEachBlock()).
    [[nodiscard]] glm::vec4 storedVoxel(StorageIndex storage) const {
        const Block& block = *mBlocks[static_cast<std::size_t>(storage / kBlockVoxels)];
        const auto voxel = static_cast<std::size_t>(storage % kBlockVoxels);
        return block.voxels ? (*block.voxels)[voxel] : mPalette[(*block.indices)[voxel]];
    }

    /// @brief The 512 colours and extinctions of the allocated block whose voxel (0, 0, 0) is
    /// stored at @p first (from blockStorage() or forEachBlock()), x fastest, into @p voxels:
    /// for a pass over whole blocks.
    void readBlock(StorageIndex first, std::array<glm::vec4, kBlockVoxels>& voxels) const;

    /// @brief The media of the allocated block whose voxel (0, 0, 0) is stored at @p first, x
    /// fastest (Storage::Direct only): for a loop that reads a block's voxels itself.
    [[nodiscard]] const glm::vec4* directBlock(StorageIndex first) const {
        return mBlocks[static_cast<std::size_t>(first / kBlockVoxels)]->voxels->data();
    }

    /// @brief The palette indices of the allocated block whose voxel (0, 0, 0) is stored at
    /// @p first, x fastest (Storage::Palette only).
    [[nodiscard]] const std::uint16_t* paletteBlock(StorageIndex first) const {
        return mBlocks[static_cast<std::size_t>(first / kBlockVoxels)]->indices->data();
    }

    /// @brief The vector of voxel @p ijk (hasVectors() must hold; zero outside allocated blocks).
    [[nodiscard]] glm::vec3 vector(glm::u64vec3 ijk) const {
        TEXSPLAT_ASSERT(mHasVectors, "ClassifiedGrid::vector(): no vectors");
        const std::uint32_t slot = blockSlot(ijk);
        return slot == kNoBlock ? glm::vec3(0.0f) : storedVector(storageIndex(slot, ijk));
    }

    /// @brief The vector of the voxel stored at @p storage (hasVectors() must hold).
    [[nodiscard]] glm::vec3 storedVector(StorageIndex storage) const {
        TEXSPLAT_ASSERT(mHasVectors, "ClassifiedGrid::storedVector(): no vectors");
        const Block& block = *mBlocks[static_cast<std::size_t>(storage / kBlockVoxels)];
        return (*block.vectors)[static_cast<std::size_t>(storage % kBlockVoxels)];
    }

    /// @brief Whether voxel @p ijk is empty (all four values zero).
    [[nodiscard]] bool isEmptyVoxel(glm::u64vec3 ijk) const {
        return voxel(ijk) == glm::vec4(0.0f);
    }

    /// @brief Linear index of voxel @p ijk.
    [[nodiscard]] std::uint64_t index(glm::u64vec3 ijk) const {
        return ijk.x + mDims.x * (ijk.y + mDims.y * ijk.z);
    }

    /// @brief Voxel coordinates of linear index @p index.
    [[nodiscard]] glm::u64vec3 coordinates(std::uint64_t index) const {
        TEXSPLAT_ASSERT(index < voxelCount(), "ClassifiedGrid: index outside the grid");
        return {index % mDims.x, (index / mDims.x) % mDims.y, index / (mDims.x * mDims.y)};
    }

    /// @brief World position of a point given in voxel index coordinates (voxel centres are
    /// at integer coordinates).
    [[nodiscard]] glm::dvec3 toWorld(glm::dvec3 indexPosition) const {
        return mOrigin + mSpacing * indexPosition;
    }

    /// @brief Number of voxels along x, y, z.
    [[nodiscard]] glm::u64vec3 dims() const { return mDims; }

    /// @brief Distance between neighbouring voxel centres along x, y, z.
    [[nodiscard]] glm::dvec3 spacing() const { return mSpacing; }

    /// @brief World position of voxel (0, 0, 0).
    [[nodiscard]] glm::dvec3 origin() const { return mOrigin; }

    /// @brief Total number of voxels of the box, empty or not.
    [[nodiscard]] std::uint64_t voxelCount() const { return mDims.x * mDims.y * mDims.z; }

    /// @brief Number of blocks along x, y, z (the box rounded up to whole blocks).
    [[nodiscard]] glm::u64vec3 blockDims() const { return mBlockDims; }

    /// @brief Whether block @p block (block coordinates) is allocated; voxels outside allocated
    /// blocks are empty.
    [[nodiscard]] bool hasBlock(glm::u64vec3 block) const {
        return mSlots[static_cast<std::size_t>(blockIndex(block))] != kNoBlock;
    }

    /// @brief What blockStorage() answers for an unallocated block.
    static constexpr StorageIndex kNoStorage = ~StorageIndex{0};

    /// @brief The storage index of the voxel (0, 0, 0) of block @p block (block coordinates), or
    /// kNoStorage when the block is not allocated; voxel ijk of the block is at that plus
    /// offsetInBlock(ijk).
    [[nodiscard]] StorageIndex blockStorage(glm::u64vec3 block) const {
        const std::uint32_t slot = mSlots[static_cast<std::size_t>(blockIndex(block))];
        return slot == kNoBlock ? kNoStorage : StorageIndex{slot} * kBlockVoxels;
    }

    /// @brief Where voxel @p ijk lies in its block's storage.
    [[nodiscard]] static std::uint64_t offsetInBlock(glm::u64vec3 ijk) {
        const glm::u64vec3 inBlock = ijk % kBlockSize;
        return inBlock.x + kBlockSize * (inBlock.y + kBlockSize * inBlock.z);
    }

    /// @brief Number of non-empty voxels: what a full-resolution splat list holds at most.
    [[nodiscard]] std::uint64_t nonEmptyVoxelCount() const { return mNonEmptyCount; }

    /// @brief Number of non-empty voxels of the allocated block whose voxel (0, 0, 0) is stored
    /// at @p first.
    [[nodiscard]] std::uint32_t storedBlockCount(StorageIndex first) const {
        return mBlocks[static_cast<std::size_t>(first / kBlockVoxels)]->nonEmpty;
    }

    /// @brief Number of allocated blocks.
    [[nodiscard]] std::size_t blockCount() const { return mBlocks.size(); }

    /// @brief Calls `visit(glm::u64vec3 block, StorageIndex first)` for every allocated block,
    /// in allocation order: the block's coordinates and the storage index of its voxel (0, 0, 0)
    /// (voxel (x, y, z) of the block is at `first + x + 8 * (y + 8 * z)`; voxels of a block
    /// clipped by the grid's upper faces read as empty there).
    template <typename Visit> void forEachBlock(Visit&& visit) const {
        for (std::size_t slot = 0; slot < mBlocks.size(); ++slot) {
            visit(mBlocks[slot]->coordinates, StorageIndex{slot} * kBlockVoxels);
        }
    }

    /// @brief Bytes held: the block table, the palette and the allocated blocks (with their
    /// vectors).
    [[nodiscard]] std::uint64_t memoryBytes() const;

    /// @brief Blocks along x, y, z of a box of @p dims voxels (rounded up, without overflow).
    [[nodiscard]] static glm::u64vec3 boxBlockDims(glm::u64vec3 dims);

    /// @brief Number of blocks of a box of @p dims voxels, saturating at the largest uint64.
    [[nodiscard]] static std::uint64_t boxBlockCount(glm::u64vec3 dims);

    /// @brief What a grid of @p dims with @p blocks allocated blocks costs (memoryBytes()),
    /// held directly or, with @p paletteSize media (> 0), as palette indices; saturating at the
    /// largest uint64: for an estimate before classifying.
    [[nodiscard]] static std::uint64_t memoryBytesFor(glm::u64vec3 dims, std::uint64_t blocks,
                                                      bool withVectors,
                                                      std::size_t paletteSize = 0);

private:
    static constexpr std::uint32_t kNoBlock = 0xffffffffu;

    struct Block {
        glm::u64vec3 coordinates{0};
        std::uint32_t nonEmpty = 0;                                   // voxels not empty
        std::unique_ptr<std::array<glm::vec4, kBlockVoxels>> voxels;  // Storage::Direct
        std::unique_ptr<PaletteBlock> indices;                        // Storage::Palette
        std::unique_ptr<std::array<glm::vec3, kBlockVoxels>> vectors; // with hasVectors() only
    };

    [[nodiscard]] std::uint64_t blockIndex(glm::u64vec3 block) const {
        return block.x + mBlockDims.x * (block.y + mBlockDims.y * block.z);
    }

    [[nodiscard]] std::uint32_t blockSlot(glm::u64vec3 ijk) const {
        TEXSPLAT_ASSERT(ijk.x < mDims.x && ijk.y < mDims.y && ijk.z < mDims.z,
                        "ClassifiedGrid: voxel outside the grid");
        return mSlots[static_cast<std::size_t>(blockIndex(ijk / kBlockSize))];
    }

    [[nodiscard]] static StorageIndex storageIndex(std::uint32_t slot, glm::u64vec3 ijk) {
        return StorageIndex{slot} * kBlockVoxels + offsetInBlock(ijk);
    }

    // The block of `ijk`, allocated (empty) on first use.
    Block& block(glm::u64vec3 ijk);
    // A new block (not allocated yet) holding `voxels` (Direct) or `indices` (Palette).
    Block& allocateBlock(glm::u64vec3 coordinates,
                         const std::array<glm::vec4, kBlockVoxels>* voxels,
                         const PaletteBlock* indices);
    // Bytes of one allocated block.
    static std::uint64_t blockBytes(bool withVectors, Storage storage);
    // Asserts that the voxels of `block` outside the grid (a block clipped by its upper faces)
    // are empty by `isEmpty(i)`, i the voxel's place in the block.
    template <typename IsEmpty> void checkClipped(glm::u64vec3 block, IsEmpty&& isEmpty) const;

    // Throws DataError unless every channel of voxel `ijk`'s `value` is finite and >= 0.
    static void checkVoxel(glm::u64vec3 ijk, glm::vec4 value);

    glm::u64vec3 mDims;
    glm::u64vec3 mBlockDims;
    glm::dvec3 mSpacing;
    glm::dvec3 mOrigin;
    bool mHasVectors = false;
    std::uint64_t mNonEmptyCount = 0;
    std::vector<std::uint32_t> mSlots; // per block of the box: its slot in mBlocks, or kNoBlock
    std::vector<std::unique_ptr<Block>> mBlocks;
    std::vector<glm::vec4> mPalette; // Storage::Palette: the media; empty for Storage::Direct
};

} // namespace texsplat::octree
