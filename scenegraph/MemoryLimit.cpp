#include "scenegraph/MemoryLimit.h"

#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace texsplat {
namespace {

// The one limit of the process, set by applications (0: the default).
std::atomic<std::uint64_t>& limitSlot() {
    static std::atomic<std::uint64_t> slot{0};
    return slot;
}

std::uint64_t physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageBytes = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageBytes > 0 ? std::uint64_t(pages) * std::uint64_t(pageBytes) : 0;
}

} // namespace

std::uint64_t memoryLimit() {
    const std::uint64_t limit = limitSlot().load();
    return limit != 0 ? limit : physicalMemoryBytes();
}

std::uint64_t setMemoryLimit(std::uint64_t bytes) { return limitSlot().exchange(bytes); }

std::uint64_t availableMemoryBytes() {
    std::ifstream info("/proc/meminfo");
    std::string key;
    std::uint64_t kibibytes = 0;
    std::string unit;
    while (info >> key >> kibibytes >> unit) {
        if (key == "MemAvailable:")
            return kibibytes * 1024;
    }
    return physicalMemoryBytes();
}

std::string bytesText(std::uint64_t bytes) {
    static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double scaled = double(bytes) / 1024.0;
    std::size_t unit = 0;
    while (scaled >= 1024.0 && unit + 1 < std::size(kUnits)) {
        scaled /= 1024.0;
        ++unit;
    }
    char rounded[32];
    std::snprintf(rounded, sizeof rounded, "%.3g %s", scaled, kUnits[unit]);
    return std::to_string(bytes) + " bytes (" + rounded + ")";
}

std::uint64_t parseByteCount(std::string_view text) {
    const auto fail = [text]() -> std::uint64_t {
        throw DataError("expected a byte count such as 512M or 8G, got '" + std::string(text) +
                        "'");
    };
    std::size_t end = 0;
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) ||
                                 text[end] == '.')) {
        ++end;
    }
    const std::string number(text.substr(0, end));
    if (number.empty() || number.find('.') != number.rfind('.') || number == ".")
        return fail();
    std::string suffix(text.substr(end));
    for (char& c : suffix)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    // "", "B", or a unit K, M, G, T alone or with "B" or "iB"; a fraction only with a unit.
    static constexpr std::string_view kUnits = "KMGT";
    const std::size_t unit = suffix.empty() ? std::string_view::npos : kUnits.find(suffix[0]);
    const std::string rest = unit == std::string_view::npos ? suffix : suffix.substr(1);
    const bool isUnitSuffix = rest.empty() || rest == "B" || (unit != std::string_view::npos &&
                                                               rest == "IB");
    if (!isUnitSuffix || (unit == std::string_view::npos && number.find('.') != std::string::npos))
        return fail();
    const double scale =
        unit == std::string_view::npos ? 1.0 : std::ldexp(1.0, 10 * (1 + int(unit)));
    const double bytes = std::floor(std::stod(number) * scale);
    if (!(bytes >= 1.0) || bytes >= std::ldexp(1.0, 64))
        return fail();
    return static_cast<std::uint64_t>(bytes);
}

std::uint64_t byteProduct(std::uint64_t count, std::uint64_t each) {
    constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
    return each != 0 && count > kLargest / each ? kLargest : count * each;
}

std::uint64_t byteSum(std::uint64_t a, std::uint64_t b) {
    constexpr std::uint64_t kLargest = std::numeric_limits<std::uint64_t>::max();
    return a > kLargest - b ? kLargest : a + b;
}

void checkMemory(std::string_view what, std::uint64_t bytes, std::string_view advice) {
    const std::uint64_t limit = memoryLimit();
    if (limit != 0 && bytes > limit)
        throw ResourceError(std::string(what) + " would need " + bytesText(bytes) +
                            ", more than the memory limit of " + bytesText(limit) + "; " +
                            std::string(advice));
}

std::string outOfMemoryText(std::string_view stage, std::uint64_t estimate,
                            std::string_view advice) {
    std::string text = std::string(stage) + ": out of memory";
    if (estimate != 0)
        text += " (this stage was estimated at " + bytesText(estimate) + ")";
    const std::uint64_t limit = memoryLimit();
    if (limit != 0)
        text += "; the memory limit is " + bytesText(limit);
    return text + "; " + std::string(advice);
}

} // namespace texsplat
