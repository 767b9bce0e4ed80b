// OpenRailCAN frames: a run of up to 64 13-byte network frames, as a CAN-to-UDP gateway passes a bus on (a
// short last frame is padded with zeros), read in order.
// Invariants: every well-formed 29-bit frame decodes to a message that encodes back to the same frame
// (encode(decode(f)) == f), and a decoded message encodes to a frame that decodes to the same message
// (decode(encode(m)) == m); a message sent with the default priority gets one of 01..11, never 00; the
// report's text and JSON are printable ASCII and the JSON is valid; the bus description of an ORC frame on
// an ORC bus is that report with its protocol, and a frame the ORC codec decodes is never foreign there.
#include "FuzzSupport.h"
#include "busreading/FrameDescription.h"
#include "can/FrameText.h"
#include "orc/Codec.h"
#include "orc/FrameReport.h"

#include <array>
#include <cstring>

using namespace stellwerk;

namespace {

constexpr std::size_t MaximumFrames = 64; // longer runs add no coverage, only time

// The details of a broken invariant are written only when it breaks: a run checks thousands of frames.
void checkRoundTrip(const can::CanFrame& frame, const orc::Message& message) {
    const can::CanFrame encoded = orc::encode(message);
    if (encoded != frame)
        fuzz::fail("encode(decode(f)) differs from f", can::formatDocument(frame) + " (" +
                                                           std::string(orc::nameOf(message)) + ") -> " +
                                                           can::formatDocument(encoded));
    if (!(orc::decode(encoded) == message))
        fuzz::fail("decode(encode(m)) differs from m", can::formatDocument(frame));
}

void checkDefaultPriority(const orc::Message& message) {
    if (std::holds_alternative<orc::Unknown>(message))
        return;
    const std::uint8_t prio = orc::defaultPriority(message);
    if (prio < 1 || prio > 3)
        fuzz::fail("a default priority outside 01..11", std::string(orc::nameOf(message)));
}

void checkReport(const fuzz::ReportStrings& report) {
    const std::string& text = report.text;
    const std::string& json = report.json;
    if (!fuzz::isPrintableAscii(text))
        fuzz::fail("FrameReport::text() is not printable ASCII", text);
    if (!fuzz::isPrintableAscii(json) || !fuzz::isJsonDocument(json, false))
        fuzz::fail("FrameReport::json() is not valid JSON in printable ASCII", json);
}

void checkDescription(const can::CanFrame& frame, bool decoded, const fuzz::ReportStrings& report) {
    const busreading::FrameDescription description(frame, busreading::BusProfile::openRailCan());
    if (decoded && description.protocol() != busreading::Protocol::Orc)
        fuzz::fail("a frame the ORC codec decodes is not ORC on an ORC bus", can::formatDocument(frame));
    if (description.protocol() != busreading::Protocol::Orc)
        return;
    if (description.text() != report.text ||
        description.json() != "{\"protocol\":\"orc\"," + report.json.substr(1))
        fuzz::fail("the description of an ORC frame is not its report", description.json());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > MaximumFrames * can::CanFrame::NetworkSize)
        return -1;
    fuzz::FuzzInput input(data, size);
    while (!input.empty()) {
        std::array<std::uint8_t, can::CanFrame::NetworkSize> bytes{}; // a short last frame: the rest is zero
        const auto part = input.take(bytes.size());
        std::memcpy(bytes.data(), part.data(), part.size());
        const can::CanFrame frame = can::CanFrame::fromNetwork(bytes);
        const orc::Message message = orc::decode(frame);
        if (frame.isWellFormed())
            checkRoundTrip(frame, message);
        checkDefaultPriority(message);
        const orc::FrameReport report(frame);
        const auto strings = fuzz::ReportStrings::of(report);
        checkReport(strings);
        checkDescription(frame, report.decoded(), strings);
    }
    return 0;
}
