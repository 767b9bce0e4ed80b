#pragma once

#include "cs2config/Node.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace stellwerk::cs2config {

// Writes typed values into a record (or a sub-block) while keeping everything it is not told to
// change: unknown keys, their order, spacing, and values whose meaning did not change ("0x05" stays
// "0x05" when the number is still 5). Missing keys are added only when they differ from the default.
class RecordEditor {
public:
    enum class Base { Decimal, Hex };

    RecordEditor(Node& record, const LineStyle& style) : record_(record), style_(style) {}

    Node& record() { return record_; }

    // Sets key=value; adds the line after the record's last value line when the key is missing.
    void setText(std::string_view key, std::string_view value);
    // Like setText, but a missing key is only added when the value is not empty.
    void setOptionalText(std::string_view key, std::string_view value);
    // Sets a number unless the line already holds that number; a missing key is only added when
    // the value differs from `absentMeans` (the value a reader assumes for a missing key).
    void setInteger(std::string_view key, std::int64_t value, Base base = Base::Decimal,
                    std::optional<std::int64_t> absentMeans = std::nullopt);
    void remove(std::string_view key);
    // A new sub-block line ("<indent>.funktionen") appended at the end of the record.
    Node& appendBlock(std::string_view key);

private:
    Node& insertEntry(std::string_view key, std::string_view value);
    Node* ownLine(std::string_view key);
    int childLevel() const { return record_.level() + 1; }

    Node& record_;
    const LineStyle& style_;
};

} // namespace stellwerk::cs2config
