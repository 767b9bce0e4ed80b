#pragma once

#include "can/CanFrame.h"
#include "mcan/Codec.h"
#include "mcanhandhelds/Handheld.h"
#include "mcanhandhelds/HandheldBook.h"
#include "mcanhandhelds/HandheldEvent.h"
#include "mcanhandhelds/HandheldRailway.h"
#include "mcanhandhelds/HandheldWatcher.h"
#include "mcanhandhelds/LoginDesk.h"
#include "mcanhandhelds/SlaveSession.h"

#include <QObject>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace stellwerk::mcanhandhelds {

// How the master behaves; the defaults are the documents' (notes B§5.2) and the ECoS's.
struct MasterSettings {
    std::uint32_t uid = 0x53574D31; // Stellwerk's UID in the stage-0 reply
    std::uint8_t nodeBase = 42;     // the first master node (ECoS, CS1 from 2.0.4); 2 for older CS1
    bool exclusive = true;          // a locomotive one handheld drives is refused to the others
    std::chrono::milliseconds silentAfter{7500}; // no poll for this long: the master starts polling
    std::chrono::milliseconds masterPollEvery{1000};
    int masterPolls = 30; // unanswered master polls before the handheld is dropped
    std::chrono::milliseconds loginStageTimeout{2000};
    std::chrono::milliseconds tick{100};
};

// Why Stellwerk only watches the handhelds instead of answering them.
enum class Watching : std::uint8_t {
    No,                // it is their master
    UntilDevicesKnown, // it waits for the start-up to list the devices on the bus
    CentralStation,    // a Central Station is on the bus: it is the handhelds' master itself
    AnotherMaster,     // another master answered on the bus
    Asked,             // a person chose to watch only
};

// What the master has seen since it started, for the monitor, the panel and tests.
struct MasterCounters {
    std::uint64_t framesIn = 0;   // M-CAN frames received
    std::uint64_t answers = 0;    // frames the master sent
    std::uint64_t unexpected = 0; // frames it did not answer: an unknown node, a stage out of order, a handle
                                  // nobody issued, a frame the documents do not explain
    std::uint64_t refused = 0;    // drive requests for a locomotive another handheld holds
};

// Stellwerk as the M-CAN master of the MS1 handhelds on one bus (notes B§3, B§5.1 4): the logins of up to 31
// handhelds at once, each handheld's upgrade answered in the order it asks, their polls, the master's polls
// of a silent handheld, one owner per locomotive, names, stacks remembered by UID, and stop/go both ways.
// What a handheld does drives the railway (HandheldRailway); what changes on the railway reaches every
// handheld that shows it. It never sets the boot-loader bit of a login grant. When another master answers on
// the bus (a CS2, CS1, ECoS or an MS1 master), it falls silent at once and only watches (HandheldWatcher).
class HandheldMaster final : public QObject, private SessionHost {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(HandheldMaster)

public:
    using Send = std::function<void(const std::vector<can::CanFrame>&)>;
    using Clock = std::chrono::steady_clock;

    HandheldMaster(Send send, MasterSettings settings = {}, QObject* parent = nullptr);
    ~HandheldMaster() override;

    // The railway the handhelds drive (not owned; null: none yet, every locomotive unknown).
    void setRailway(HandheldRailway* railway);
    // Where handhelds are remembered (not owned; null: nowhere).
    void setBook(HandheldBook* book);
    // Frames from the bus, in order; anything that is not M-CAN is ignored.
    void receive(const std::vector<can::CanFrame>& frames);

    // Whether Stellwerk answers the handhelds: false once another master spoke, or when told not to.
    bool isMaster() const { return active_ && !otherMaster_; }
    void setActive(bool active);
    // Stops answering at once and only watches, for the reason given.
    void standDown(Watching why);
    // Why it only watches (No while it is the master).
    Watching watching() const;
    // The node of the other master that answered, when that is why it watches.
    std::uint8_t otherMasterNode() const { return otherMasterNode_; }

    // Every handheld known on the bus: those logged in here, those watched at another master, and those
    // that went offline or sit in their boot loader.
    std::vector<Handheld> handhelds() const;
    const MasterCounters& counters() const { return counters_; }

    // People's changes: a handheld's locomotive stack, its name. Remembered, and told to it when it is on.
    void setStack(std::uint32_t uid, const std::vector<std::uint32_t>& stack);
    void rename(std::uint32_t uid, const QString& name);
    // Sends the abort of document 9.6 to a handheld in its boot loader: it stops sending (it stays there).
    void silenceBootLoader(std::uint32_t uid);

    // The railway's changes, told by whoever implements HandheldRailway.
    void locoChanged(std::uint32_t locId);
    void powerChanged();
    // The railway reports a short circuit (an overload): every handheld shows it until the power is on again.
    void shortCircuitReported();
    void locomotivesChanged();

signals:
    void handheldsChanged();
    void event(const stellwerk::mcanhandhelds::HandheldEvent& event);
    // isMaster() changed.
    void masterChanged(bool master);

private:
    struct Live {
        std::unique_ptr<SlaveSession> session;
        Clock::time_point lastHeard;
        Clock::time_point nextPoll;
    };

    // SessionHost
    const HandheldLoco* loco(std::uint32_t locId) const override;
    LocoDrive drive(std::uint32_t locId) const override;
    bool stopped() const override;
    bool shortCircuit() const override { return shortCircuit_; }
    bool take(SlaveSession& session, std::uint32_t locId) override;
    void release(SlaveSession& session, std::uint32_t locId) override;
    bool heldByOther(const SlaveSession& session, std::uint32_t locId) const override;
    void drive(SlaveSession& session, std::uint32_t locId, std::uint8_t function,
               std::uint8_t value) override;
    void stopKey(SlaveSession& session, bool stop) override;
    void changed(SlaveSession& session) override;

    void receiveOne(const can::CanFrame& frame, Clock::time_point now);
    void receiveLogin(const mcan::Message& message, const can::CanFrame& frame, Clock::time_point now);
    void receiveSession(const mcan::Message& message, const can::CanFrame& frame, Clock::time_point now);
    void receiveFlash(const mcan::Message& message);
    void completeLogin(const CompletedLogin& login);
    mcan::HandleRole roleOf(const can::CanFrame& frame) const;
    bool isEcho(const can::CanFrame& frame);
    bool spokeAsMaster(const mcan::Message& message, const can::CanFrame& frame) const;
    void otherMasterSpoke(const can::CanFrame& frame);
    void endSessions();
    void send(const std::vector<mcan::Message>& messages);
    void sendAfterAnswer(const std::vector<mcan::Message>& messages);
    void tick();
    void checkLiveness(Live& live, Clock::time_point now);
    void drop(std::uint8_t slaveNode);
    std::uint8_t freeSlaveNode(std::uint32_t uid) const;
    SlaveSession* sessionOf(std::uint32_t uid);
    void remember(const Handheld& handheld);
    void tell(HandheldEvent event);
    void driveRailway(SlaveSession& session, std::uint32_t locId, std::uint8_t function, std::uint8_t value);
    std::vector<std::uint32_t> firstLocos(std::size_t count) const;

    Send send_;
    MasterSettings settings_;
    HandheldRailway* railway_ = nullptr;
    HandheldBook* book_ = nullptr;
    LoginDesk logins_;
    HandheldWatcher watcher_;
    std::map<std::uint8_t, Live> sessions_;          // by slave node
    std::map<std::uint32_t, Handheld> offline_;      // by UID: dropped, or in the boot loader
    std::map<std::uint32_t, std::uint32_t> holders_; // Loc-ID -> UID of the handheld that drives it
    std::vector<HandheldLoco> locos_;                // the railway's, as the handhelds show them
    std::vector<mcan::Message> afterAnswer_;         // told to others once a handheld's request is answered
    std::deque<std::pair<can::CanFrame, Clock::time_point>> sent_; // our own frames, to know their echoes
    bool active_ = true;
    bool otherMaster_ = false;
    bool shortCircuit_ = false;   // reported since the power was last on
    Watching why_ = Watching::No; // why it is not active (when active_ is false)
    std::uint8_t otherMasterNode_ = 0;
    MasterCounters counters_;
    QTimer ticker_;
};

} // namespace stellwerk::mcanhandhelds
