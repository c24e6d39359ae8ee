#include "nodes/bench/BenchDataset.h"

#include "nodes/OrthographicCamera.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/CameraView.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <sstream>

namespace texsplat::bench {
namespace {

struct SourceName {
    const char* prefix;
    BenchDataset::Source source;
};

constexpr SourceName kSourceNames[] = {{"ml", BenchDataset::Source::MarschnerLobb},
                                       {"tornado", BenchDataset::Source::Tornado},
                                       {"blob", BenchDataset::Source::Blob}};

constexpr int kMinResolution = 2;
constexpr int kMaxResolution = 1024;

[[noreturn]] void unknownDataset(const std::string& name) {
    throw DataError("unknown dataset '" + name +
                    "' (expected ml<N>, tornado<N> or blob<N> with N from 2 to 1024, e.g. ml41, "
                    "ml128, tornado128, blob256)");
}

// The transfer functions of examples/marschner-lobb.iv, tornado.iv and blob.iv.
nodes::TransferFunction::Ptr transferFunction(BenchDataset::Source source) {
    nodes::TransferFunction::Ptr transfer = nodes::TransferFunction::create();
    switch (source) {
    case BenchDataset::Source::MarschnerLobb:
        transfer->preset.setValue(nodes::ColorPreset::Viridis);
        transfer->range.setValue(glm::vec2(0.0f, 1.0f));
        transfer->opacityValues.setValue({0.0f, 0.45f, 0.55f, 1.0f});
        transfer->opacities.setValue({0.0f, 0.0f, 6.0f, 6.0f});
        break;
    case BenchDataset::Source::Tornado:
        transfer->preset.setValue(nodes::ColorPreset::Browns);
        transfer->range.setValue(glm::vec2(0.0f, 0.32f));
        transfer->opacityValues.setValue({0.0f, 0.35f, 1.0f});
        transfer->opacities.setValue({0.0f, 0.0f, 20.0f});
        break;
    case BenchDataset::Source::Blob:
        transfer->preset.setValue(nodes::ColorPreset::Hot);
        transfer->range.setValue(glm::vec2(0.0f, 1.2f));
        transfer->opacityValues.setValue({0.0f, 0.2f, 1.0f});
        transfer->opacities.setValue({0.0f, 0.0f, 8.0f});
        break;
    }
    return transfer;
}

nodes::VolumeSource volumeSource(BenchDataset::Source source) {
    switch (source) {
    case BenchDataset::Source::MarschnerLobb: return nodes::VolumeSource::MarschnerLobb;
    case BenchDataset::Source::Tornado: return nodes::VolumeSource::Tornado;
    case BenchDataset::Source::Blob: return nodes::VolumeSource::Blob;
    }
    return nodes::VolumeSource::Blob;
}

} // namespace

BenchDataset BenchDataset::fromName(const std::string& name) {
    for (const SourceName& entry : kSourceNames) {
        const std::string prefix = entry.prefix;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        const std::string digits = name.substr(prefix.size());
        const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
        if (digits.size() > 4 || digits.front() == '0' ||
            !std::all_of(digits.begin(), digits.end(), isDigit)) {
            unknownDataset(name);
        }
        const int resolution = std::stoi(digits);
        if (resolution < kMinResolution || resolution > kMaxResolution) {
            unknownDataset(name);
        }
        return BenchDataset(entry.source, resolution);
    }
    unknownDataset(name);
}

std::vector<BenchDataset> BenchDataset::parseList(const std::string& names) {
    std::vector<BenchDataset> datasets;
    std::istringstream stream(names);
    std::string name;
    while (std::getline(stream, name, ',')) {
        datasets.push_back(fromName(name));
    }
    if (datasets.empty()) {
        throw DataError("empty dataset list");
    }
    return datasets;
}

std::string BenchDataset::name() const {
    for (const SourceName& entry : kSourceNames) {
        if (entry.source == mSource) {
            return entry.prefix + std::to_string(mResolution);
        }
    }
    return std::to_string(mResolution);
}

std::string BenchDataset::description() const {
    const std::string cube = std::to_string(mResolution) + "^3";
    switch (mSource) {
    case Source::MarschnerLobb: return "Marschner-Lobb " + cube;
    case Source::Tornado: return "tornado " + cube;
    case Source::Blob: return "blob " + cube;
    }
    return cube;
}

glm::vec3 BenchDataset::viewDirection() const {
    // The tornado from the side, its funnel upright (as `texsplat render` shows it); the others
    // obliquely, so that no axis lines voxels up behind one another.
    return mSource == Source::Tornado ? glm::vec3(0.0f, 1.0f, -0.25f)
                                      : glm::vec3(0.35f, 0.5f, -1.0f);
}

sg::Separator::Ptr BenchDataset::scene(const sg::Node::Ptr& splatNode, float aspect,
                                       render::FramingCamera kind) const {
    nodes::VolumeData::Ptr volume = nodes::VolumeData::create();
    volume->setName(name());
    volume->source.setValue(volumeSource(mSource));
    volume->resolution.setValue(glm::vec3(static_cast<float>(mResolution)));
    const std::shared_ptr<nodes::Camera> camera =
        kind == render::FramingCamera::Orthographic
            ? std::shared_ptr<nodes::Camera>(nodes::OrthographicCamera::create())
            : std::shared_ptr<nodes::Camera>(nodes::PerspectiveCamera::create());
    camera->orientation.setValue(render::rotationLookingAlong(viewDirection()));
    camera->viewAll(volume->bounds(), aspect);
    sg::Separator::Ptr root = sg::Separator::create();
    root->addChild(camera);
    root->addChild(transferFunction(mSource));
    root->addChild(volume);
    root->addChild(splatNode);
    return root;
}

} // namespace texsplat::bench
