#include "octree/ClassifiedGrid.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"

#include <glm/vector_relational.hpp>

#include <cmath>
#include <limits>
#include <memory>
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

ClassifiedGrid::ClassifiedGrid(glm::u64vec3 dims, glm::dvec3 spacing, glm::dvec3 origin,
                               std::vector<glm::vec4> palette)
    : ClassifiedGrid(dims, spacing, origin) {
    if (palette.empty() || palette.size() > kPaletteSize) {
        throw DataError("ClassifiedGrid: a palette holds 1 to " + std::to_string(kPaletteSize) +
                        " media, got " + std::to_string(palette.size()));
    }
    if (palette.front() != glm::vec4(0.0f)) {
        throw DataError("ClassifiedGrid: the palette's first medium must be empty");
    }
    for (std::size_t i = 0; i < palette.size(); ++i) {
        for (int channel = 0; channel < 4; ++channel) {
            if (!std::isfinite(palette[i][channel]) || palette[i][channel] < 0.0f) {
                std::ostringstream text;
                text << "ClassifiedGrid: palette medium " << i << ": "
                     << (channel < 3 ? "color" : "extinction") << " must be finite and >= 0, got "
                     << palette[i][channel];
                throw DataError(text.str());
            }
        }
    }
    mPalette = std::move(palette);
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
    if (slot != kNoBlock) {
        return *mBlocks[slot];
    }
    const std::array<glm::vec4, kBlockVoxels> empty{};
    return allocateBlock(ijk / kBlockSize, &empty, nullptr);
}

ClassifiedGrid::Block&
ClassifiedGrid::allocateBlock(glm::u64vec3 coordinates,
                              const std::array<glm::vec4, kBlockVoxels>* voxels,
                              const PaletteBlock* indices) {
    if (mBlocks.size() >= kNoBlock) {
        throw DataError("ClassifiedGrid: more than 2^32 - 1 blocks of 8^3 voxels");
    }
    auto allocated = std::make_unique<Block>();
    allocated->coordinates = coordinates;
    // The voxels copied in as the block is made: zeroing it first cost as much as the copy.
    if (voxels != nullptr) {
        allocated->voxels = std::make_unique<std::array<glm::vec4, kBlockVoxels>>(*voxels);
    } else {
        allocated->indices = std::make_unique<PaletteBlock>(*indices);
    }
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
    TEXSPLAT_ASSERT(storage() == Storage::Direct,
                    "ClassifiedGrid::setVoxel(): a palette grid is set by blocks of indices");
    const glm::vec4 value(color, extinction);
    checkVoxel(ijk, value);
    if (value == glm::vec4(0.0f) && blockSlot(ijk) == kNoBlock) {
        return;
    }
    Block& target = block(ijk);
    glm::vec4& stored = (*target.voxels)[static_cast<std::size_t>(offsetInBlock(ijk))];
    const int change = (value != glm::vec4(0.0f) ? 1 : 0) - (stored != glm::vec4(0.0f) ? 1 : 0);
    mNonEmptyCount += static_cast<std::uint64_t>(static_cast<std::int64_t>(change));
    target.nonEmpty =
        static_cast<std::uint32_t>(static_cast<std::int64_t>(target.nonEmpty) + change);
    stored = value;
}

template <typename IsEmpty>
void ClassifiedGrid::checkClipped(glm::u64vec3 block, IsEmpty&& isEmpty) const {
    if (glm::any(glm::greaterThan((block + std::uint64_t{1}) * kBlockSize, mDims))) {
        for (std::size_t i = 0; i < kBlockVoxels; ++i) {
            const glm::u64vec3 voxel =
                block * kBlockSize + glm::u64vec3(i % kBlockSize, (i / kBlockSize) % kBlockSize,
                                                  i / (kBlockSize * kBlockSize));
            TEXSPLAT_ASSERT(glm::all(glm::lessThan(voxel, mDims)) || isEmpty(i),
                            "ClassifiedGrid::setBlock(): a voxel outside the grid is not empty");
            static_cast<void>(voxel);
            static_cast<void>(isEmpty);
        }
    }
}

void ClassifiedGrid::setBlock(glm::u64vec3 block,
                              const std::array<glm::vec4, kBlockVoxels>& voxels) {
    TEXSPLAT_ASSERT(storage() == Storage::Direct,
                    "ClassifiedGrid::setBlock(): a palette grid is set by blocks of indices");
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
    for (std::size_t i = 0; i < kBlockVoxels && !valid; ++i) {
        checkVoxel(block * kBlockSize + glm::u64vec3(i % kBlockSize, (i / kBlockSize) % kBlockSize,
                                                     i / (kBlockSize * kBlockSize)),
                   voxels[i]);
    }
    if (nonEmpty == 0 && !hasBlock(block)) {
        return;
    }
    checkClipped(block, [&](std::size_t i) { return voxels[i] == glm::vec4(0.0f); });
    mNonEmptyCount += nonEmpty;
    if (!hasBlock(block)) {
        allocateBlock(block, &voxels, nullptr).nonEmpty = static_cast<std::uint32_t>(nonEmpty);
        return;
    }
    Block& target = this->block(block * kBlockSize);
    mNonEmptyCount -= target.nonEmpty;
    *target.voxels = voxels;
    target.nonEmpty = static_cast<std::uint32_t>(nonEmpty);
}

void ClassifiedGrid::setBlock(glm::u64vec3 block, const PaletteBlock& indices) {
    TEXSPLAT_ASSERT(storage() == Storage::Palette,
                    "ClassifiedGrid::setBlock(): a direct grid is set by blocks of media");
    std::uint64_t nonEmpty = 0;
    for (const std::uint16_t index : indices) {
        TEXSPLAT_ASSERT(index < mPalette.size(),
                        "ClassifiedGrid::setBlock(): index outside the palette");
        nonEmpty += mPalette[index] != glm::vec4(0.0f) ? 1 : 0;
    }
    if (nonEmpty == 0 && !hasBlock(block)) {
        return;
    }
    checkClipped(block, [&](std::size_t i) { return mPalette[indices[i]] == glm::vec4(0.0f); });
    mNonEmptyCount += nonEmpty;
    if (!hasBlock(block)) {
        allocateBlock(block, nullptr, &indices).nonEmpty = static_cast<std::uint32_t>(nonEmpty);
        return;
    }
    Block& target = this->block(block * kBlockSize);
    mNonEmptyCount -= target.nonEmpty;
    *target.indices = indices;
    target.nonEmpty = static_cast<std::uint32_t>(nonEmpty);
}

void ClassifiedGrid::readBlock(StorageIndex first,
                               std::array<glm::vec4, kBlockVoxels>& voxels) const {
    const Block& block = *mBlocks[static_cast<std::size_t>(first / kBlockVoxels)];
    if (block.voxels) {
        voxels = *block.voxels;
        return;
    }
    for (std::size_t i = 0; i < kBlockVoxels; ++i) {
        voxels[i] = mPalette[(*block.indices)[i]];
    }
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
    return memoryBytesFor(mDims, mBlocks.size(), mHasVectors, mPalette.size());
}

std::uint64_t ClassifiedGrid::blockBytes(bool withVectors, Storage storage) {
    return sizeof(Block) + sizeof(std::unique_ptr<Block>) +
           (storage == Storage::Palette ? sizeof(PaletteBlock)
                                        : sizeof(std::array<glm::vec4, kBlockVoxels>)) +
           (withVectors ? sizeof(std::array<glm::vec3, kBlockVoxels>) : 0);
}

std::uint64_t ClassifiedGrid::memoryBytesFor(glm::u64vec3 dims, std::uint64_t blocks,
                                             bool withVectors, std::size_t paletteSize) {
    const Storage storage = paletteSize > 0 ? Storage::Palette : Storage::Direct;
    return byteSum(byteSum(byteProduct(boxBlockCount(dims), sizeof(std::uint32_t)),
                           byteProduct(blocks, blockBytes(withVectors, storage))),
                   byteProduct(paletteSize, sizeof(glm::vec4)));
}

} // namespace texsplat::octree
