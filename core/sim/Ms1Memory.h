#pragma once

#include "can/CanFrame.h"
#include "mcan/Messages.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::sim {

// Who an MS1 is, whatever master it logs in to: its UID, the name it shows and how many locomotives its
// stack holds. The master may rename it (document 7.5).
struct Ms1Identity {
    std::uint32_t uid = 0x000204B3; // the chapter-11 trace's MS1
    std::string name = "KS MS1";    // at most 16 characters
    std::uint16_t stackSize = 10;
};

// The nodes and handles of one MS1's session (notes B§1.6): the node and start handle from the login,
// the SD and SY handles from the upgrade. The master's node is one less than the slave's.
struct Ms1Link {
    static constexpr std::uint16_t PollHandle = 0x0001; // the trace's poll handle (#82), not the start handle

    std::uint8_t node = 0;
    std::uint16_t startHandle = 0;
    std::uint16_t sdHandle = 0;
    std::uint16_t syHandle = 0;

    std::uint8_t masterNode() const { return std::uint8_t(node - 1); }
    mcan::Address at(std::uint16_t handle, std::uint8_t prio = mcan::prio::Data) const {
        return {prio, handle, node};
    }
};

// A function key of a locomotive as the master described it (FKT 2 = f0 ...; document 6.7.3).
struct Ms1Function {
    std::uint8_t kind = 0; // 01 latching, 02 momentary
    std::uint8_t icon = 0;
    std::uint8_t value = 0;
};

// A locomotive on the MS1's stack: what the upgrade's questions and the master's later frames told.
struct Ms1Loco {
    std::uint16_t handle = 0;
    std::string name;
    std::uint8_t type = 0;       // 00 none, 01 electric, 02 diesel, 03 steam
    std::uint8_t railFormat = 0; // 01 mfx, 02 DCC, 03 Motorola / Selectrix
    std::uint8_t speed = 0;      // 0..127
    bool reverse = false;
    std::vector<Ms1Function> functions; // f0, f1, ... as described (at most 8)
    std::uint16_t assignment = 0; // the last assignment answer: 0000 free, 0008, FFFF held by the master
};

// Whether the MS1 may drive the locomotive it shows (document 7.6).
enum class Ms1Control : std::uint8_t {
    None,         // no locomotive taken
    Asked,        // take request sent, no answer yet
    Granted,      // the master echoed the take request
    HeldByMaster, // the master answered FFFF: the MS1 shows the loco crossed out and only watches
};

// What an MS1 has learnt from its master during one session (notes B§3.2-3.8): the link, the status list,
// the stop and short-circuit state, its loco stack, the locomotive it shows and whether it may drive it.
// A new login starts with an empty memory.
struct Ms1Memory {
    Ms1Link link;
    std::map<std::uint8_t, std::uint8_t> statusTypes; // status index -> type (01 stop/go, 02 short circuit)
    bool stopped = false;
    bool shortCircuit = false;
    std::vector<Ms1Loco> stack;
    std::size_t capacity = 10; // the identity's stack size
    std::optional<std::size_t> shown;
    Ms1Control control = Ms1Control::None;
    bool choosingAgain = false; // chose the shown locomotive again after the master released it

    Ms1Loco* loco(std::uint16_t handle);
    std::optional<std::size_t> indexOf(std::uint16_t handle) const;
    const Ms1Loco* shownLoco() const { return shown ? &stack[*shown] : nullptr; }
    // The status index that carries `type`; before the status list is known, the trace's index (= type).
    std::uint8_t statusIndexOf(std::uint8_t type) const;
    // A status value of the master's (document 6.6, 7.4): type 01 is stop (1) or go (0), type 02 a short
    // circuit (1) or none (0); other types change nothing the MS1 shows.
    void setStatus(std::uint8_t index, std::uint8_t value);
};

// What one step of an MS1's conversation produces: frames to send and what a watcher should hear.
struct Ms1Outbox {
    enum class Event : std::uint8_t {
        LoggedIn,
        UpgradeDone,
        LocoTaken,
        LocoRefused,
        MasterLost,
        FlashMode,
        DisplayChanged
    };
    std::vector<can::CanFrame> frames;
    std::vector<std::pair<Event, int>> events;

    void send(const mcan::Message& message);
    void tell(Event event, int value = 0) { events.emplace_back(event, value); }
};

} // namespace stellwerk::sim
