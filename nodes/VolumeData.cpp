#include "nodes/VolumeData.h"

#include "nodes/detail/NodeContext.h"
#include "nodes/detail/SharedLoads.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/volume/Blob.h"
#include "nodes/volume/JetStream.h"
#include "nodes/volume/Magnitude.h"
#include "nodes/volume/MarschnerLobb.h"
#include "nodes/volume/NetCdfVolume.h"
#include "nodes/volume/NpyVolume.h"
#include "nodes/volume/NrrdVolume.h"
#include "nodes/volume/PlacedGrid.h"
#include "nodes/volume/RawVolume.h"
#include "nodes/volume/Tornado.h"
#include "nodes/volume/VdbVolume.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace texsplat::nodes {
namespace {

// Loads report to a traversal's progress at most once per this fraction of a step (and at its
// start and end): the viewer polls its window's events in that callback.
constexpr double kReportInterval = 0.01;

// The loader's progress for `path`: to the traversal's `work` when there is one, as the step
// "<the loader's message> from <file name>" ("reading from cloud.raw"), where a false answer
// throws sg::Cancelled out of the loader; else for the user through texsplat::log, named like the
// node's errors ("VolumeData 'cloud': cloud.raw: reading 40%"), when volume::logProgress() finds
// the load long enough to be worth it.
volume::ProgressCallback loadProgress(const VolumeData& node, const std::string& path,
                                      const sg::WorkProgress& work) {
    if (work) {
        return [&work, file = std::filesystem::path(path).filename().string(),
                step = std::string(), reported = 0.0](double fraction,
                                                      std::string_view message) mutable {
            std::string current = std::string(message) + " from " + file;
            const bool done = fraction >= 1.0 && reported < 1.0;
            if (current == step && !done && fraction < reported + kReportInterval) {
                return true;
            }
            step = std::move(current);
            reported = fraction;
            sg::reportWork(work, step, fraction);
            return true;
        };
    }
    std::error_code error; // a missing file fails in the loader, with the loader's message
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    return volume::logProgress(detail::nodeContext(node) + ": " + path,
                               error ? 0 : static_cast<std::int64_t>(bytes));
}

} // namespace

// What one load of the source yields.
struct VolumeData::Loaded {
    volume::AnyGrid grid;
    // Further scalar grids a generator makes along with the main one, by name.
    std::map<std::string, volume::ScalarGridPtr> scalars;
    std::vector<volume::Fiber> fibers;
};

VolumeData::VolumeData() {
    addField(source, "source", VolumeSource::Blob, kVolumeSourceNames,
             "Where the grid comes from: a file format (FILE_…), a built-in generator, or MEMORY "
             "(a grid given in C++)");
    addField(fileName, "fileName", std::string(),
             "The file of the FILE_ sources, relative to the scene file's folder");
    addField(gridName, "gridName", std::string(),
             "FILE_VDB: the grid, FILE_NETCDF: the variable (either may stay empty when the "
             "file has one); with component SCALAR the generator's scalar grid");
    addField(resolution, "resolution", glm::vec3(64.0f),
             "Generators: samples along x, y, z (whole numbers >= 1); files bring their own");
    addField(time, "time", 0.0f,
             "Animation time of the generators TORNADO (frames) and JET_STREAM (days)");
    addField(timeStep, "timeStep", 0,
             "FILE_NETCDF: step of a 4-D variable's first (time) dimension, from 0");
    addField(component, "component", VolumeComponent::Magnitude, kVolumeComponentNames,
             "The scalar that scalar splats classify, from vector data: MAGNITUDE |v|, or "
             "SCALAR the grid named by gridName");
    addField(dimensions, "dimensions", glm::vec3(0.0f),
             "FILE_RAW_HEADERLESS: voxels along x, y, z (whole numbers >= 1, x fastest in the "
             "file)");
    addField(dataType, "dataType", volume::RawValueType::Float32, kVolumeDataTypeNames,
             "FILE_RAW_HEADERLESS: the type of each value in the file");
    addField(byteOrder, "byteOrder", volume::RawEndian::Little, kVolumeByteOrderNames,
             "FILE_RAW_HEADERLESS: the byte order of multi-byte values");
    addField(headerBytes, "headerBytes", 0,
             "FILE_RAW_HEADERLESS: bytes to skip before the values, >= 0");
    addField(components, "components", 1,
             "FILE_RAW_HEADERLESS: values per voxel, 1 (scalars) or 3 (vectors, x y z "
             "interleaved)");
    addField(origin, "origin", std::vector<glm::vec3>{},
             "Any source: the centre of voxel (0,0,0) as x y z; none: the source's own");
    addField(spacing, "spacing", std::vector<glm::vec3>{},
             "Any source: the distance between voxel centres along x, y, z (> 0); none: the "
             "source's own");
}

namespace {

// Voxels per axis from an SFVec3f of whole numbers (Inventor has no integer vector field).
glm::i64vec3 wholeNumbers(const sg::SFVec3f& field, const std::string& name) {
    // Beyond this a grid could not be held anyway, and the conversion stays exact.
    constexpr float kMaxSamples = 1e9f;
    const glm::vec3 samples = field.value();
    for (int axis = 0; axis < 3; ++axis) {
        const float n = samples[axis];
        if (!(n >= 1.0f && n <= kMaxSamples) || std::floor(n) != n) {
            throw DataError(name + " must hold whole numbers from 1 to 1e9, got " +
                            field.valueText());
        }
    }
    return glm::i64vec3(samples);
}

} // namespace

glm::i64vec3 VolumeData::dims() const { return wholeNumbers(resolution, "resolution"); }

template <typename T>
std::shared_ptr<const volume::Grid<T>>
VolumeData::placed(std::shared_ptr<const volume::Grid<T>> grid) const {
    if (origin.size() == 0 && spacing.size() == 0) {
        return grid;
    }
    const auto one = [](const sg::MFVec3f& field, const glm::dvec3& fallback) {
        if (field.size() > 1) {
            throw DataError(field.name() +
                            " holds one x y z (or none, for the source's own), got " +
                            std::to_string(field.size()) + " values");
        }
        return field.size() == 1 ? glm::dvec3(field[0]) : fallback;
    };
    const volume::GridGeometry& own = grid->geometry();
    const glm::dvec3 where = one(origin, own.origin());
    const glm::dvec3 step = one(spacing, own.spacing());
    try {
        const volume::GridGeometry geometry(own.dims(), where, step);
        return std::make_shared<volume::PlacedGrid<T>>(std::move(grid), geometry);
    } catch (const DataError& error) {
        throw DataError(std::string("origin and spacing: ") + error.what());
    }
}

volume::RawHeader VolumeData::headerlessLayout() const {
    volume::RawHeader layout;
    layout.dims = wholeNumbers(dimensions, "dimensions");
    layout.type = dataType.as<volume::RawValueType>();
    layout.endian = byteOrder.as<volume::RawEndian>();
    if (components.value() != 1 && components.value() != 3) {
        throw DataError("components must be 1 or 3, got " + components.valueText());
    }
    layout.components = components.value();
    if (headerBytes.value() < 0) {
        throw DataError("headerBytes must be 0 or more, got " + headerBytes.valueText());
    }
    return layout;
}

std::shared_ptr<const VolumeData::Loaded>
VolumeData::loadShared(const sg::WorkProgress& progress) const {
    const auto kind = source.as<VolumeSource>();
    const bool readsFile = kind == VolumeSource::FileRaw ||
                           kind == VolumeSource::FileRawHeaderless ||
                           kind == VolumeSource::FileNpy || kind == VolumeSource::FileNrrd ||
                           kind == VolumeSource::FileNetCdf || kind == VolumeSource::FileVdb;
    if (!readsFile || fileName.value().empty()) {
        return read(progress);
    }
    // Everything that shapes what is read, so that only equal loads share. The data roots are
    // asked first: a grid another node read is shared only with a node that may read it too.
    std::string key = source.valueText() + "\n" +
                      detail::fileIdentity(readablePath(fileName.value(), "file"));
    const std::initializer_list<const sg::Field*> shaping = {
        &gridName, &timeStep, &dimensions, &dataType, &byteOrder, &headerBytes, &components};
    for (const sg::Field* field : shaping) {
        key += "\n" + field->valueText();
    }
    // A cancelled or failed read throws before anything is shared: the next load reads again.
    return detail::sharedLoad<Loaded>(key, [this, &progress] { return read(progress); });
}

std::shared_ptr<const VolumeData::Loaded>
VolumeData::read(const sg::WorkProgress& progress) const {
    auto result = std::make_shared<Loaded>();
    const auto kind = source.as<VolumeSource>();
    const auto requireFile = [this]() -> std::string {
        if (fileName.value().empty()) {
            throw DataError("fileName is empty; source " +
                            *kVolumeSourceNames.name(source.value()) + " reads a file");
        }
        return readablePath(fileName.value(), "file");
    };
    switch (kind) {
    case VolumeSource::FileRaw: {
        const std::string path = requireFile();
        result->grid = volume::readRawVolume(path, loadProgress(*this, path, progress));
        break;
    }
    case VolumeSource::FileRawHeaderless: {
        const std::string path = requireFile();
        result->grid = volume::readHeaderlessRawVolume(path, headerlessLayout(),
                                                       headerBytes.value(),
                                                       loadProgress(*this, path, progress));
        break;
    }
    case VolumeSource::FileNpy: {
        const std::string path = requireFile();
        result->grid = volume::readNpyVolume(path, loadProgress(*this, path, progress));
        break;
    }
    case VolumeSource::FileNrrd: {
        const std::string path = requireFile();
        result->grid =
            volume::readNrrdVolume(path, loadProgress(*this, path, progress), dataRoots().get());
        break;
    }
    case VolumeSource::FileNetCdf: {
        const std::string path = requireFile();
        result->grid = volume::readNetCdfVariable(path, gridName.value(), timeStep.value(),
                                                  loadProgress(*this, path, progress));
        break;
    }
    case VolumeSource::FileVdb: {
        const std::string path = requireFile();
        std::string name = gridName.value();
        if (name.empty()) {
            // A file of one grid needs no name; otherwise say which names there are.
            const std::vector<volume::VdbGridInfo> grids = volume::listVdbGrids(path);
            if (grids.size() != 1) {
                std::string names;
                for (const volume::VdbGridInfo& grid : grids) {
                    names += (names.empty() ? "" : ", ") + grid.name + " (" + grid.valueType + ")";
                }
                throw DataError(
                    grids.empty() ? path + ": the file has no grids"
                                  : "gridName is empty and " + path + " has " +
                                        std::to_string(grids.size()) +
                                        " grids; set gridName to one of: " + names);
            }
            name = grids.front().name;
        }
        result->grid = volume::readVdbGrid(path, name, loadProgress(*this, path, progress));
        break;
    }
    case VolumeSource::Tornado:
        result->grid = volume::generateTornado({dims(), double(time.value())});
        break;
    case VolumeSource::MarschnerLobb: {
        volume::MarschnerLobbParameters parameters;
        parameters.dims = dims();
        result->grid = volume::generateMarschnerLobb(parameters);
        break;
    }
    case VolumeSource::Blob: {
        volume::BlobParameters parameters;
        parameters.dims = dims();
        result->grid = volume::generateBlob(parameters);
        break;
    }
    case VolumeSource::JetStream: {
        volume::JetStreamParameters parameters;
        parameters.dims = dims();
        parameters.time = double(time.value());
        volume::JetStreamField field = volume::generateJetStream(parameters);
        result->grid = std::move(field.wind);
        result->scalars.emplace("cloudiness", std::move(field.cloudiness));
        break;
    }
    case VolumeSource::Aerogel: {
        volume::AerogelParameters parameters;
        parameters.dims = dims();
        volume::AerogelField field = volume::generateAerogel(parameters);
        result->grid = std::move(field.velocity);
        result->fibers = std::move(field.fibers);
        break;
    }
    case VolumeSource::Memory: {
        const bool hasGrid =
            std::visit([](const auto& grid) { return grid != nullptr; }, mMemoryGrid);
        if (!hasGrid) {
            throw DataError("source MEMORY has no grid: a program gives it one with "
                            "VolumeData::setGrid(); a scene file cannot hold one");
        }
        result->grid = mMemoryGrid;
        break;
    }
    }
    return result;
}

std::shared_ptr<const VolumeData::Loaded>
VolumeData::loaded(const sg::WorkProgress& progress) const {
    if (!mLoaded) {
        mLoaded =
            detail::withNodeContext(*this, [this, &progress] { return loadShared(progress); });
    }
    return mLoaded;
}

void VolumeData::load(const sg::WorkProgress& progress) const {
    const std::lock_guard<std::mutex> lock(mMutex);
    loaded(progress);
}

volume::ScalarGridPtr VolumeData::scalarGrid() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    const std::shared_ptr<const Loaded> data = loaded();
    if (mScalar) {
        return mScalar;
    }
    if (const auto* scalar = std::get_if<volume::ScalarGridPtr>(&data->grid)) {
        mScalar = detail::withNodeContext(*this, [&] { return placed(*scalar); });
        return mScalar;
    }
    const volume::VectorGridPtr& vectors = std::get<volume::VectorGridPtr>(data->grid);
    mScalar = detail::withNodeContext(*this, [&]() -> volume::ScalarGridPtr {
        if (component.as<VolumeComponent>() == VolumeComponent::Magnitude) {
            return placed(volume::magnitudeGrid(*vectors));
        }
        const auto found = data->scalars.find(gridName.value());
        if (found == data->scalars.end()) {
            std::string names;
            for (const auto& [name, grid] : data->scalars) {
                names += (names.empty() ? "" : ", ") + name;
            }
            throw DataError("component SCALAR: source " +
                            *kVolumeSourceNames.name(source.value()) + " has no scalar grid '" +
                            gridName.value() + "' (" +
                            (names.empty() ? "it has vectors only; use MAGNITUDE"
                                           : "it has: " + names) +
                            ")");
        }
        return placed(found->second);
    });
    return mScalar;
}

volume::VectorGridPtr VolumeData::vectorGrid() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    const std::shared_ptr<const Loaded> data = loaded();
    const auto* vectors = std::get_if<volume::VectorGridPtr>(&data->grid);
    if (vectors == nullptr) {
        return nullptr;
    }
    if (!mVectors) {
        mVectors = detail::withNodeContext(*this, [&] { return placed(*vectors); });
    }
    return mVectors;
}

std::vector<volume::Fiber> VolumeData::fibers() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return loaded()->fibers;
}

sg::Box3 VolumeData::bounds() const {
    const volume::VectorGridPtr vectors = vectorGrid();
    const volume::GridGeometry geometry =
        vectors ? vectors->geometry() : scalarGrid()->geometry();
    return sg::Box3(glm::vec3(geometry.boundsMin()), glm::vec3(geometry.boundsMax()));
}

void VolumeData::setGrid(volume::AnyGrid grid) {
    {
        const std::lock_guard<std::mutex> lock(mMutex);
        mMemoryGrid = std::move(grid);
    }
    if (source.as<VolumeSource>() == VolumeSource::Memory) {
        touch();
    } else {
        source.setValue(VolumeSource::Memory);
    }
}

bool VolumeData::isLoaded() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return mLoaded != nullptr;
}

void VolumeData::getBoundingBox(sg::BoundingBoxAction& action) {
    // Also the element: shapes after it (Fibers) bound what they draw from this volume.
    doAction(action);
    // Framing a scene is often what reads its volumes first.
    load(action.workProgress());
    action.extendBy(bounds());
}

void VolumeData::doAction(sg::Action& action) {
    action.state().modify<VolumeElement>().volume = this;
}

void VolumeData::notify(const sg::Field* changed) {
    {
        const std::lock_guard<std::mutex> lock(mMutex);
        mLoaded.reset();
        mScalar.reset();
        mVectors.reset();
    }
    sg::Node::notify(changed);
}

} // namespace texsplat::nodes
