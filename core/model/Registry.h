#pragma once

#include <cstddef>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace stellwerk::model {

// Items in the order they were added, found by key in O(1): what the views list and what a received
// frame looks up.
template <class Key, class Item>
class Registry {
public:
    Item* find(const Key& key) {
        const auto it = index_.find(key);
        return it == index_.end() ? nullptr : &items_[it->second];
    }
    const Item* find(const Key& key) const { return const_cast<Registry*>(this)->find(key); }

    // Adds the item, or replaces the one with the same key in place.
    Item& put(const Key& key, Item item) {
        if (Item* existing = find(key)) {
            *existing = std::move(item);
            return *existing;
        }
        index_.emplace(key, items_.size());
        keys_.push_back(key);
        return items_.emplace_back(std::move(item));
    }

    const std::vector<Item>& items() const { return items_; }
    // The items to change in place (their keys must stay as they are).
    std::span<Item> items() { return items_; }
    const std::vector<Key>& keys() const { return keys_; }
    std::size_t size() const { return items_.size(); }
    void clear() {
        items_.clear();
        keys_.clear();
        index_.clear();
    }

private:
    std::vector<Item> items_;
    std::vector<Key> keys_;
    std::unordered_map<Key, std::size_t> index_;
};

// The keys one batch changed, each once, in the order of their first change.
template <class Key>
class ChangedKeys {
public:
    void add(const Key& key) {
        if (seen_.emplace(key, true).second)
            keys_.push_back(key);
    }
    bool empty() const { return keys_.empty(); }
    bool contains(const Key& key) const { return seen_.count(key) != 0; }
    const std::vector<Key>& keys() const { return keys_; }

private:
    std::vector<Key> keys_;
    std::unordered_map<Key, bool> seen_;
};

} // namespace stellwerk::model
