#pragma once

#include <QString>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

class QSettings;

namespace stellwerk::model {

// Which address each locomotive has for Z21 clients (the Z21 app, WLANmaus), which know only DCC-like
// numbers: a DCC locomotive keeps its own address; MM and mfx locomotives get one of their own from this
// book (an MM one its MM address while that is free, an mfx one the first free from 1000), never two
// locomotives on one address. Kept with the settings and meant to be edited in the Locomotives panel.
class Z21Addresses {
public:
    // The Z21 addresses clients can use.
    static constexpr std::uint16_t First = 1;
    static constexpr std::uint16_t Last = 9999;
    static constexpr std::uint16_t FirstForMfx = 1000;

    enum class Refusal : std::uint8_t { None, OutOfRange, Taken, DccKeepsItsAddress };

    // Whether a locomotive takes its Z21 address from this book (MM and mfx ones), so that it can be changed.
    static bool isBooked(std::uint32_t locId);

    // Gives every MM and mfx locomotive of `locIds` that has none an address, and forgets nothing (a
    // locomotive that is gone may come back). DCC locomotives keep theirs.
    void cover(const std::vector<std::uint32_t>& locIds);
    // The Z21 address of a locomotive: a DCC one's own, else the book's; nullopt: none given.
    std::optional<std::uint16_t> addressOf(std::uint32_t locId) const;
    // The locomotive of `locIds` on a Z21 address.
    std::optional<std::uint32_t> locoAt(std::uint16_t address,
                                        const std::vector<std::uint32_t>& locIds) const;
    // Gives an MM or mfx locomotive another address; refused (and nothing changed) when a DCC locomotive of
    // `locIds` or another entry of the book has it, or it is outside First..Last.
    Refusal assign(std::uint32_t locId, std::uint16_t address, const std::vector<std::uint32_t>& locIds);
    // Which locomotive of `locIds` (other than `locId`) already has the address; nullopt: free.
    std::optional<std::uint32_t> holderOf(std::uint16_t address, const std::vector<std::uint32_t>& locIds,
                                          std::uint32_t locId = 0) const;
    const std::map<std::uint32_t, std::uint16_t>& entries() const { return entries_; }

    // Read from and written to the group "z21Addresses" of `settings`; entries that cannot be read or
    // that collide are left out.
    static Z21Addresses load(QSettings& settings);
    void save(QSettings& settings) const;

private:
    std::uint16_t firstFree(std::uint16_t from, const std::vector<std::uint32_t>& locIds) const;

    std::map<std::uint32_t, std::uint16_t> entries_; // Loc-ID -> Z21 address, MM and mfx only
};

} // namespace stellwerk::model
