#pragma once

#include "cs2/Header.h"
#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace stellwerk::sim {

class StatusChannels;

// A Central Station 2 as seen on the CAN bus: answers every command the way a real one does and
// keeps the state. It is a peer behind a transport, never a shortcut inside the app: frames come in
// through receive() and go out through framesEmitted (to every listener, as a CS2 does).
class SimulatedStation : public QObject {
    Q_OBJECT

public:
    using Power = TrackPower;

    struct Options {
        std::uint32_t uid = 0x43533201;         // the CS2 master's UID
        bool gleisbox = false;                  // also a Gleisbox on the bus (ping, status data)
        std::uint32_t gleisboxUid = 0x47431001; // its UID
        std::uint16_t hash = 0;                 // 0: derived from uid as the document says
        Power power = Power::Stopped;           // track power at start (a CS2 starts in STOP)
        // mfx decoders on the track that no station registered yet: discovery finds them (UIDs).
        std::vector<std::uint32_t> newMfxDecoders{};
        // The M-CAN master of the MS1 handhelds on its bus, as a real CS2 is (StationHandhelds); false: it
        // answers a ping as a Gleisbox, which is no master, so that another program may be theirs.
        bool handheldMaster = true;
    };

    explicit SimulatedStation(StationLayout layout, QObject* parent = nullptr);
    SimulatedStation(StationLayout layout, Options options, QObject* parent = nullptr);
    ~SimulatedStation() override;

    // A frame from the bus (any sender; responses, including our own echoes, are not commands; M-CAN
    // frames, which MS1 handhelds and their master send, are not CS2 frames).
    // The answer goes out in one framesEmitted before this returns.
    void receive(const can::CanFrame& frame);

    std::uint32_t uid() const;
    // The hash the station sends with; a new one after another sender used it (document 1.2.4).
    std::uint16_t hash() const;
    Power power() const;
    // A decoder the station knows (in the cycle or programmed), or null.
    const SimulatedLoco* loco(std::uint32_t locId) const;
    // Position of an accessory by its Loc-ID (0x3000 + keyboard number - 1 for MM, 0x3800.. DCC).
    std::optional<std::uint8_t> accessoryPosition(std::uint32_t locId) const;
    // The state of a contact as set by setContact (false when never set).
    bool contact(std::uint16_t device, std::uint16_t contact) const;
    const StationLayout& layout() const;
    // The station's measurement and configuration channels (status data configuration).
    const StatusChannels& statusChannels() const;

    // Reports a changed S88 contact the way an S88/Link-S88 module does (0x11 event), and keeps it
    // for later queries. Used by the train movement. No event when the state is unchanged.
    void setContact(std::uint16_t device, std::uint16_t contact, bool occupied);
    // The load on the main track in milliampere, for the current reading (the train movement sets
    // it). Above the current limit the station reports an overload and switches the track off.
    void setTrackLoad(int milliampere);
    // Says on the bus what the track power is now (Stop, Go or Halt with the response bit, as the station
    // reports a change), without changing it: what a CS2 shows a controller that just connected.
    void announcePower();

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
    // Every frame given to receive(), before it is handled: the log of what reached the station, for
    // tests and the soak program that check nothing stale ever arrives.
    void frameReceived(const stellwerk::can::CanFrame& frame);

private:
    class Private;
    void emitAll(std::vector<can::CanFrame> frames);
    void runLater(std::chrono::milliseconds delay, std::function<void(Outbox&)> work);

    std::unique_ptr<Private> d_;
};

} // namespace stellwerk::sim
