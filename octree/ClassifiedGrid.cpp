#include "octree/ClassifiedGrid.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#include <glm/vector_relational.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace texsplat::octree {

namespace {

std::string dimsText(glm::u64vec3 dims) {
    std::ostringstream text;
    text << dims.x << "x" << dims.y << "x" << dims.z;
    return text.str();
}

std::string vectorText(glm::dvec3 v) {
    std::ostringstream text;
    text << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return text.str();
}

bool isFinite(glm::dvec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

ClassifiedGrid::ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin)
    : mDims(dims), mBlockDims(boxBlockDims(dims)), mSpacing(spacing),
      mOrigin(origin) {
    if (dims.x == 0 || dims.y == 0 || dims.z == 0) {
        throw DataError("ClassifiedGrid: dimensions must be positive, got " + dimsText(dims));
    }
    // Linear voxel indices are 64-bit, and the block table lives in one std::vector.
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    constexpr std::uint64_t kMaxBlocks =
        std::numeric_limits<std::size_t>::max() / sizeof(std::uint32_t);
    if (dims.y > kMax / dims.x || dims.z > kMax / (dims.x * dims.y) ||
        boxBlockCount(dims) > kMaxBlocks) {
        throw DataError("ClassifiedGrid: " + dimsText(dims) +
                        " voxels exceed the addressable memory");
    }
    if (!isFinite(spacing) || spacing.x <= 0.0 || spacing.y <= 0.0 || spacing.z <= 0.0) {
        throw DataError("ClassifiedGrid: spacing must be finite and positive, got " +
                        vectorText(spacing));
    }
    if (!isFinite(origin)) {
        throw DataError("ClassifiedGrid: origin must be finite, got " + vectorText(origin));
    }
    mSlots.assign(static_cast<std::size_t>(boxBlockCount(dims)), kNoBlock);
}

void ClassifiedGrid::checkVoxel(glm::u64vec3 ijk, glm::vec4 value) {
    for (int channel = 0; channel < 4; ++channel) {
        if (!std::isfinite(value[channel]) || value[channel] < 0.0f) {
            std::ostringstream text;
            text << "ClassifiedGrid: voxel (" << ijk.x << ", " << ijk.y << ", " << ijk.z
                 << "): " << (channel < 3 ? "color" : "extinction")
                 << " must be finite and >= 0, got " << value[channel];
            throw DataError(text.str());
        }
    }
}

ClassifiedGrid::Block& ClassifiedGrid::block(glm::u64vec3 ijk) {
    const std::uint32_t slot = mSlots[static_cast<std::size_t>(blockIndex(ijk / kBlockSize))];
    return slot != kNoBlock ? *mBlocks[slot] : allocateBlock(ijk / kBlockSize, {});
}

ClassifiedGrid::Block& ClassifiedGrid::allocateBlock(glm::u64vec3 coordinates,
                                                     const std::array<glm::vec4, kBlockVoxels>& voxels) {
    if (mBlocks.size() >= kNoBlock) {
        throw DataError("ClassifiedGrid: more than 2^32 - 1 blocks of 8^3 voxels");
    }
    // The voxels copied in as the block is made: zeroing it first cost as much as the copy.
    auto allocated = std::unique_ptr<Block>(new Block{coordinates, voxels, nullptr});
    if (mHasVectors) {
        allocated->vectors = std::make_unique<std::array<glm::vec3, kBlockVoxels>>();
    }
    const auto slot = static_cast<std::uint32_t>(mBlocks.size());
    mSlots[static_cast<std::size_t>(blockIndex(coordinates))] = slot;
    mBlocks.push_back(std::move(allocated));
    return *mBlocks.back();
}

void ClassifiedGrid::setVoxel(glm::u64vec3 ijk, glm::vec3 color, float extinction) {
    TEXSPLAT_ASSERT(ijk.x < mDims.x && ijk.y < mDims.y && ijk.z < mDims.z,
                    "ClassifiedGrid::setVoxel(): voxel outside the grid");
    const glm::vec4 value(color, extinction);
    checkVoxel(ijk, value);
    if (value == glm::vec4(0.0f) && blockSlot(ijk) == kNoBlock) {
        return;
    }
    glm::vec4& stored = block(ijk).voxels[static_cast<std::size_t>(offsetInBlock(ijk))];
    mNonEmptyCount += (value != glm::vec4(0.0f) ? 1 : 0) - (stored != glm::vec4(0.0f) ? 1 : 0);
    stored = value;
}

void ClassifiedGrid::setBlock(glm::u64vec3 block,
                              const std::array<glm::vec4, kBlockVoxels>& voxels) {
    // Branch-free passes (this runs on one thread while the blocks were made on all): every
    // channel in [0, FLT_MAX] (NaN fails), and the non-empty voxels counted. Over the channels
    // as one float array (glm::value_ptr's layout), with | rather than ||: loops the compiler
    // vectorizes at -O2. With every channel >= 0, a voxel is non-empty exactly when the sum of
    // its channels is not 0.
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "a vec4 is four packed floats");
    const float* channels = &voxels[0].x;
    unsigned invalid = 0;
    for (std::size_t i = 0; i < 4 * kBlockVoxels; ++i) {
        invalid |= unsigned{!(channels[i] >= 0.0f)} |
                   unsigned{channels[i] > std::numeric_limits<float>::max()};
    }
    const bool valid = invalid == 0;
    std::uint64_t nonEmpty = 0;
    for (std::size_t i = 0; i < kBlockVoxels; ++i) {
        const float* value = channels + 4 * i;
        nonEmpty += unsigned{value[0] + value[1] + value[2] + value[3] != 0.0f};
    }
    const auto voxelOf = [&](std::size_t i) {
        return block * kBlockSize + glm::u64vec3(i % kBlockSize, (i / kBlockSize) % kBlockSize,
                                                 i / (kBlockSize * kBlockSize));
    };
    for (std::size_t i = 0; i < kBlockVoxels && !valid; ++i) {
        checkVoxel(voxelOf(i), voxels[i]);
    }
    if (nonEmpty == 0 && !hasBlock(block)) {
        return;
    }
    if (glm::any(glm::greaterThan((block + std::uint64_t{1}) * kBlockSize, mDims))) {
        for (std::size_t i = 0; i < kBlockVoxels; ++i) {
            TEXSPLAT_ASSERT(glm::all(glm::lessThan(voxelOf(i), mDims)) ||
                                voxels[i] == glm::vec4(0.0f),
                            "ClassifiedGrid::setBlock(): a voxel outside the grid is not empty");
        }
    }
    mNonEmptyCount += nonEmpty;
    if (!hasBlock(block)) {
        allocateBlock(block, voxels);
        return;
    }
    std::array<glm::vec4, kBlockVoxels>& stored = this->block(block * kBlockSize).voxels;
    for (const glm::vec4& value : stored) {
        mNonEmptyCount -= value != glm::vec4(0.0f) ? 1 : 0;
    }
    stored = voxels;
}

void ClassifiedGrid::enableVectors() {
    if (mHasVectors) {
        return;
    }
    mHasVectors = true;
    for (const std::unique_ptr<Block>& allocated : mBlocks) {
        allocated->vectors = std::make_unique<std::array<glm::vec3, kBlockVoxels>>();
    }
}

void ClassifiedGrid::setVector(glm::u64vec3 ijk, glm::vec3 vector) {
    TEXSPLAT_ASSERT(hasVectors(), "ClassifiedGrid::setVector(): enableVectors() first");
    if (!isFinite(glm::dvec3(vector))) {
        std::ostringstream text;
        text << "ClassifiedGrid: voxel (" << ijk.x << ", " << ijk.y << ", " << ijk.z
             << "): vector must be finite, got " << vectorText(glm::dvec3(vector));
        throw DataError(text.str());
    }
    const std::uint32_t slot = blockSlot(ijk);
    if (slot != kNoBlock) {
        const StorageIndex storage = storageIndex(slot, ijk);
        (*mBlocks[slot]->vectors)[static_cast<std::size_t>(storage % kBlockVoxels)] = vector;
    }
}

glm::u64vec3 ClassifiedGrid::boxBlockDims(glm::u64vec3 dims) {
    return dims / kBlockSize + glm::u64vec3(glm::notEqual(dims % kBlockSize, glm::u64vec3(0)));
}

std::uint64_t ClassifiedGrid::boxBlockCount(glm::u64vec3 dims) {
    const glm::u64vec3 blocks = boxBlockDims(dims);
    return byteProduct(byteProduct(blocks.x, blocks.y), blocks.z);
}

std::uint64_t ClassifiedGrid::memoryBytes() const {
    return memoryBytesFor(mDims, mBlocks.size(), mHasVectors);
}

std::uint64_t ClassifiedGrid::memoryBytesFor(glm::u64vec3 dims, std::uint64_t blocks,
                                             bool withVectors) {
    const std::uint64_t perBlock =
        sizeof(Block) + sizeof(std::unique_ptr<Block>) +
        (withVectors ? sizeof(std::array<glm::vec3, kBlockVoxels>) : 0);
    return byteSum(byteProduct(boxBlockCount(dims), sizeof(std::uint32_t)),
                         byteProduct(blocks, perBlock));
}

} // namespace texsplat::octree
