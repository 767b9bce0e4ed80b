#pragma once

#include "model/FeedbackContact.h"

#include <QString>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

class QSettings;

namespace stellwerk::model {

// An OpenRailCAN decoder output: the decoder's Ziel-Id (a CAN decoder's bus id, or a legacy id such as
// 0x3005) and, for a decoder whose Pos is the state of its outputs (bit n = output n, as the simulated
// 8-output decoder reads it), the output. Without an output, Pos is the accessory's position itself (MM/DCC
// turnouts: 0 round/red, 1 straight/green).
struct OrcOutput {
    std::uint16_t target = 0;
    std::optional<std::uint8_t> output; // 0..7
    friend bool operator==(const OrcOutput&, const OrcOutput&) = default;
};

// An RO module's relay, numbered from 1 (004 §3.4); relay on = position 1 (straight/green).
struct RoRelay {
    QString module; // the module profile's name
    int relay = 1;
    friend bool operator==(const RoRelay&, const RoRelay&) = default;
};

// An OpenRailCAN encoder input: the encoder's UID (its bus id is given by the central) and the input,
// numbered from 0 as the document's bits are.
struct OrcInput {
    std::uint32_t encoderUid = 0;
    int input = 0;
    friend bool operator==(const OrcInput&, const OrcInput&) = default;
};

// An RO module's input, numbered from 1 like its relays.
struct RoInput {
    QString module;
    int input = 1;
    friend bool operator==(const RoInput&, const RoInput&) = default;
};

// A keyboard article (magnetartikel.cs2 number) switched by a device instead of the CS2.
struct AccessoryBinding {
    std::int64_t accessory = 0;
    std::variant<OrcOutput, RoRelay> output;
    friend bool operator==(const AccessoryBinding&, const AccessoryBinding&) = default;
};

// A feedback contact lit by a device input instead of an S88 module.
struct ContactBinding {
    ContactKey contact = 0;
    std::variant<OrcInput, RoInput> input;
    friend bool operator==(const ContactBinding&, const ContactBinding&) = default;
};

// Which accessories and contacts of the layout are the devices' (OpenRailCAN decoders and encoders, RO
// relays and inputs), saved with the station settings. Typed, so that no key string leaves
// DeviceBindings.cpp.
struct DeviceBindings {
    std::vector<AccessoryBinding> accessories;
    std::vector<ContactBinding> contacts;

    const AccessoryBinding* accessory(std::int64_t id) const;
    const ContactBinding* contact(ContactKey key) const;

    // The demo layout's (resources/demo-layout) on the embedded station's devices: turnout W1 Einfahrt West
    // (1) on relay 1 of "Demo RO", signal A Einfahrsignal (6) on output 0 of the OpenRailCAN decoder with
    // bus id 0x0101 (UID 0x3A2E0101), the siding's contact (Abstellgleis, 0/9) on input 0 of the encoder
    // with UID 0x3A2E0102 (its occupancy detector: lit while a train stands there), and contact 0/20,
    // which the plan does not show, on input 1 of "Demo RO".
    static DeviceBindings demo();

    // Read from and written to the group "deviceBindings" of `settings`; entries that cannot be read are
    // left out.
    static DeviceBindings load(QSettings& settings);
    void save(QSettings& settings) const;
};

} // namespace stellwerk::model
