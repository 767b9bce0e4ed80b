#pragma once

#include "can/CanFrame.h"
#include "sim/Ms1Memory.h"

#include <QObject>
#include <chrono>
#include <memory>
#include <vector>

namespace stellwerk::sim {

// A Mobile Station 1 handheld on the CAN bus, the slave side of M-CAN: it logs in to whatever master is on
// the bus, runs the upgrade, polls, and drives a locomotive of its stack, exactly as the chapter-11 trace's
// MS1 does (notes B§3, trace #3-#99). Like SimulatedStation it is a peer behind a transport: every frame on
// the bus comes in through receive(), its own go out through framesEmitted. Tests, stellwerk-sim and the
// demo press its keys; it never starts or takes part in a firmware flash.
class SimulatedMs1 : public QObject {
    Q_OBJECT

public:
    // Settable so that tests run fast; the defaults are the documents' (notes B§5.2).
    struct Timing {
        std::chrono::milliseconds pollPeriod{250};  // cyclic poll; also the unit of the master's silence
        std::chrono::milliseconds loginRetry{5000}; // after a lost login stage, or a stage nobody answers
        int pollsWithoutAnswer = 30;                // then "KEIN MASTER" and a new login
        int pollsBeforeTake = 5;                    // after a restart: take the first entry (trace #92)
        std::chrono::milliseconds driveEvery{4000}; // the "now and then" of drivesNowAndThen
    };
    struct Options {
        Ms1Identity identity;
        Timing timing;
        // Once it has a locomotive, change its speed (0..60) every driveEvery and now and then switch f0.
        bool drivesNowAndThen = false;
    };
    enum class Phase : std::uint8_t {
        Unplugged, // silent; plugIn() starts it
        LoggingIn, // login stages 0-7, or waiting to try again
        Upgrading, // logged in, asking its questions
        Online,    // polling; may drive
        FlashMode, // told to flash at the login: said so on node 127 and waits for a flasher
    };
    enum class Direction : std::uint8_t { Forward, Reverse };

    explicit SimulatedMs1(QObject* parent = nullptr); // the trace's MS1, the documents' timing
    explicit SimulatedMs1(Options options, QObject* parent = nullptr);
    ~SimulatedMs1() override;

    // A frame from the bus (any sender). What the MS1 answers goes out in one framesEmitted before this
    // returns.
    void receive(const can::CanFrame& frame);

    // Plugged in (again): a new login from stage 0; what the last session taught is forgotten.
    void plugIn();
    // Pulled out: silent at once.
    void unplug();

    // The keys; false (and no frame) while the MS1 is not online or could not do it (see Ms1Keys).
    bool takeLoco(int stackIndex);
    bool setSpeed(int speed, Direction direction);
    bool setFunction(int function, bool on);
    bool pressStop();
    bool pressGo();

    Phase phase() const;
    const Ms1Identity& identity() const;
    // What it has learnt in this session: link (node, handles), stack, shown locomotive, control, status.
    const Ms1Memory& memory() const;
    const Ms1Loco* shownLoco() const { return memory().shownLoco(); }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);
    void loggedIn(int node);
    void upgradeDone();
    void locoTaken(int stackIndex);
    void locoRefused(int stackIndex);
    void masterLost();
    void flashModeEntered();
    // Something it shows changed: stop/go, short circuit, speed, functions, stack, names.
    void displayChanged();

private:
    class Private;
    void flush(Ms1Outbox& out);
    void announce(Ms1Outbox::Event event, int value);

    std::unique_ptr<Private> d_;
};

} // namespace stellwerk::sim
