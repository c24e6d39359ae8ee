#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsplat::render::detail {

/// What a backend derives from a shared object (a footprint, a mark table) and keeps while the
/// object lives: one Value per object and tag (e.g. a GL context's serial), made on first use
/// and dropped once the object is gone. Few objects live at a time, so a list is searched.
template <class Key, class Value> class KeptPerObject {
public:
    /// The value kept for `key` and `tag`, made by `make()` when there is none.
    template <class Make>
    Value& get(const std::shared_ptr<const Key>& key, std::uint64_t tag, Make&& make) {
        mEntries.erase(std::remove_if(mEntries.begin(), mEntries.end(),
                                      [](const Entry& entry) { return entry.key.expired(); }),
                       mEntries.end());
        for (Entry& entry : mEntries) {
            if (entry.tag == tag && entry.key.lock() == key) {
                return entry.value;
            }
        }
        mEntries.push_back({key, tag, make()});
        ++mMade;
        return mEntries.back().value;
    }

    /// Values made so far.
    std::size_t made() const { return mMade; }

private:
    struct Entry {
        std::weak_ptr<const Key> key;
        std::uint64_t tag;
        Value value;
    };

    std::vector<Entry> mEntries;
    std::size_t mMade = 0;
};

} // namespace texsplat::render::detail
