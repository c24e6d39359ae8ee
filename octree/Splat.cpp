#include "octree/Splat.h"

#include "scenegraph/Assert.h"

#include <algorithm>
#include <utility>

namespace texsplat::octree {

SplatList& SplatList::operator=(const SplatList& other) {
    mSplats = other.mSplats;
    mMarks = other.mMarks;
    mMarkBegins = other.mMarkBegins;
    mRevision = std::max(mRevision, other.mRevision) + 1;
    return *this;
}

SplatList& SplatList::operator=(SplatList&& other) noexcept {
    mSplats = std::move(other.mSplats);
    mMarks = std::move(other.mMarks);
    mMarkBegins = std::move(other.mMarkBegins);
    mRevision = std::max(mRevision, other.mRevision) + 1;
    return *this;
}

void SplatList::reserve(std::size_t count, bool withMarks) {
    mSplats.reserve(count);
    if (withMarks) {
        mMarkBegins.reserve(count + 1);
    }
}

void SplatList::add(const Splat& splat) {
    TEXSPLAT_ASSERT(mMarkBegins.empty(), "SplatList::add(): a vector splat list needs the marks");
    mSplats.push_back(splat);
    ++mRevision;
}

void SplatList::add(const Splat& splat, const SplatMark* marks, std::size_t markCount) {
    TEXSPLAT_ASSERT(mSplats.empty() || !mMarkBegins.empty(),
                    "SplatList::add(): a scalar splat list cannot take a vector splat");
    TEXSPLAT_ASSERT(mMarks.size() + markCount <= kMaxMarks, "SplatList::add(): too many marks");
    if (mMarkBegins.empty()) {
        mMarkBegins.push_back(0);
    }
    mSplats.push_back(splat);
    mMarks.insert(mMarks.end(), marks, marks + markCount);
    mMarkBegins.push_back(static_cast<std::uint32_t>(mMarks.size()));
    ++mRevision;
}

void SplatList::resize(std::size_t count, bool withMarks, std::size_t markCount) {
    TEXSPLAT_ASSERT(markCount <= kMaxMarks, "SplatList::resize(): too many marks");
    mSplats.resize(count);
    mMarks.resize(withMarks ? markCount : 0);
    mMarkBegins.resize(withMarks ? count + 1 : 0);
    ++mRevision;
}

void SplatList::clear() {
    mSplats.clear();
    mMarks.clear();
    mMarkBegins.clear();
    ++mRevision;
}

} // namespace texsplat::octree
