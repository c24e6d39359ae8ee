#include "nodes/detail/SharedLoads.h"

#include <filesystem>
#include <map>
#include <mutex>

namespace texsplat::nodes::detail {
namespace {

struct Cache {
    std::mutex mutex;
    std::map<std::string, std::weak_ptr<const void>> loads;
};

Cache& cache() {
    static Cache instance;
    return instance;
}

} // namespace

std::shared_ptr<const void> sharedLoad(const std::string& key,
                                       const std::function<std::shared_ptr<const void>()>& load) {
    Cache& shared = cache();
    {
        const std::lock_guard<std::mutex> lock(shared.mutex);
        const auto found = shared.loads.find(key);
        if (found != shared.loads.end()) {
            if (std::shared_ptr<const void> alive = found->second.lock()) {
                return alive;
            }
            shared.loads.erase(found);
        }
    }
    // Loading takes long: without the lock, so that other files load meanwhile.
    std::shared_ptr<const void> result = load();
    const std::lock_guard<std::mutex> lock(shared.mutex);
    // Forget the loads nobody holds any more, so the map stays as small as what is shared.
    for (auto entry = shared.loads.begin(); entry != shared.loads.end();) {
        entry = entry->second.expired() ? shared.loads.erase(entry) : std::next(entry);
    }
    shared.loads[key] = result;
    return result;
}

std::string fileIdentity(const std::string& path) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::canonical(path, error);
    if (error) {
        return path;
    }
    const std::uintmax_t size = std::filesystem::file_size(canonical, error);
    const auto modified = std::filesystem::last_write_time(canonical, error);
    if (error) {
        return canonical.string();
    }
    return canonical.string() + "\n" + std::to_string(size) + "\n" +
           std::to_string(modified.time_since_epoch().count());
}

} // namespace texsplat::nodes::detail
