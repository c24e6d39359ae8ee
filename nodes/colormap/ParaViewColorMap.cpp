#include "nodes/colormap/ParaViewColorMap.h"

#include "nodes/detail/JsonNesting.h"
#include "nodes/image/detail/FileBytes.h"
#include "scenegraph/Error.h"
#include "scenegraph/fields/ValueFormat.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace texsplat::colormap {
namespace {

// "path:line:column: what" for a JSON syntax error at byte `byte` (1-based, as nlohmann counts).
std::string syntaxError(const std::string& text, const std::string& path,
                        const nlohmann::json::parse_error& error) {
    const std::size_t end =
        std::min<std::size_t>(error.byte == 0 ? 0 : error.byte - 1, text.size());
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 1,
    // column 5: syntax error while parsing value - …": keep what follows the location.
    std::string what = error.what();
    const std::size_t columnText = what.find("column ");
    const std::size_t colon = what.find(": ", columnText == std::string::npos ? 0 : columnText);
    if (colon != std::string::npos) {
        what = what.substr(colon + 2);
    }
    return path + ":" + std::to_string(line) + ":" + std::to_string(column) +
           ": not valid JSON: " + what;
}

float number(const nlohmann::json& value, const std::string& context, std::size_t index) {
    if (!value.is_number()) {
        throw DataError(context + ": RGBPoints[" + std::to_string(index) +
                        "] must be a number, got " + value.dump());
    }
    const double x = value.get<double>();
    if (!std::isfinite(x) || std::abs(x) > 3.0e38) {
        throw DataError(context + ": RGBPoints[" + std::to_string(index) +
                        "] must be a finite float, got " + value.dump());
    }
    return static_cast<float>(x);
}

std::string text(const nlohmann::json& map, const char* key) {
    const auto found = map.find(key);
    return found != map.end() && found->is_string() ? found->get<std::string>() : std::string();
}

} // namespace

ParaViewColorMap parseParaViewColorMap(const std::string& source, const std::string& path) {
    // nlohmann parses without recursion, but copies a document recursively (document.front()
    // below): a million levels overflowed the stack.
    nodes::detail::checkJsonNesting(source, path);
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(source);
    } catch (const nlohmann::json::parse_error& error) {
        throw ParseError(syntaxError(source, path, error));
    } catch (const nlohmann::json::out_of_range& error) {
        // A number beyond double's range ("1e999"): nlohmann names the literal, not its place.
        const std::string what = error.what();
        const std::size_t bracket = what.find("] ");
        throw ParseError(path + ": not valid JSON: " +
                         (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
    if (document.is_array() && !document.empty()) {
        document = document.front();
    }
    if (!document.is_object()) {
        throw DataError(path + ": expected a ParaView colour map, a list of objects with "
                               "\"RGBPoints\", got " +
                        std::string(document.type_name()));
    }
    ParaViewColorMap result;
    result.name = text(document, "Name");
    result.colorSpace = text(document, "ColorSpace");
    const std::string context =
        result.name.empty() ? path : path + ": colour map '" + result.name + "'";
    const auto points = document.find("RGBPoints");
    if (points == document.end() || !points->is_array()) {
        throw DataError(context + ": has no \"RGBPoints\" list [x, r, g, b, …]");
    }
    if (points->empty() || points->size() % 4 != 0) {
        throw DataError(context + ": RGBPoints must hold x, r, g, b for each point (a multiple of "
                                  "4 numbers, at least 4), got " +
                        std::to_string(points->size()) + " numbers");
    }
    std::vector<float> x;
    for (std::size_t i = 0; i < points->size(); i += 4) {
        x.push_back(number((*points)[i], context, i));
        if (x.size() > 1 && x.back() < x[x.size() - 2]) {
            throw DataError(context + ": the x of RGBPoints must not decrease, but RGBPoints[" +
                            std::to_string(i) + "] = " + sg::formatFloat(x.back()) +
                            " follows " + sg::formatFloat(x[x.size() - 2]));
        }
        glm::vec3 color;
        for (int c = 0; c < 3; ++c) {
            const std::size_t index = i + 1 + static_cast<std::size_t>(c);
            color[c] = number((*points)[index], context, index);
            if (color[c] < 0.0f || color[c] > 1.0f) {
                throw DataError(context + ": RGBPoints[" + std::to_string(index) +
                                "] is a colour component and must lie in [0, 1], got " +
                                sg::formatFloat(color[c]));
            }
        }
        result.colors.push_back(color);
    }
    // As ParaView applies a preset: the points' own span becomes the transfer function's range.
    const double first = x.front();
    const double span = double(x.back()) - first;
    for (const float position : x) {
        result.positions.push_back(span > 0.0 ? static_cast<float>((position - first) / span)
                                              : 0.0f);
    }
    return result;
}

ParaViewColorMap readParaViewColorMap(const std::string& path) {
    const std::vector<char> bytes = image::detail::readFileBytes(path);
    return parseParaViewColorMap(std::string(bytes.begin(), bytes.end()), path);
}

} // namespace texsplat::colormap
