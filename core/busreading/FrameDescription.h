#pragma once

#include "busreading/FrameClassifier.h"
#include "busreading/Handheld.h"
#include "can/CanFrame.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::busreading {

class BusContext;

// What one protocol reads in a frame; each protocol of the bus has its own (CS2 and foreign frames in
// FrameDescription.cpp, M-CAN in McanReading.cpp).
class FrameReading {
public:
    virtual ~FrameReading() = default;

    virtual std::string_view name() const = 0;
    virtual bool decoded() const = 0;
    virtual bool isResponse() const = 0;
    // "key=value ..." of the fields, or why the frame did not decode.
    virtual std::string detailText() const = 0;
    // The whole line: frame, name and details, as `stellwerk-cli decode` prints it.
    virtual std::string text() const = 0;
    // One JSON object whose first key is "protocol".
    virtual std::string json() const = 0;
    // A numeric field by key ("locId", "contact", ...), when the frame has it.
    virtual std::optional<std::uint64_t> number(std::string_view key) const = 0;
    // The MS1 handheld the frame belongs to (M-CAN only).
    virtual std::optional<Handheld> handheld() const { return std::nullopt; }
};

// What a frame on a bus says, in terms every protocol shares: the protocol it belongs to, a name, fields
// and its text and JSON forms. The bus monitor, the frame decoder panel and `stellwerk-cli decode` show
// this and never call a codec themselves. Decodes once, when made; cheap to copy. With the context of its
// bus (what earlier frames revealed), an M-CAN frame names its handle's role and its handheld's name.
class FrameDescription {
public:
    FrameDescription(const can::CanFrame& frame, const BusProfile& profile,
                     const BusContext* context = nullptr);

    const can::CanFrame& frame() const { return frame_; }
    Protocol protocol() const { return protocol_; }
    // "cs2", "mcan", "ro", "foreign".
    std::string_view protocolName() const { return busreading::protocolName(protocol_); }
    // The message's name ("loco.speed"); a frame that did not decode has the name it would have had.
    std::string_view name() const { return reading_->name(); }
    bool decoded() const { return reading_->decoded(); }
    bool isResponse() const { return reading_->isResponse(); }
    // The frame in the protocol document's notation: "00084711 6 00 00 C0 03 01 20".
    std::string frameText() const;
    std::string detailText() const { return reading_->detailText(); }
    std::string text() const { return reading_->text(); }
    std::string json() const { return reading_->json(); }
    std::optional<std::uint64_t> number(std::string_view key) const { return reading_->number(key); }
    // The MS1 handheld an M-CAN frame belongs to (the slave node of its pair, and its name when the
    // context knew it); nullopt for other frames and for M-CAN frames of no pair (login, flash).
    std::optional<Handheld> handheld() const { return reading_->handheld(); }

private:
    can::CanFrame frame_;
    Protocol protocol_;
    std::shared_ptr<const FrameReading> reading_;
};

// Every message name the protocols of this profile know, for choosing one in a filter.
std::vector<std::string_view> messageNames(const BusProfile& profile);

// A locomotive as people type it into a filter: a Loc-ID ("0x4005", "16389") or a protocol and address
// ("mm2 5", "dcc 3", "mfx 12"); the Loc-ID that frames about it carry in their "locId" field.
std::optional<std::uint32_t> parseLocoReference(std::string_view text);

} // namespace stellwerk::busreading
