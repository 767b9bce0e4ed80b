// Status-data configuration packets (command 0x1D, document 6.2) as a device on the bus sends them:
// n x 13 network bytes; the 8-byte packets are joined by packet number and read as the device summary
// (index 0), a reading channel and a config channel, as StatusDataReader does.
// Invariant: every text read from a device is printable UTF-8 (no terminal escapes reach the CLI or the
// UI) and the article number is printable ASCII.
#include "FuzzSupport.h"
#include "cs2/Codec.h"
#include "station/DeviceDescription.h"
#include "station/StatusDataPackets.h"
#include "transport/NetworkFraming.h"

#include <vector>

using namespace stellwerk;
using namespace stellwerk::station;

namespace {

void checkText(const std::string& text, const char* what) {
    fuzz::check(fuzz::isPrintableText(text), what, text);
}

void checkSummary(const DeviceSummary& summary) {
    for (char c : summary.article)
        fuzz::check(c > 0x20 && c < 0x7F, "the article number is not printable ASCII", summary.article);
    checkText(summary.name, "a device name is not printable text");
    checkText(summary.nickname, "a device nickname is not printable text");
}

void checkReading(const ReadingChannel& reading) {
    for (const std::string* text : {&reading.name, &reading.startLabel, &reading.endLabel, &reading.unit})
        checkText(*text, "a reading channel's text is not printable");
    reading.scaled(0);
    reading.scaled(0xFFFF);
}

void checkConfig(const ConfigChannel& config) {
    for (const std::string* text : {&config.title, &config.startLabel, &config.endLabel, &config.unit})
        checkText(*text, "a config channel's text is not printable");
    for (const std::string& option : config.options)
        checkText(option, "a config channel's option is not printable");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 13)
        return -1;
    std::vector<can::CanFrame> frames;
    transport::decodeDatagram({data, size / 13 * 13}, frames);
    StatusDataPackets packets;
    for (const can::CanFrame& frame : frames) {
        const auto message = cs2::decode(frame);
        if (!message)
            continue;
        if (const auto* status = std::get_if<cs2::StatusDataConfig>(&message->body))
            if (status->form == cs2::StatusDataConfig::Form::Packet)
                packets.add(cs2::hash(frame), status->packet);
    }
    const std::vector<std::uint8_t> bytes = packets.assemble();
    fuzz::check(bytes.size() <= frames.size() * 8, "more bytes assembled than packets carried");
    if (const auto summary = parseDeviceSummary(bytes))
        checkSummary(*summary);
    if (const auto reading = parseReadingChannel(1, bytes))
        checkReading(*reading);
    if (const auto config = parseConfigChannel(2, bytes))
        checkConfig(*config);
    return 0;
}
