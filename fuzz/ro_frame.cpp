// RO relay/IO module frames (seed 004): a run of up to 64 records of 9 bytes, each a header byte (bit 0:
// sent on the answer id, bit 1: an 11-bit module, bits 4..7: the DLC, which may claim more than 8) and 8
// data bytes (a short last record is padded with zeros), read in order on a bus with one RO module.
// Invariants: a payload decodes as a request or answer, or is refused with a reason and a byte within
// the payload; whatever decodes encodes to a payload that decodes to the same message (decode(encode(m))
// == m), and a write or OK encodes back to the very bytes it came from when they were canonical; the
// frame's report and its bus description are printable text, the JSON valid, and the description is
// that report with its protocol and module.
#include "FuzzSupport.h"
#include "busreading/FrameDescription.h"
#include "can/FrameText.h"
#include "ro/Codec.h"
#include "ro/FrameReport.h"

#include <array>
#include <cstring>

using namespace stellwerk;

namespace {

constexpr std::size_t RecordSize = 9;
constexpr std::size_t MaximumRecords = 64;
constexpr ro::FrameIds Extended{0x01FE0001, 0x01FF0001, true};
constexpr ro::FrameIds Standard{0x700, 0x701, false};

std::string hexOf(std::span<const std::uint8_t> bytes) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string text;
    for (const std::uint8_t byte : bytes)
        text += std::string{digits[byte >> 4], digits[byte & 15], ' '};
    return text;
}

void checkRefusal(const ro::DecodeError& error, std::span<const std::uint8_t> payload) {
    if (error.reason.empty() || error.byte > payload.size() + 1)
        fuzz::fail("a refusal without a reason or naming a byte past the payload", hexOf(payload));
}

void checkRequest(std::span<const std::uint8_t> payload) {
    const auto request = ro::decodeRequest(payload);
    if (!request)
        return checkRefusal(request.error(), payload);
    for (const auto size : {ro::ReadRequestSize::Eight, ro::ReadRequestSize::Four}) {
        const ro::Payload encoded = ro::encode(*request, size);
        const auto again = ro::decodeRequest(encoded.span());
        if (!again || !(*again == *request))
            fuzz::fail("decode(encode(request)) differs from the request", hexOf(payload));
    }
    // A write of 8 bytes is canonical: it comes back byte for byte.
    if (request->isWrite() && payload.size() == 8 &&
        !(ro::encode(*request).span().size() == 8 &&
          std::equal(payload.begin(), payload.end(), ro::encode(*request).bytes.begin())))
        fuzz::fail("encode(decode(write)) differs from the write", hexOf(payload));
}

void checkAnswer(std::span<const std::uint8_t> payload) {
    const auto answer = ro::decodeAnswer(payload);
    if (!answer)
        return checkRefusal(answer.error(), payload);
    const ro::Payload encoded = ro::encode(*answer);
    const auto again = ro::decodeAnswer(encoded.span());
    if (!again || !(*again == *answer))
        fuzz::fail("decode(encode(answer)) differs from the answer", hexOf(payload));
    if (std::holds_alternative<ro::OkAnswer>(*answer) && payload.size() == 7 &&
        !std::equal(payload.begin(), payload.end(), encoded.bytes.begin()))
        fuzz::fail("encode(decode(OK)) of 7 bytes differs from the OK", hexOf(payload));
}

void checkReport(const can::CanFrame& frame, ro::Direction direction, const busreading::BusProfile& profile) {
    const auto report = fuzz::ReportStrings::of(ro::FrameReport(frame, direction));
    const busreading::FrameDescription description(frame, profile);
    if (!fuzz::isPrintableText(report.text) || !fuzz::isJsonDocument(report.json, false))
        fuzz::fail("the report is not printable text and valid JSON", report.json);
    if (description.protocol() != busreading::Protocol::Ro || description.text() != report.text ||
        description.json() != "{\"protocol\":\"ro\",\"module\":" + std::string(frame.extended ? "0" : "1") +
                                  "," + report.json.substr(1))
        fuzz::fail("the description of an RO frame is not its report", description.json());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > MaximumRecords * RecordSize)
        return -1;
    busreading::BusProfile profile = busreading::BusProfile::centralStation();
    profile.addRoModule(Extended).addRoModule(Standard);
    fuzz::FuzzInput input(data, size);
    while (!input.empty()) {
        const std::uint8_t header = input.byte();
        std::array<std::uint8_t, 8> bytes{};
        const auto part = input.take(bytes.size());
        std::memcpy(bytes.data(), part.data(), part.size());
        const ro::FrameIds& ids = (header & 2) ? Standard : Extended;
        const bool answer = header & 1;
        can::CanFrame frame =
            ro::frameOf(answer ? ids.answer : ids.request, ids.extended, ro::Payload{bytes, 8});
        frame.dlc = std::uint8_t(header >> 4);
        answer ? checkAnswer(frame.payload()) : checkRequest(frame.payload());
        checkReport(frame, answer ? ro::Direction::Answer : ro::Direction::Request, profile);
    }
    return 0;
}
