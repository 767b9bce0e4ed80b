#pragma once

#include <QHash>
#include <optional>
#include <vector>

namespace stellwerk::ui {

// Which table row shows which item of the railway, found both ways in O(1): what a table model needs to
// turn a batch of changed keys into one dataChanged without searching its rows per change.
template <class Key>
class RowIndex {
public:
    void reset(std::vector<Key> keys) {
        keys_ = std::move(keys);
        rows_.clear();
        for (int row = 0; row < int(keys_.size()); ++row)
            rows_.insert(keys_[std::size_t(row)], row);
    }
    void append(const Key& key) {
        rows_.insert(key, int(keys_.size()));
        keys_.push_back(key);
    }
    std::optional<int> row(const Key& key) const {
        const auto it = rows_.constFind(key);
        return it == rows_.cend() ? std::nullopt : std::optional<int>(*it);
    }
    const Key& key(int row) const { return keys_[std::size_t(row)]; }
    int size() const { return int(keys_.size()); }

private:
    std::vector<Key> keys_;
    QHash<Key, int> rows_;
};

} // namespace stellwerk::ui
