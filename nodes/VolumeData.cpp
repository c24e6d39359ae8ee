#include "nodes/VolumeData.h"

#include "nodes/detail/NodeContext.h"
#include "nodes/detail/SharedLoads.h"
#include "nodes/elements/VolumeElement.h"
#include "nodes/volume/Blob.h"
#include "nodes/volume/BrickGrid.h"
#include "nodes/volume/DenseGrid.h"
#include "nodes/volume/JetStream.h"
#include "nodes/volume/Magnitude.h"
#include "nodes/volume/MarschnerLobb.h"
#include "nodes/volume/NetCdfVolume.h"
#include "nodes/volume/NrrdHeader.h"
#include "nodes/volume/PlacedGrid.h"
#include "nodes/volume/Tornado.h"
#include "nodes/volume/VdbVolume.h"
#include "nodes/volume/detail/RawData.h"
#include "nodes/volume/detail/SourceSupport.h"
#include "scenegraph/Error.h"
#include "scenegraph/actions/Action.h"
#include "scenegraph/actions/BoundingBoxAction.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
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
    // A brick's (setBrick()): whether it is one, and once setWholeGrids() gave them, the whole
    // grid's figures of `grid` (which its magnitudes share).
    bool isBrick = false;
    std::shared_ptr<const volume::WholeGrid> gridWhole;
    // Where the grids' first voxel is in the whole grid (a brick's region; 0 for a whole load).
    glm::i64vec3 offset{0};
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

volume::GridGeometry VolumeData::placedGeometry(const volume::GridGeometry& own,
                                                const glm::i64vec3& offset) const {
    const auto one = [](const sg::MFVec3f& field, const glm::dvec3& fallback) {
        if (field.size() > 1) {
            throw DataError(field.name() +
                            " holds one x y z (or none, for the source's own), got " +
                            std::to_string(field.size()) + " values");
        }
        return field.size() == 1 ? glm::dvec3(field[0]) : fallback;
    };
    const glm::dvec3 step = one(spacing, own.spacing());
    // A brick's first voxel is voxel `offset` of the whole grid, which the fields place.
    const glm::dvec3 first = glm::dvec3(offset);
    const glm::dvec3 where = one(origin, own.origin() - first * own.spacing()) + first * step;
    try {
        return volume::GridGeometry(own.dims(), where, step);
    } catch (const DataError& error) {
        throw DataError(std::string("origin and spacing: ") + error.what());
    }
}

template <typename T>
std::shared_ptr<const volume::Grid<T>>
VolumeData::placed(std::shared_ptr<const volume::Grid<T>> grid, const glm::i64vec3& offset) const {
    if (origin.size() == 0 && spacing.size() == 0) {
        return grid;
    }
    const volume::GridGeometry geometry = placedGeometry(grid->geometry(), offset);
    return std::make_shared<volume::PlacedGrid<T>>(std::move(grid), geometry);
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
VolumeData::read(const sg::WorkProgress& progress,
                 const std::optional<volume::IndexBox>& region) const {
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
    case VolumeSource::FileRaw:
    case VolumeSource::FileRawHeaderless:
    case VolumeSource::FileNpy:
    case VolumeSource::FileNrrd: {
        const std::string path = requireFile();
        const volume::ProgressCallback reading = loadProgress(*this, path, progress);
        result->grid = region ? volume::detail::readRawGridRegion(rawData(path), *region, reading)
                              : volume::detail::readRawGrid(rawData(path), reading);
        break;
    }
    case VolumeSource::FileNetCdf: {
        const std::string path = requireFile();
        result->grid = volume::NetCdfReader(path).read(gridName.value(), timeStep.value(),
                                                       loadProgress(*this, path, progress), region);
        break;
    }
    case VolumeSource::FileVdb: {
        const std::string path = requireFile();
        const std::string name = vdbGridName(path);
        const volume::ProgressCallback reading = loadProgress(*this, path, progress);
        result->grid = region ? volume::readVdbRegion(path, name, *region, reading)
                              : volume::readVdbGrid(path, name, reading);
        break;
    }
    case VolumeSource::Tornado:
        result->grid = volume::generateTornado({dims(), double(time.value())}, region);
        break;
    case VolumeSource::MarschnerLobb: {
        volume::MarschnerLobbParameters parameters;
        parameters.dims = dims();
        result->grid = volume::generateMarschnerLobb(parameters, region);
        break;
    }
    case VolumeSource::Blob: {
        volume::BlobParameters parameters;
        parameters.dims = dims();
        result->grid = volume::generateBlob(parameters, region);
        break;
    }
    case VolumeSource::JetStream: {
        volume::JetStreamParameters parameters;
        parameters.dims = dims();
        parameters.time = double(time.value());
        volume::JetStreamField field = volume::generateJetStream(parameters, region);
        result->grid = std::move(field.wind);
        result->scalars.emplace("cloudiness", std::move(field.cloudiness));
        break;
    }
    case VolumeSource::Aerogel: {
        volume::AerogelParameters parameters;
        parameters.dims = dims();
        volume::AerogelField field = volume::generateAerogel(parameters, region);
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
        if (region) {
            // A view of the program's grid: no copy.
            result->grid = std::visit(
                [&](const auto& grid) -> volume::AnyGrid {
                    using Value = typename std::decay_t<decltype(*grid)>::ValueType;
                    return std::make_shared<const volume::BrickGrid<Value>>(grid, *region, nullptr);
                },
                mMemoryGrid);
        }
        break;
    }
    }
    return result;
}

namespace {

// A grid of one empty voxel where `grid` has its first: what a brick without voxels serves.
volume::AnyGrid emptyVoxel(const volume::AnyGrid& grid) {
    return std::visit(
        [](const auto& typed) -> volume::AnyGrid {
            using Value = typename std::decay_t<decltype(*typed)>::ValueType;
            const volume::GridGeometry one(glm::i64vec3(1), typed->geometry().origin(),
                                           typed->geometry().spacing());
            return std::make_shared<const volume::DenseGrid<Value>>(
                one, Value(std::numeric_limits<float>::quiet_NaN()));
        },
        grid);
}

// `grid` as a brick with the whole grid's figures `whole`: a view made by read() is unwrapped
// first, so that a brick reads its voxels through one view.
template <typename T>
std::shared_ptr<const volume::Grid<T>> asBrick(const std::shared_ptr<const volume::Grid<T>>& grid,
                                               std::shared_ptr<const volume::WholeGrid> whole) {
    if (const auto* view = dynamic_cast<const volume::BrickGrid<T>*>(grid.get())) {
        return std::make_shared<const volume::BrickGrid<T>>(view->voxels(), view->box(),
                                                            std::move(whole));
    }
    return std::make_shared<const volume::BrickGrid<T>>(
        grid, volume::IndexBox::of(grid->geometry()), std::move(whole));
}

} // namespace

std::shared_ptr<const VolumeData::Loaded>
VolumeData::readBrick(const sg::WorkProgress& progress, const volume::GridGeometry& whole) const {
    const volume::IndexBox region = mBrick->intersection(volume::IndexBox::of(whole));
    std::shared_ptr<Loaded> result;
    if (region.isEmpty()) {
        // No voxel here: the first voxel's kind and place, with nothing in it.
        auto data = std::make_shared<Loaded>(
            *read(progress, volume::IndexBox{glm::i64vec3(0), glm::i64vec3(1)}));
        data->grid = emptyVoxel(data->grid);
        for (auto& [name, grid] : data->scalars) {
            grid = std::get<volume::ScalarGridPtr>(emptyVoxel(grid));
        }
        result = std::move(data);
    } else {
        result = std::make_shared<Loaded>(*read(progress, region));
        result->offset = region.lo;
    }
    result->isBrick = true;
    return result;
}

std::shared_ptr<const VolumeData::Loaded>
VolumeData::loaded(const sg::WorkProgress& progress) const {
    if (!mLoaded) {
        mLoaded = detail::withNodeContext(*this, [this, &progress] {
            return mBrick ? readBrick(progress, wholeGeometryHeld()) : loadShared(progress);
        });
    }
    return mLoaded;
}

std::shared_ptr<const VolumeData::Loaded> VolumeData::servedData() const {
    std::shared_ptr<const Loaded> data = loaded();
    if (data->isBrick && !data->gridWhole) {
        throw DataError(detail::nodeContext(*this) +
                        ": a brick of a render split over processes was loaded without the whole "
                        "grid's figures (a distributed render loads every volume and gathers "
                        "them before the frame)");
    }
    return data;
}

void VolumeData::load(const sg::WorkProgress& progress) const {
    const std::lock_guard<std::mutex> lock(mMutex);
    loaded(progress);
}

volume::ScalarGridPtr VolumeData::scalarGrid() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    const std::shared_ptr<const Loaded> data = servedData();
    if (mScalar) {
        return mScalar;
    }
    if (const auto* scalar = std::get_if<volume::ScalarGridPtr>(&data->grid)) {
        mScalar = detail::withNodeContext(*this, [&] { return placed(*scalar, data->offset); });
        return mScalar;
    }
    const volume::VectorGridPtr& vectors = std::get<volume::VectorGridPtr>(data->grid);
    mScalar = detail::withNodeContext(*this, [&]() -> volume::ScalarGridPtr {
        if (component.as<VolumeComponent>() == VolumeComponent::Magnitude) {
            volume::ScalarGridPtr magnitudes = volume::magnitudeGrid(*vectors);
            // A brick's magnitudes: the vectors' whole figures are their lengths'.
            if (data->gridWhole) {
                magnitudes = asBrick(magnitudes, data->gridWhole);
            }
            return placed(magnitudes, data->offset);
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
        return placed(found->second, data->offset);
    });
    return mScalar;
}

volume::VectorGridPtr VolumeData::vectorGrid() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    const std::shared_ptr<const Loaded> data = servedData();
    const auto* vectors = std::get_if<volume::VectorGridPtr>(&data->grid);
    if (vectors == nullptr) {
        return nullptr;
    }
    if (!mVectors) {
        mVectors = detail::withNodeContext(*this, [&] { return placed(*vectors, data->offset); });
    }
    return mVectors;
}

std::vector<volume::Fiber> VolumeData::fibers() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return loaded()->fibers;
}

sg::Box3 VolumeData::bounds() const {
    const volume::GridGeometry geometry = [this] {
        {
            // A brick's box is the whole grid's, read from the source's header: framing and
            // outlines show the whole volume.
            const std::lock_guard<std::mutex> lock(mMutex);
            if (mBrick) {
                return wholeGeometryHeld();
            }
        }
        const volume::VectorGridPtr vectors = vectorGrid();
        return vectors ? vectors->geometry() : scalarGrid()->geometry();
    }();
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

void VolumeData::setBrick(const std::optional<volume::IndexBox>& region) {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (region != mBrick) {
        mBrick = region;
        mLoaded.reset();
        mScalar.reset();
    }
}

std::optional<volume::IndexBox> VolumeData::brick() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return mBrick;
}

volume::GridGeometry VolumeData::wholeGeometry() const {
    const std::lock_guard<std::mutex> lock(mMutex);
    return detail::withNodeContext(*this, [this] { return wholeGeometryHeld(); });
}

volume::GridGeometry VolumeData::wholeGeometryHeld() const {
    const volume::GridGeometry own = [this] {
        switch (source.as<VolumeSource>()) {
        case VolumeSource::FileRaw:
        case VolumeSource::FileRawHeaderless:
        case VolumeSource::FileNpy:
            return volume::detail::rawGridGeometry(rawData(readablePath(fileName.value(), "file")));
        case VolumeSource::FileNrrd: {
            // The header alone: its gzip data would be checked to the end once handed over.
            const std::string path = readablePath(fileName.value(), "file");
            std::ifstream in = volume::detail::openForReading(path);
            const volume::RawHeader layout = volume::NrrdHeader::parse(in, path).layout;
            return volume::GridGeometry(layout.dims, layout.origin, layout.spacing);
        }
        case VolumeSource::FileNetCdf:
            return volume::NetCdfReader(readablePath(fileName.value(), "file"))
                .geometry(gridName.value(), timeStep.value())
                .first;
        case VolumeSource::FileVdb: {
            const std::string path = readablePath(fileName.value(), "file");
            return volume::vdbGridGeometry(path, vdbGridName(path));
        }
        case VolumeSource::Memory: {
            const std::shared_ptr<const Loaded> data = read({});
            return std::visit([](const auto& grid) { return grid->geometry(); }, data->grid);
        }
        default: {
            // A generator's first voxel says where the grid starts and how its voxels lie.
            const std::shared_ptr<const Loaded> first =
                read({}, volume::IndexBox{glm::i64vec3(0), glm::i64vec3(1)});
            const volume::GridGeometry one =
                std::visit([](const auto& grid) { return grid->geometry(); }, first->grid);
            return volume::GridGeometry(dims(), one.origin(), one.spacing());
        }
        }
    }();
    return placedGeometry(own, glm::i64vec3(0));
}

std::function<void(const volume::detail::RawDataDecoder&)>
VolumeData::rawData(const std::string& path) const {
    switch (source.as<VolumeSource>()) {
    case VolumeSource::FileRaw:
        return [path](const volume::detail::RawDataDecoder& use) {
            volume::detail::withRawVolumeData(path, use);
        };
    case VolumeSource::FileRawHeaderless:
        return
            [this, path, layout = headerlessLayout()](const volume::detail::RawDataDecoder& use) {
                volume::detail::withHeaderlessRawData(path, layout, headerBytes.value(), use);
            };
    case VolumeSource::FileNpy:
        return [path](const volume::detail::RawDataDecoder& use) {
            volume::detail::withNpyData(path, use);
        };
    default:
        return [this, path, roots = dataRoots()](const volume::detail::RawDataDecoder& use) {
            volume::detail::withNrrdData(path, use, roots.get());
        };
    }
}

std::string VolumeData::vdbGridName(const std::string& path) const {
    if (!gridName.value().empty()) {
        return gridName.value();
    }
    // A file of one grid needs no name; otherwise say which names there are.
    const std::vector<volume::VdbGridInfo> grids = volume::listVdbGrids(path);
    if (grids.size() != 1) {
        std::string names;
        for (const volume::VdbGridInfo& grid : grids) {
            names += (names.empty() ? "" : ", ") + grid.name + " (" + grid.valueType + ")";
        }
        throw DataError(grids.empty() ? path + ": the file has no grids"
                                      : "gridName is empty and " + path + " has " +
                                            std::to_string(grids.size()) +
                                            " grids; set gridName to one of: " + names);
    }
    return grids.front().name;
}

std::vector<volume::AnyGrid> VolumeData::brickGrids(const sg::WorkProgress& progress) const {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (!mBrick) {
        throw DataError(detail::nodeContext(*this) + ": brickGrids() of a whole node");
    }
    const std::shared_ptr<const Loaded> data = loaded(progress);
    std::vector<volume::AnyGrid> grids{data->grid};
    for (const auto& named : data->scalars) {
        grids.emplace_back(named.second);
    }
    return grids;
}

void VolumeData::setWholeGrids(
    const std::vector<std::shared_ptr<const volume::WholeGrid>>& wholes) {
    const std::lock_guard<std::mutex> lock(mMutex);
    if (!mLoaded || !mLoaded->isBrick || wholes.size() != 1 + mLoaded->scalars.size()) {
        throw DataError(detail::nodeContext(*this) +
                        ": setWholeGrids() needs a loaded brick and the figures of each of its "
                        "grids");
    }
    auto data = std::make_shared<Loaded>(*mLoaded);
    data->gridWhole = wholes.front();
    data->grid = std::visit(
        [&](const auto& grid) -> volume::AnyGrid { return asBrick(grid, data->gridWhole); },
        data->grid);
    std::size_t next = 1;
    for (auto& named : data->scalars) {
        named.second = asBrick(named.second, wholes[next++]);
    }
    mLoaded = std::move(data);
    mScalar.reset();
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
