#include "cs2/Automation.h"

namespace stellwerk::cs2 {
namespace {

constexpr int UpperRows = 26;

std::optional<int> rowIndex(char row) {
    if (row >= 'A' && row <= 'Z')
        return row - 'A';
    if (row >= 'a' && row <= 'z')
        return UpperRows + (row - 'a');
    return std::nullopt;
}

char rowLetter(int index) {
    return index < UpperRows ? char('A' + index) : char('a' + (index - UpperRows));
}

} // namespace

std::optional<MemoryFunction> MemoryFunction::fromWire(std::uint16_t function) {
    const char row = char(function >> 8);
    const auto column = std::uint8_t(function & 0xFF);
    if (!rowIndex(row) || column < '1' || column > '0' + Columns)
        return std::nullopt;
    return MemoryFunction(row, column);
}

std::optional<MemoryFunction> MemoryFunction::fromNumber(int number) {
    if (number < 1 || number > Count)
        return std::nullopt;
    const int slot = number - 1;
    return MemoryFunction(rowLetter(slot / Columns), std::uint8_t('1' + slot % Columns));
}

std::optional<MemoryFunction> MemoryFunction::fromText(std::string_view text) {
    if (text.size() != 2)
        return std::nullopt;
    return fromWire(std::uint16_t(std::uint8_t(text[0]) << 8 | std::uint8_t(text[1])));
}

int MemoryFunction::number() const {
    return *rowIndex(row_) * Columns + column();
}

std::optional<AutomationState> automationStateOf(std::uint8_t value) {
    if (value <= std::uint8_t(AutomationState::Reserved) || value == std::uint8_t(AutomationState::Waiting) ||
        value == std::uint8_t(AutomationState::Error))
        return AutomationState(value);
    return std::nullopt;
}

std::string_view automationStateName(AutomationState state) {
    switch (state) {
    case AutomationState::Deactivated:
        return "deactivated";
    case AutomationState::Activated:
        return "activated";
    case AutomationState::Running:
        return "running";
    case AutomationState::BlockFree:
        return "block-free";
    case AutomationState::BlockOccupied:
        return "block-occupied";
    case AutomationState::Suspended:
        return "suspended";
    case AutomationState::Reserved:
        return "reserved";
    case AutomationState::Waiting:
        return "waiting";
    case AutomationState::Error:
        return "error";
    }
    return "error";
}

} // namespace stellwerk::cs2
