#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::cs2 {

// A memory function as chapter 9 and 1.3.2.2 address it: a row letter (A-Z, then a-z) in the high byte and a
// column digit ('1'-'8') in the low byte, "A1".."z8". Its number counts the slots row by row (A1 = 1, A8 = 8,
// B1 = 9, ... z8 = 416), the way a CS2 numbers its routes (fahrstrassen.cs2 `.id`) in the memory.
class MemoryFunction {
public:
    static constexpr int Columns = 8;
    static constexpr int Rows = 52;
    static constexpr int Count = Rows * Columns;

    // nullopt for a function outside A1..z8 (another automation function, or a value no device uses yet).
    static std::optional<MemoryFunction> fromWire(std::uint16_t function);
    // 1..416; nullopt outside.
    static std::optional<MemoryFunction> fromNumber(int number);
    // "A1".."z8"; nullopt for anything else.
    static std::optional<MemoryFunction> fromText(std::string_view text);

    std::uint16_t wire() const { return std::uint16_t(std::uint16_t(std::uint8_t(row_)) << 8 | column_); }
    int number() const;
    char row() const { return row_; }
    int column() const { return column_ - '0'; }
    std::string text() const { return {row_, char(column_)}; }

    friend bool operator==(const MemoryFunction&, const MemoryFunction&) = default;

private:
    MemoryFunction(char row, std::uint8_t column) : row_(row), column_(column) {}

    char row_ = 'A';
    std::uint8_t column_ = '1';
};

// The states a status answer of chapter 9 carries, with the document's values.
enum class AutomationState : std::uint8_t {
    Deactivated = 0,   // "Automatikfunktion deaktiviert" (not marked)
    Activated = 1,     // "aktiviert" (marked green)
    Running = 2,       // "im Ablauf, beim Einlaufen" (marked yellow)
    BlockFree = 3,     // "Block frei"
    BlockOccupied = 4, // "Block belegt"
    Suspended = 5,     // "Block / Automatikfunktion Suspendiert, Wartet"
    Reserved = 6,      // "Block / Automatikfunktion Reserviert, Vorbelegt"
    Waiting = 254,     // "Automatikfunktion wartet"
    Error = 255,       // "Ablauffehler", shown as "Status unbekannt"
};

// The document's state for a status value; nullopt for a value it does not define, which a display shows
// as "status unknown", as the document asks (the value itself is kept by whoever received it).
std::optional<AutomationState> automationStateOf(std::uint8_t value);
// "deactivated", "activated", "running", "block-free", "block-occupied", "suspended", "reserved", "waiting",
// "error".
std::string_view automationStateName(AutomationState state);

} // namespace stellwerk::cs2
