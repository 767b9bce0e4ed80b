// M-CAN frames (the MS1 handhelds' protocol): a run of up to 64 13-byte network frames, as a CAN-to-UDP
// gateway passes a bus on (a short last frame is padded with zeros), read in order as one bus.
// Invariants: every well-formed frame decodes, with any handle role and with the roles learnt from the
// frames before it, to a message that encodes back to the same frame (encode(decode(f)) == f); the
// report's text and JSON are printable ASCII and the JSON is valid; the bus description of an M-CAN frame
// is that report with its protocol, and names a handheld only on a node pair; the roles and names learnt
// from any frame sequence stay bounded (4096 handles, 16 characters a name).
#include "FuzzSupport.h"
#include "busreading/BusContext.h"
#include "can/FrameText.h"
#include "mcan/Codec.h"
#include "mcan/FrameReport.h"
#include "mcan/HandleRoles.h"

#include <array>
#include <cstring>

using namespace stellwerk;

namespace {

constexpr std::size_t MaximumHandles = 4096; // mcan::HandleRoles' bound
constexpr std::size_t MaximumName = 16;      // four segments of four characters
constexpr std::size_t MaximumFrames = 64;    // longer runs add no coverage, only time

constexpr mcan::HandleRole Roles[] = {mcan::HandleRole::Unknown,      mcan::HandleRole::Start,
                                      mcan::HandleRole::Poll,         mcan::HandleRole::SlaveDescription,
                                      mcan::HandleRole::SystemStatus, mcan::HandleRole::Loco};

// The details of a broken invariant are written only when it breaks: a run checks thousands of frames.
void checkRoundTrip(const can::CanFrame& frame, const mcan::Message& message) {
    const can::CanFrame encoded = mcan::encode(message);
    if (encoded != frame)
        fuzz::fail("encode(decode(f)) differs from f", can::formatDocument(frame) + " (" +
                                                           std::string(mcan::nameOf(message)) + ") -> " +
                                                           can::formatDocument(encoded));
}

void checkReport(const fuzz::ReportStrings& report) {
    const std::string& text = report.text;
    const std::string& json = report.json;
    if (!fuzz::isPrintableAscii(text))
        fuzz::fail("FrameReport::text() is not printable ASCII", text);
    if (!fuzz::isPrintableAscii(json) || !fuzz::isJsonDocument(json, false))
        fuzz::fail("FrameReport::json() is not valid JSON in printable ASCII", json);
}

void checkBounded(const mcan::HandleRoles& roles, const can::CanFrame& frame) {
    if (roles.size() > MaximumHandles)
        fuzz::fail("HandleRoles grew beyond its bound", std::to_string(roles.size()));
    const mcan::SessionId s = mcan::readSession(frame.id);
    if (roles.name(s.node, s.handle).size() > MaximumName || roles.slaveName(s.node).size() > MaximumName)
        fuzz::fail("a name grew beyond 16 characters", can::formatDocument(frame));
}

// The context has learnt from the same frames as `roles`, so it reads an M-CAN frame as `report` does.
void checkDescription(busreading::BusContext& context, const can::CanFrame& frame,
                      const fuzz::ReportStrings& report) {
    const busreading::FrameDescription description =
        context.read(frame, busreading::BusProfile::centralStation());
    if (description.protocol() != busreading::Protocol::Mcan)
        return;
    if (description.text() != report.text ||
        description.json() != "{\"protocol\":\"mcan\"," + report.json.substr(1))
        fuzz::fail("the description of an M-CAN frame is not its report", description.json());
    const auto handheld = description.handheld();
    if (handheld && (handheld->node % 2 == 0 || handheld->node >= 126 || handheld->name.size() > MaximumName))
        fuzz::fail("a handheld outside the node pairs or with a long name", can::formatDocument(frame));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > MaximumFrames * can::CanFrame::NetworkSize)
        return -1;
    fuzz::FuzzInput input(data, size);
    mcan::HandleRoles roles;    // learns from the M-CAN frames, as a bus context does
    mcan::HandleRoles anyFrame; // learns from every frame, as nobody should feed it, and stays bounded too
    busreading::BusContext context;
    while (!input.empty()) {
        std::array<std::uint8_t, can::CanFrame::NetworkSize> bytes{}; // a short last frame: the rest is zero
        const auto part = input.take(bytes.size());
        std::memcpy(bytes.data(), part.data(), part.size());
        const can::CanFrame frame = can::CanFrame::fromNetwork(bytes);
        if (frame.isWellFormed()) {
            for (const mcan::HandleRole role : Roles)
                checkRoundTrip(frame, mcan::decode(frame, role));
            checkRoundTrip(frame, roles.decode(frame));
        }
        if (mcan::isMcan(frame))
            roles.observe(frame);
        anyFrame.observe(frame);
        const auto report = fuzz::ReportStrings::of(mcan::FrameReport(frame, &roles));
        checkReport(report);
        checkBounded(roles, frame);
        checkBounded(anyFrame, frame);
        checkDescription(context, frame, report);
    }
    return 0;
}
