#pragma once

#include "can/CanFrame.h"
#include "orc/Messages.h"

#include <QObject>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::sim {

// An OpenRailCAN device on the CAN bus (seed 001): a peer behind a transport, like SimulatedMs1. It answers
// Ping and Find (Find with Stellwerk's extension answer), takes a new bus id when the central assigns one
// (the extension), and forgets it when it is powered up again (it then asks for the low 16 bits of its UID
// once more, announcing itself with an unsolicited ping answer). The kinds below add what they do.
class SimulatedOrcDevice : public QObject {
    Q_OBJECT

public:
    SimulatedOrcDevice(std::uint32_t uid, orc::DeviceType type, QObject* parent = nullptr);

    // A frame from the bus (any sender); what the device answers goes out in one framesEmitted before this
    // returns.
    void receive(const can::CanFrame& frame);
    // Powered up (again): bus id = low 16 bits of the UID, and an unsolicited ping answer.
    void plugIn();
    // Powered off or pulled out: silent at once.
    void unplug();

    bool pluggedIn() const { return plugged_; }
    std::uint32_t uid() const { return uid_; }
    std::uint16_t busId() const { return busId_; }
    std::uint16_t version() const { return 0x0102; }

signals:
    void framesEmitted(const std::vector<stellwerk::can::CanFrame>& frames);

protected:
    // What this kind of device does with a message that is not system management.
    virtual void act(const orc::Message& message) = 0;
    // Queues a message from this device, sent at the end of receive() or at once outside it.
    void say(const orc::Message& message);
    orc::Origin origin() const;
    bool addressed(const orc::Target& target) const;

private:
    bool manage(const orc::Message& message);
    void flush();

    std::uint32_t uid_;
    orc::DeviceType type_;
    std::uint16_t busId_;
    bool plugged_ = false;
    bool receiving_ = false;
    std::vector<can::CanFrame> outbox_;
};

// A booster: its track output follows Alles EIN / Alles Aus, its loco commands (0x81) are kept and answered;
// an overload can be injected on a port and cleared.
class SimulatedOrcBooster final : public SimulatedOrcDevice {
    Q_OBJECT

public:
    explicit SimulatedOrcBooster(std::uint32_t uid, QObject* parent = nullptr);

    void injectOverload(std::uint8_t port, std::uint8_t kind = 1);
    void clearOverload(std::uint8_t port);
    bool powered() const { return powered_; }
    bool emergencyStopped() const { return stopped_; }
    std::uint16_t speed(std::uint16_t loco) const;

protected:
    void act(const orc::Message& message) override;

private:
    bool powered_ = false;
    bool stopped_ = false;
    std::map<std::uint16_t, std::uint16_t> speeds_;
};

// A CAN decoder with 8 outputs. Pos (decoder-specific in the document) is, for this decoder, the state of
// all 8 outputs, bit n = output n; it acknowledges a switch with D=1 unless told not to (the ack is
// optional in the document).
class SimulatedOrcDecoder final : public SimulatedOrcDevice {
    Q_OBJECT

public:
    explicit SimulatedOrcDecoder(std::uint32_t uid, bool acknowledges = true, QObject* parent = nullptr);

    std::uint8_t outputs() const { return outputs_; }
    bool enabled() const { return enabled_; }
    int switchCount() const { return switches_; }

signals:
    // A dekoder schalten it carried out: its outputs now.
    void switched(std::uint8_t outputs);

protected:
    void act(const orc::Message& message) override;

private:
    bool acknowledges_;
    bool enabled_ = true;
    std::uint8_t outputs_ = 0;
    int switches_ = 0;
};

// A CAN encoder with 32 inputs: a change is sent as an event (D=0), a query answered with D=1.
class SimulatedOrcEncoder final : public SimulatedOrcDevice {
    Q_OBJECT

public:
    explicit SimulatedOrcEncoder(std::uint32_t uid, QObject* parent = nullptr);

    void setInput(int input, bool on);
    std::uint32_t inputs() const { return inputs_; }

protected:
    void act(const orc::Message& message) override;

private:
    orc::EncoderStatus status(bool answer) const;

    std::uint32_t inputs_ = 0;
};

// A throttle (Fahrpult, device type 1): what its user does goes out as loco control (0x81) with D=0, and the
// answers to its queries (D=1, from whoever holds the loco's state, notes O24) are kept.
class SimulatedOrcThrottle final : public SimulatedOrcDevice {
    Q_OBJECT

public:
    explicit SimulatedOrcThrottle(std::uint32_t uid, QObject* parent = nullptr);

    // Speed 0..1000; `forward` false sets bit 15 (notes O13).
    void drive(std::uint16_t loco, std::uint16_t speed, bool forward = true);
    void setFunction(std::uint16_t loco, std::uint8_t function, bool on);
    void setFunctions(std::uint16_t loco, std::uint32_t functions);
    // Lok(s) Nothalt for one loco, or (nullopt) all.
    void emergencyStop(std::optional<std::uint16_t> loco = std::nullopt);
    void querySpeed(std::uint16_t loco);
    void queryFunctions(std::uint16_t loco);

    // The last answer for the loco, if one came.
    std::optional<std::uint16_t> answeredSpeed(std::uint16_t loco) const;
    std::optional<std::uint32_t> answeredFunctions(std::uint16_t loco) const;

protected:
    void act(const orc::Message& message) override;

private:
    std::map<std::uint16_t, std::uint16_t> speeds_;
    std::map<std::uint16_t, std::uint32_t> functions_;
};

} // namespace stellwerk::sim
