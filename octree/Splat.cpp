#include "octree/Splat.h"

#include "scenegraph/Assert.h"

namespace texsplat::octree {

void SplatList::reserve(std::size_t count, bool withVectors) {
    mSplats.reserve(count);
    if (withVectors) {
        mVectors.reserve(count);
    }
}

void SplatList::add(const Splat& splat) {
    TEXSPLAT_ASSERT(mVectors.empty(), "SplatList::add(): a vector splat list needs the vector");
    mSplats.push_back(splat);
}

void SplatList::add(const Splat& splat, const SplatVector& vector) {
    TEXSPLAT_ASSERT(mVectors.size() == mSplats.size(),
                    "SplatList::add(): a scalar splat list cannot take a vector splat");
    mSplats.push_back(splat);
    mVectors.push_back(vector);
}

void SplatList::resize(std::size_t count, bool withVectors) {
    mSplats.resize(count);
    mVectors.resize(withVectors ? count : 0);
}

void SplatList::clear() {
    mSplats.clear();
    mVectors.clear();
}

} // namespace texsplat::octree
