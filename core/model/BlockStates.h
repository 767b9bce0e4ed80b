#pragma once

#include "cs2/Automation.h"
#include "cs2/LocId.h"

#include <QList>
#include <QObject>
#include <QString>
#include <compare>
#include <cstdint>
#include <map>
#include <optional>

namespace stellwerk::station {
class StationSession;
struct StationUpdates;
} // namespace stellwerk::station

namespace stellwerk::model {

// Where chapter 9 of the CS2 document addresses an automation function or a block: a device id (2.13) and
// the function in that device (a memory function "A1".."z8", or another value the device uses).
struct AutomationAddress {
    std::uint16_t device = 0;
    std::uint16_t function = 0;

    friend auto operator<=>(const AutomationAddress&, const AutomationAddress&) = default;
};

// What an announced state means to a person: a memory function's marking (not marked, green, yellow), a
// block's state, or unknown (a run error, or a value the document does not define).
enum class AnnouncedMeaning : std::uint8_t {
    Deactivated,
    Activated,
    Running,
    Free,
    Occupied,
    Waiting,
    Reserved,
    Unknown
};

// The latest state announced for one address: the value as received, the document's state for it (none:
// a value the document does not define, shown as "unknown"), and the locomotive in the block if named.
struct AnnouncedState {
    std::uint8_t value = 0;
    std::optional<cs2::AutomationState> state;
    std::optional<cs2::LocId> loco;
    bool isUnknown() const { return !state || *state == cs2::AutomationState::Error; }
    AnnouncedMeaning meaning() const;
};

// The states Stellwerk announces for its own blocks.
enum class BlockState : std::uint8_t { Free, Occupied, Reserved, Waiting, Unknown };

// The book of block and memory function states the programs on the bus announce with the station's own
// automation command (CS2 chapter 9, 0x30), and the way Stellwerk announces its own blocks' states and
// requests a memory function there. Block n of the track graph is addressed as memory slot n (A1 = block 1,
// B1 = block 9, ... z8 = block 416) on Stellwerk's device id, so that another program sees it there, and
// another Stellwerk on the same plan shows it on the same block.
class BlockStates final : public QObject {
    Q_OBJECT

public:
    // Stellwerk's device id in automation addresses ("SW"; 2.13 forbids 0 and 0xFFFF). No station hands
    // one to a PC program, so it is fixed.
    static constexpr std::uint16_t StellwerkDevice = 0x5357;
    // The device id that asks the master to run a memory function ("Sonderfall Broadcastadresse").
    static constexpr std::uint16_t MasterDevice = 0x0000;

    explicit BlockStates(station::StationSession& session, QObject* parent = nullptr);

    // Everything announced since the station was last heard, by address.
    const std::map<AutomationAddress, AnnouncedState>& announced() const { return announced_; }
    std::optional<AnnouncedState> announcedAt(AutomationAddress address) const;
    // What the bus says about block `blockId` of the plan (announced on Stellwerk's address of it).
    std::optional<AnnouncedState> blockState(int blockId) const;
    // The latest state any device announced for a memory function (the master's answers to a request).
    std::optional<AnnouncedState> memoryState(cs2::MemoryFunction function) const;

    // Routes by their id in fahrstrassen.cs2, which is their memory slot: "A1" for route 1, "B1" for route
    // 9; empty (and no state, no request) beyond "z8" (416).
    static QString memorySlotOfRoute(std::int64_t route);
    std::optional<AnnouncedState> routeState(std::int64_t route) const;
    bool requestRoute(std::int64_t route, bool activate = true);

    // The address of a track graph block (ids count from 1); none beyond the 416 memory slots.
    static std::optional<AutomationAddress> addressOfBlock(int blockId);
    // The document's status value for a state of ours: free 3, occupied 4, reserved 6, waiting 5 ("Block
    // suspendiert, wartet"), unknown 255 ("Ablauffehler", shown as "Status unbekannt").
    static std::uint8_t statusValue(BlockState state);

    // Says on the bus that block `blockId` is in `state` (a status answer on the block's address); false
    // when the block has no address or the frame could not be sent.
    bool announce(int blockId, BlockState state);
    std::optional<BlockState> ownState(int blockId) const;
    // Asks the station's master to run (activate) or release a memory function; its answers come back as
    // announcements. False when the frame could not be sent.
    bool requestMemoryFunction(cs2::MemoryFunction function, bool activate = true);

signals:
    // The addresses whose announced state changed (once per batch of frames), or all of them when the
    // station was lost and the book forgotten.
    void changed(const QList<stellwerk::model::AutomationAddress>& addresses);

private:
    void apply(const station::StationUpdates& updates);
    void forget();

    station::StationSession& session_;
    std::map<AutomationAddress, AnnouncedState> announced_;
    std::map<std::uint16_t, AutomationAddress> latestOfFunction_;
    std::map<int, BlockState> own_;
};

} // namespace stellwerk::model
