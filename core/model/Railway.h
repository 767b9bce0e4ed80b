#pragma once

#include "model/BlockStates.h"
#include "model/Programmer.h"
#include "model/RailwayState.h"
#include "model/ReadingPoller.h"
#include "model/RouteRunner.h"
#include "model/ThrottlePort.h"
#include "model/UnconfirmedCommands.h"

#include <QList>
#include <QObject>
#include <QString>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>

namespace stellwerk::station {
class StationSession;
class StateQueryRound;
struct CommandResult;
} // namespace stellwerk::station

namespace stellwerk::model {

// Switches the accessories a device drives instead of the station (RailwayDevices: OpenRailCAN decoder
// outputs, RO relays).
class DeviceAccessories {
public:
    virtual ~DeviceAccessories() = default;
    virtual bool drives(std::int64_t accessory) const = 0;
    // Whether a device input lights the contact: the station's reports of it are then left out.
    virtual bool lights(ContactKey contact) const = 0;
    // `done` gets an empty text once the device confirmed the position, else a sentence saying what failed.
    virtual void switchTo(std::int64_t accessory, int position, std::function<void(const QString&)> done) = 0;
};

// The railway as the UI sees it: locomotives, accessories, contacts, routes, track plan pages and
// devices, and the intents a person has (drive, switch, run a route, stop). Intents become station
// commands; the state changes only when the station confirms them or the bus shows a change, so that
// several controllers on one station stay consistent. Every received batch gives at most one change
// signal per kind, so that views keep up with a flood of frames.
class Railway final : public QObject {
    Q_OBJECT

public:
    // The part of a locomotive a command changes, so that a throttle can mark the control it came from.
    enum class LocomotiveControl : std::uint8_t { Speed, Direction, Function, EmergencyStop };
    Q_ENUM(LocomotiveControl)

    // Create it before the start-up runs to keep the state answers the start-up asks for, then load().
    // The session must outlive the railway.
    explicit Railway(station::StationSession& session, QObject* parent = nullptr);
    Railway(station::StationSession& session, const station::StartupResult& startup,
            QObject* parent = nullptr);
    ~Railway() override;

    // Takes the layout from the start-up's files and starts polling the devices' readings.
    void load(const station::StartupResult& startup);

    const RailwayState& state() const { return state_; }
    const Locomotive* locomotive(std::uint32_t id) const { return state_.locomotives().find(id); }
    const Accessory* accessory(std::int64_t id) const { return state_.accessories().find(id); }
    const FeedbackContact* contact(ContactKey key) const { return state_.contacts().find(key); }
    // Which locomotive (Loc-ID; 0: nobody) is on a contact, as the simulator or the user says: the station
    // cannot report it. Forgotten when the contact is reported free. Announced as contactsChanged.
    void reportOccupant(ContactKey key, std::uint32_t locId);
    // The locomotive on an occupied contact, where someone said which it is and the station knows it.
    const Locomotive* locomotiveOn(const FeedbackContact& contact) const {
        return contact.occupied() ? locomotive(contact.occupant()) : nullptr;
    }
    const Route* route(std::int64_t id) const { return state_.routes().find(id); }
    // True when every accessory of the route stands where the route leaves it, as the station confirmed.
    bool isRouteSet(std::int64_t id) const;
    const Device* device(std::uint32_t uid) const { return state_.devices().find(uid); }
    // The position the bus last showed for an MM2 keyboard number without an article.
    std::optional<int> addressPosition(std::int64_t address) const { return state_.addressPosition(address); }
    const TrackLayout& layout() const { return state_.layout(); }
    // Unknown until the station reported its power state, and again while the state is not reported.
    std::optional<station::PowerState> power() const { return state_.power(); }
    // True while what the railway holds is what the station reports: false before the first start-up
    // finished, and from the moment the station falls silent or the connection is lost (or the transport
    // is not connected) until a start-up has read the state again (load() while the station is heard).
    // While false, power() is unknown and the locomotives, accessories and contacts hold the last state
    // reported, which views show as "not reported".
    //
    // Per item, whether a value was reported since the state was last lost:
    // Locomotive::isSpeedReported / isDirectionReported / isFunctionReported, Accessory::isPositionReported,
    // FeedbackContact::known. On loss every item becomes "not reported" at once (stateReportedChanged(false),
    // then one locomotivesChanged, accessoriesChanged, contactsChanged and tilesChanged naming all of them);
    // the start-up's state queries make locomotives and contacts reported again one by one (with the usual
    // change signals), and an item whose query failed stays "not reported" after load(). The CS2 has no
    // query for track power or accessory positions: they stay unknown until the station reports them (a
    // change, or an announcement on connect). Route runs are cancelled, and commands that were waiting for
    // an answer fail at once (locomotiveCommandFailed, problem) and are never sent later.
    bool isStateReported() const { return stateReported_; }
    ReadingPoller& readings() { return *poller_; }
    // The one way every throttle that is not the desk (MS1, OpenRailCAN, Z21, WiThrottle) drives this
    // railway, with the book of who drives which locomotive.
    ThrottlePort& throttlePort() { return *throttlePort_; }
    const ThrottlePort& throttlePort() const { return *throttlePort_; }
    // Decoder programming on this station: mfx discovery, bind, verify, CV read and write.
    Programmer& programmer() { return *programmer_; }
    // The block and memory function states announced on the bus (CS2 chapter 9), and ours to announce.
    BlockStates& blockStates() { return *blockStates_; }
    const BlockStates& blockStates() const { return *blockStates_; }
    // lokomotive.cs2 as loaded (or last replaced); null when the station sent none.
    const cs2config::LocomotiveFile* locomotiveFile() const { return state_.locomotiveFile(); }
    // An edited lokomotive.cs2 (see cs2config::LocomotiveEditor): the locomotives follow it, and every view
    // reloads (loaded()). The station itself is not changed.
    void replaceLocomotiveFile(const cs2config::LocomotiveFile& file);

    // Intents, in railway words. Each reports a problem signal when the station does not carry it out.
    void setSpeed(std::uint32_t loco, int speed); // 0..1000
    void setDirection(std::uint32_t loco, cs2::Direction direction);
    void reverse(std::uint32_t loco);
    void setFunction(std::uint32_t loco, int function, bool on);
    void toggleFunction(std::uint32_t loco, int function);
    void emergencyStop(std::uint32_t loco);
    void switchAccessory(std::int64_t accessory, int position);
    // Switches a keyboard number that no article uses, as an MM2 address: 0 red (round), 1 green (straight).
    void switchAddress(std::int64_t address, int position);
    // Writes a device's configuration channel; deviceConfigured reports how the device answered.
    void configureDevice(std::uint32_t uid, std::uint8_t channel, std::uint16_t value);
    // Starts a route; false (and a problem) when it is unknown, already running or cannot run.
    bool runRoute(std::int64_t route);
    void cancelRoute(std::int64_t route);
    void stop();
    void go();

    // After trouble. A command the station did not confirm (no answer after every retry, or cut off with
    // the connection) may still reach it: a station that stalled reads its copies when it wakes. So, as
    // soon as the station is heard again, every locomotive, accessory and the track power that had such a
    // command is brought back to what the station last confirmed (a locomotive without a confirmed speed
    // to 0), or, in the StopLocomotives aftermath, every locomotive that had one is stopped; a copy the
    // station carries out later is undone again (UnconfirmedCommands::WatchTime). Nothing is made faster,
    // started or switched on to bring it back. Each step is announced with stateCorrected.
    void setAftermath(Aftermath aftermath) { unconfirmed_.setAftermath(aftermath); }
    Aftermath aftermath() const { return unconfirmed_.aftermath(); }
    const UnconfirmedCommands& unconfirmedCommands() const { return unconfirmed_; }
    // "I don't trust what I see": brings back what waits to be brought back, sends every locomotive its
    // confirmed speed (or 0 in the StopLocomotives aftermath, or when none was confirmed) and reads every
    // state the station can report again (speeds, directions, functions, contacts); backInStep() follows.
    void bringBackInStep();
    bool isBringingBackInStep() const { return resync_ != nullptr; }

    // Accessories `switcher` drives go to it, not to the station (null: all go to the station). Not owned.
    void setDeviceAccessories(DeviceAccessories* switcher) { switcher_ = switcher; }
    // What a device reported: an accessory's position (nullopt: no longer reported, the device is offline)
    // and a contact (nullopt: not reported). Announced like the station's reports.
    void reportDevicePosition(std::int64_t accessory, std::optional<int> position);
    void reportDeviceContact(ContactKey key, std::optional<bool> occupied);

signals:
    void loaded();
    // isStateReported() changed.
    void stateReportedChanged(bool reported);
    void locomotivesChanged(const QList<quint32>& ids);
    void accessoriesChanged(const QList<qint64>& ids);
    // Keyboard numbers without an article whose position changed (see addressPosition).
    void addressesChanged(const QList<qint64>& addresses);
    // A switchAccessory or switchAddress ended: acknowledged by the station, or not (then also a problem).
    void switchingEnded(qint64 address, int position, bool acknowledged);
    // A configureDevice ended; on Accepted the value is read back and arrives with devicesChanged.
    void deviceConfigured(quint32 uid, quint8 channel, stellwerk::model::SettingResult result);
    void contactsChanged(const QList<quint32>& keys);
    // Tiles whose accessory or contact changed, for the track plan view.
    void tilesChanged(const QList<stellwerk::model::TileRef>& tiles);
    // New devices, and devices whose readings changed or went stale.
    void devicesChanged(const QList<quint32>& uids);
    void powerChanged(stellwerk::station::PowerState state);
    void overloaded(quint32 device, quint8 channel);
    // The station announced changed configuration files (a broadcast config stream): time to download again.
    void configurationChanged();
    void routeStarted(qint64 route);
    void routeProgressed(qint64 route, int stepsDone, int stepCount);
    void routeFinished(qint64 route);
    void routeFailed(qint64 route, const QString& message);
    // A command to a locomotive went out and waits for the station's acknowledgement. `function` is the
    // function number for LocomotiveControl::Function, else -1. Every sent command ends in exactly one
    // of locomotiveCommandAcknowledged or locomotiveCommandFailed.
    void locomotiveCommandSent(quint32 loco, stellwerk::model::Railway::LocomotiveControl control,
                               int function);
    void locomotiveCommandAcknowledged(quint32 loco, stellwerk::model::Railway::LocomotiveControl control,
                                       int function);
    // The station refused it, did not answer, or it could not be sent; `reason` says which, readably.
    void locomotiveCommandFailed(quint32 loco, stellwerk::model::Railway::LocomotiveControl control,
                                 int function, const QString& reason);
    // A readable sentence: a command the station rejected or did not answer, an overload, a failed route.
    void problem(const QString& message);
    // Something was brought back after a command the station did not confirm (see setAftermath).
    void stateCorrected(const stellwerk::model::Correction& correction);
    // bringBackInStep() has read the states again: how many questions were answered and how many not.
    void backInStep(int answered, int unanswered);

private:
    void apply(const station::StationUpdates& updates);
    // The station went silent or the connection was lost: what we hold may no longer be true.
    void contactLost();
    void setStateReported(bool reported);
    bool stationHeard() const;
    void announceAllUnreported();
    void announce(const RailwayChanges& changes);
    void announceTiles(const RailwayChanges& changes);
    void readingMissed(quint32 device, quint8 channel);
    void updatePollerSources();
    // Sends a command to one locomotive's control, announced with the locomotiveCommand signals; `what`
    // names it for the problem message, `done` runs after an acknowledgement.
    void locoCommand(std::uint32_t loco, LocomotiveControl control, int function, int value,
                     const cs2::Message& message, const QString& what, std::function<void()> done = {});
    void powerCommand(bool on, const cs2::Message& message, const QString& what);
    // The book of unconfirmed commands (RailwayCorrections.cpp).
    std::optional<int> reportedValue(CommandTarget target) const;
    void recordOutcome(CommandTarget target, int value, std::optional<int> confirmedAtSend,
                       const station::CommandResult& result);
    void checkReports(const RailwayChanges& changes);
    void checkReport(CommandTarget target);
    void answersHeard();
    void askFor(CommandTarget target);
    void correct(const Correction& correction);
    std::vector<cs2::Message> stateQueries() const;
    void switchForRoute(std::int64_t accessory, int position, std::function<void(const QString&)> done);
    void routeEnded(std::int64_t route);
    void sendSwitching(std::int64_t address, int position, const cs2::Message& command, const QString& what);
    void readSetting(std::uint32_t uid, std::uint8_t channel);
    QString locoName(std::uint32_t loco) const;

    station::StationSession& session_;
    RailwayState state_;
    ReadingPoller* poller_;
    Programmer* programmer_;
    BlockStates* blockStates_;
    ThrottlePort* throttlePort_;
    std::map<std::int64_t, RouteRunner*> runners_;
    DeviceAccessories* switcher_ = nullptr;
    bool stateReported_ = false;
    UnconfirmedCommands unconfirmed_;
    station::StateQueryRound* resync_ = nullptr;
};

} // namespace stellwerk::model
