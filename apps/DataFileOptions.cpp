#include "apps/DataFileOptions.h"

#include "apps/OptionError.h"
#include "scenegraph/Error.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace texsplat::apps {
namespace {

// A whole number from `low` to `high`, or nullopt.
std::optional<std::int64_t> wholeNumber(const std::string& text, std::int64_t low,
                                        std::int64_t high) {
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [parsed, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || parsed != end || value < low || value > high)
        return std::nullopt;
    return value;
}

glm::i64vec3 parseDims(const std::string& text) {
    constexpr std::int64_t kMaxSamples = 1000000000;
    glm::i64vec3 dims(0);
    std::size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t comma = text.find(',', start);
        const bool last = axis == 2;
        if (last != (comma == std::string::npos))
            throw DataError("expected X,Y,Z (voxels along x, y and z, x fastest in the file), "
                            "got '" + text + "'");
        const std::string part = text.substr(start, last ? std::string::npos : comma - start);
        const std::optional<std::int64_t> value = wholeNumber(part, 1, kMaxSamples);
        if (!value)
            throw DataError("expected X,Y,Z of whole numbers from 1 to 1e9, got '" + text + "'");
        dims[axis] = *value;
        start = comma + 1;
    }
    return dims;
}

volume::RawValueType parseType(const std::string& text) {
    for (const auto type : {volume::RawValueType::UInt8, volume::RawValueType::Int8,
                            volume::RawValueType::UInt16, volume::RawValueType::Int16,
                            volume::RawValueType::UInt32, volume::RawValueType::Int32,
                            volume::RawValueType::Float32, volume::RawValueType::Float64})
        if (text == volume::toString(type))
            return type;
    throw DataError("expected uint8, int8, uint16, int16, uint32, int32, float32 or float64, "
                    "got '" + text + "'");
}

} // namespace

void addHeaderlessOptions(CLI::App& command, HeaderlessOptions& options) {
    command
        .add_option("--dims", options.dims,
                    "Read the data file as headerless raw values of X,Y,Z voxels (x fastest), "
                    "laid out as --type, --byte-order, --header-bytes and --components say")
        ->type_name("X,Y,Z");
    command
        .add_option("--type", options.type,
                    "With --dims: uint8, int8, uint16, int16, uint32, int32, float32 or float64")
        ->capture_default_str();
    command.add_option("--byte-order", options.byteOrder, "With --dims: little or big")
        ->capture_default_str();
    command
        .add_option("--header-bytes", options.headerBytes,
                    "With --dims: bytes of some other header to skip before the values")
        ->capture_default_str();
    command
        .add_option("--components", options.components,
                    "With --dims: 1 (scalars) or 3 (vectors, x y z interleaved per voxel)")
        ->capture_default_str();
}

std::optional<volume::HeaderlessRawLayout> headerlessLayout(const HeaderlessOptions& options) {
    const HeaderlessOptions defaults;
    if (options.dims.empty()) {
        const char* given = options.type != defaults.type               ? "--type"
                            : options.byteOrder != defaults.byteOrder     ? "--byte-order"
                            : options.headerBytes != defaults.headerBytes ? "--header-bytes"
                            : options.components != defaults.components   ? "--components"
                                                                          : nullptr;
        if (given != nullptr)
            throw DataError(std::string(given) +
                            ": only with --dims, for a headerless raw file (other files say "
                            "their own layout)");
        return std::nullopt;
    }
    volume::HeaderlessRawLayout result;
    result.layout.dims = withOption("--dims", [&] { return parseDims(options.dims); });
    result.layout.type = withOption("--type", [&] { return parseType(options.type); });
    result.layout.endian = withOption("--byte-order", [&] {
        if (options.byteOrder != "little" && options.byteOrder != "big")
            throw DataError("expected little or big, got '" + options.byteOrder + "'");
        return options.byteOrder == "little" ? volume::RawEndian::Little : volume::RawEndian::Big;
    });
    result.headerBytes = withOption("--header-bytes", [&] {
        const std::optional<std::int64_t> bytes =
            wholeNumber(options.headerBytes, 0, std::int64_t{1} << 62);
        if (!bytes)
            throw DataError("expected a whole number of bytes >= 0, got '" +
                            options.headerBytes + "'");
        return *bytes;
    });
    result.layout.components = withOption("--components", [&] {
        if (options.components != "1" && options.components != "3")
            throw DataError("expected 1 or 3, got '" + options.components + "'");
        return options.components == "1" ? 1 : 3;
    });
    return result;
}

std::string headerlessArguments(const HeaderlessOptions& options) {
    if (options.dims.empty())
        return {};
    const HeaderlessOptions defaults;
    std::string text = " --dims " + options.dims;
    if (options.type != defaults.type)
        text += " --type " + options.type;
    if (options.byteOrder != defaults.byteOrder)
        text += " --byte-order " + options.byteOrder;
    if (options.headerBytes != defaults.headerBytes)
        text += " --header-bytes " + options.headerBytes;
    if (options.components != defaults.components)
        text += " --components " + options.components;
    return text;
}

void addDataRootOption(CLI::App& command, std::vector<std::string>& folders) {
    command
        .add_option("--data-root", folders,
                    "Read only files inside this folder (repeat for several): every file the "
                    "scene names (volumes, meshes and the buffers they name, a NRRD header's "
                    "data file, colour maps) must lie in one, after links and '..' are resolved; "
                    "for services that render scenes they did not write (docs/security.md)")
        ->type_name("DIR")
        ->allow_extra_args(false);
}

std::shared_ptr<const sg::DataRoots> dataRootsOf(const std::vector<std::string>& folders) {
    if (folders.empty())
        return nullptr;
    try {
        return std::make_shared<const sg::DataRoots>(folders);
    } catch (const IoError& error) {
        throw IoError(std::string("--data-root: ") + error.what());
    }
}

} // namespace texsplat::apps
