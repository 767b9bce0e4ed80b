#pragma once

#include "can/CanFrame.h"
#include "orc/Messages.h"
#include "orccentral/DeviceRegistry.h"

#include <QObject>
#include <QTimer>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace stellwerk::bus {
class Bus;
}

namespace stellwerk::orccentral {

// Stellwerk as the OpenRailCAN central (001 §Bus ID Vergabe; notes A3): it finds the devices on its bus,
// gives them bus ids (Stellwerk's extension for duplicates), pings them, switches decoder outputs, queries
// and receives encoder inputs, sends and mirrors power and emergency stop, and reports booster overloads.
// It reads the ORC frames its bus hands it (never CS2, M-CAN or foreign ones) and sends through the bus's
// transport; what the document leaves open (timeouts, retries, ping period) is in its Settings.
class OrcSession final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(OrcSession)

public:
    // The document gives no timeouts; Stellwerk's choices (notes A3.2, A3.3), settable for tests.
    struct Timing {
        std::chrono::milliseconds pingPeriod{5000};
        int missedPingsOffline = 3;
        std::chrono::milliseconds answerTimeout{250}; // queries, the assignment, the decoder's optional ack
        int queryRetries = 2;
        int assignTries = 3;
    };
    struct Settings {
        std::uint16_t busId = 0x0000;              // the central's own (MM loco 0 does not exist)
        std::uint32_t uid = 0;                     // the central's own, unused on the wire so far
        std::vector<std::uint16_t> reservedBusIds; // legacy devices of the layout
        Timing timing;
    };
    enum class SwitchResult : std::uint8_t { Confirmed, SentUnconfirmed };

    OrcSession(bus::Bus& bus, Settings settings, QObject* parent = nullptr);
    ~OrcSession() override;

    // Looks for devices (Find to every unregistered device, Ping to every known one) and starts the pings.
    void start();
    void find();
    // dekoder schalten: Pos to the decoder Ziel-Id (a CAN decoder's bus id or a legacy id such as 0x3005).
    void switchOutputs(std::uint16_t target, std::uint8_t position);
    // enkoder Abfrage of one encoder; its answer arrives as inputsChanged, or queryFailed after the retries.
    void queryEncoder(std::uint16_t encoder);
    // Alles EIN / Alles Aus to every device.
    void setPower(bool on);
    // Lok(s) Nothalt to every booster.
    void emergencyStop();

    const std::vector<OrcDevice>& devices() const { return registry_.devices(); }
    const OrcDevice* device(std::uint32_t uid) const;
    const OrcDevice* deviceAt(std::uint16_t busId) const;
    bool powerOn() const { return powerOn_; }
    // The bus it is the central of, and its own bus id there (for the ThrottleBridge beside it).
    bus::Bus& bus() const { return bus_; }
    std::uint16_t busId() const { return settings_.busId; }
    // ORC frames no documented form fits (orc.unknown), read and ignored.
    std::uint64_t unreadableFrames() const { return unreadable_; }

signals:
    void deviceChanged(std::uint32_t uid);
    void inputsChanged(std::uint16_t encoder, std::uint32_t inputs, std::uint32_t changed);
    void queryFailed(std::uint16_t encoder);
    void switchReported(std::uint16_t target, std::uint8_t position, SwitchResult result);
    // Power as the bus last said it: by this central (`byOther` false) or another device.
    void powerChanged(bool on, bool byOther);
    void emergencyStopped(bool byOther);
    // Booster overload (kind 0 = cleared); port 0xFF = the device as a whole.
    void overloadChanged(std::uint16_t busId, std::uint8_t port, std::uint8_t kind);

private:
    void receive(const std::vector<can::CanFrame>& frames);
    void handle(const orc::Message& message);
    void announced(const orc::Origin& from, std::uint32_t uid, std::uint16_t version);
    void assigned(const orc::AssignBusId& answer);
    void encoderStatus(const orc::EncoderStatus& status);
    void decoderAck(const orc::DecoderSwitch& ack);
    void overload(const orc::Overload& report);
    void tick();
    void assignTimedOut(std::uint32_t uid);
    void queryTimedOut(std::uint16_t encoder);
    void switchTimedOut(std::uint16_t target);
    void goesOnline(OrcDevice& device);
    void send(const orc::Message& message);
    orc::Origin me() const;
    QTimer* startTimer(std::function<void()> expired);

    bus::Bus& bus_;
    Settings settings_;
    DeviceRegistry registry_;
    QTimer pingClock_;
    std::map<std::uint32_t, std::unique_ptr<QTimer>> assignTimers_;
    std::map<std::uint32_t, int> assignTries_;
    std::map<std::uint16_t, std::unique_ptr<QTimer>> queryTimers_;
    std::map<std::uint16_t, int> queryTries_;
    std::map<std::uint16_t, std::pair<std::uint8_t, std::unique_ptr<QTimer>>> switches_;
    bool powerOn_ = false;
    std::uint64_t unreadable_ = 0;
};

} // namespace stellwerk::orccentral
