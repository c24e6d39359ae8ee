#include "scenegraph/detail/FieldNames.h"

#include <memory>
#include <mutex>
#include <unordered_map>

namespace texsplat::sg::detail {

const std::string& internFieldName(std::string_view name) {
    static std::mutex mutex;
    // Keyed by a view of the string it owns, so that looking a name up allocates nothing.
    static std::unordered_map<std::string_view, std::unique_ptr<const std::string>> names;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = names.find(name);
    if (found != names.end()) {
        return *found->second;
    }
    auto interned = std::make_unique<const std::string>(name);
    const std::string& result = *interned;
    names.emplace(result, std::move(interned));
    return result;
}

const std::string& noName() {
    static const std::string empty;
    return empty;
}

} // namespace texsplat::sg::detail
