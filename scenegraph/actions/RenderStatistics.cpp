#include "scenegraph/actions/RenderStatistics.h"

#include <algorithm>

namespace texsplat::sg {

std::string_view toString(RenderPhase phase) {
    switch (phase) {
    case RenderPhase::Load: return "load";
    case RenderPhase::Classify: return "classify";
    case RenderPhase::Order: return "order";
    case RenderPhase::Upload: return "upload";
    case RenderPhase::Draw: return "draw";
    case RenderPhase::ReadBack: return "read back";
    }
    return "unknown";
}

void RenderStatistics::addTime(RenderPhase phase, double wallSeconds) {
    seconds[static_cast<std::size_t>(phase)] += wallSeconds;
}

RenderStatistics& RenderStatistics::operator+=(const RenderStatistics& other) {
    for (std::size_t phase = 0; phase < kRenderPhaseCount; ++phase) {
        seconds[phase] += other.seconds[phase];
    }
    splats += other.splats;
    triangles += other.triangles;
    previewed += other.previewed;
    memory.keepLarger(other.memory);
    builds += other.builds;
    return *this;
}

FrameBuilds& FrameBuilds::operator+=(const FrameBuilds& other) {
    valueRanges += other.valueRanges;
    classifications += other.classifications;
    octrees += other.octrees;
    valueHistograms += other.valueHistograms;
    previews += other.previews;
    splatBatches += other.splatBatches;
    return *this;
}

void FrameMemory::keepLarger(const FrameMemory& other) {
    grids = std::max(grids, other.grids);
    classified = std::max(classified, other.classified);
    octree = std::max(octree, other.octree);
    splats = std::max(splats, other.splats);
    textures = std::max(textures, other.textures);
}

} // namespace texsplat::sg
