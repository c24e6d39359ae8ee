#include "octree/Splat.h"

#include "scenegraph/Assert.h"

#include <algorithm>
#include <utility>

namespace texsplat::octree {

SplatList& SplatList::operator=(const SplatList& other) {
    mSplats = other.mSplats;
    mVectors = other.mVectors;
    mRevision = std::max(mRevision, other.mRevision) + 1;
    return *this;
}

SplatList& SplatList::operator=(SplatList&& other) noexcept {
    mSplats = std::move(other.mSplats);
    mVectors = std::move(other.mVectors);
    mRevision = std::max(mRevision, other.mRevision) + 1;
    return *this;
}

void SplatList::reserve(std::size_t count, bool withVectors) {
    mSplats.reserve(count);
    if (withVectors) {
        mVectors.reserve(count);
    }
}

void SplatList::add(const Splat& splat) {
    TEXSPLAT_ASSERT(mVectors.empty(), "SplatList::add(): a vector splat list needs the vector");
    mSplats.push_back(splat);
    ++mRevision;
}

void SplatList::add(const Splat& splat, const SplatVector& vector) {
    TEXSPLAT_ASSERT(mVectors.size() == mSplats.size(),
                    "SplatList::add(): a scalar splat list cannot take a vector splat");
    mSplats.push_back(splat);
    mVectors.push_back(vector);
    ++mRevision;
}

void SplatList::resize(std::size_t count, bool withVectors) {
    mSplats.resize(count);
    mVectors.resize(withVectors ? count : 0);
    ++mRevision;
}

void SplatList::clear() {
    mSplats.clear();
    mVectors.clear();
    ++mRevision;
}

} // namespace texsplat::octree
