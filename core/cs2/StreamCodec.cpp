// GUI information transfer (document chapter 7): config data requests and streams, plus the
// Connect 6021 stream; and automation (chapter 9) and unknown commands.

#include "cs2/Automation.h"
#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"

#include <algorithm>
#include <array>

namespace stellwerk::cs2 {
namespace {

using detail::be16;
using detail::be32;
using detail::BodyResult;
using detail::Reader;

constexpr std::array<NamedValue, 3> StreamForms{{{0, "header"}, {1, "broadcast-header"}, {2, "data"}}};
constexpr std::array<NamedValue, 9> AutomationStates{{{0, "deactivated"},
                                                      {1, "activated"},
                                                      {2, "running"},
                                                      {3, "block-free"},
                                                      {4, "block-occupied"},
                                                      {5, "suspended"},
                                                      {6, "reserved"},
                                                      {254, "waiting"},
                                                      {255, "error"}}};

BodyResult decodeRequest(const Reader& r) {
    if (r.size() != 8)
        return r.length("configdata.request carries an 8-byte file name");
    ConfigDataRequest m;
    for (std::size_t i = 0; i < 8; ++i)
        m.filename[i] = char(r.u8(i));
    return MessageBody(m);
}

BodyResult decodeStream(const Reader& r) {
    ConfigDataStream m;
    switch (r.size()) {
    case 6:
        m.form = ConfigDataStream::Form::Header;
        break;
    case 7:
        m.form = ConfigDataStream::Form::BroadcastHeader, m.extra = r.u8(6);
        break;
    case 8:
        for (std::size_t i = 0; i < 8; ++i)
            m.data[i] = r.u8(i);
        return MessageBody(m);
    default:
        return r.length("configdata.stream frames have 6 or 7 (header) or 8 (data) bytes");
    }
    m.length = r.u32(0);
    m.crc = r.u16(4);
    return MessageBody(m);
}

} // namespace

std::string_view ConfigDataRequest::text() const {
    const auto end = std::find(filename.begin(), filename.end(), '\0');
    return {filename.data(), std::size_t(end - filename.begin())};
}

namespace detail {

BodyResult decodeStream(std::uint8_t command, const Reader& r) {
    switch (Command(command)) {
    case Command::ConfigDataRequest:
        return decodeRequest(r);
    case Command::ConfigDataStream:
        return stellwerk::cs2::decodeStream(r);
    default:
        if (r.size() != 5 && r.size() != 6)
            return r.size() < 5 ? r.tooShort("connect6021.stream needs a UID and a value (5 data bytes)")
                                : r.length("connect6021.stream has 5 or 6 data bytes");
        return MessageBody(Connect6021Stream{r.raw()});
    }
}

BodyResult decodeAutomation(const Reader& r) {
    if (r.size() == 6)
        return MessageBody(AutomationSwitch{r.u16(0), r.u16(2), r.u8(4), r.u8(5), std::nullopt});
    if (r.size() == 8)
        return MessageBody(AutomationSwitch{r.u16(0), r.u16(2), 0, 0, LocId(r.u32(4))});
    return r.size() < 6 ? r.tooShort("automation.switch needs device, function and position (6 data bytes)")
                        : r.length("automation.switch has 6 or 8 data bytes");
}

void encode(const ConfigDataRequest& m, Writer& w) {
    for (char c : m.filename)
        w.u8(std::uint8_t(c));
}
void encode(const ConfigDataStream& m, Writer& w) {
    if (m.form == ConfigDataStream::Form::Data) {
        for (auto b : m.data)
            w.u8(b);
        return;
    }
    w.u32(m.length).u16(m.crc);
    if (m.form == ConfigDataStream::Form::BroadcastHeader)
        w.u8(m.extra);
}
void encode(const Connect6021Stream& m, Writer& w) {
    w.raw(m.raw);
}
void encode(const AutomationSwitch& m, Writer& w) {
    w.u16(m.device).u16(m.function);
    if (m.loco)
        w.u32(m.loco->value());
    else
        w.u8(m.position).u8(m.parameter);
}
void encode(const Unknown& m, Writer& w) {
    w.raw(m.raw);
}

} // namespace detail

void ConfigDataRequest::bind(FieldBinder& b) {
    b.chars("filename", filename);
}

void ConfigDataStream::bind(FieldBinder& b) {
    b.enumerated("form", form, StreamForms);
    if (form == Form::Data) {
        b.bytes("bytes", data);
        return;
    }
    b.number("length", length);
    b.number("crc", crc, FieldFormat::Hex);
    if (form == Form::BroadcastHeader)
        b.number("value", extra, FieldFormat::Hex);
}

void Connect6021Stream::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
    if (raw.size >= 4)
        b.fixed("uid", be32(raw, 0), FieldFormat::Hex);
    if (raw.size == 6)
        b.fixed("value", be16(raw, 4), FieldFormat::Hex);
    else if (raw.size == 5)
        b.fixed("value", raw.bytes[4], FieldFormat::Hex);
}

void AutomationSwitch::bind(FieldBinder& b) {
    b.number("device", device, FieldFormat::Hex);
    b.number("function", function, FieldFormat::Hex);
    if (const auto memory = MemoryFunction::fromWire(function))
        b.note("memory", memory->text());
    b.loco("locId", loco);
    if (loco)
        return;
    if (b.response()) {
        b.named("status", position, AutomationStates);
        if (!automationStateOf(position))
            b.note("state", "unknown"); // 9.1: unknown states are shown as "status unknown"
    } else
        b.number("position", position);
    b.number("parameter", parameter);
}

void Unknown::bind(FieldBinder& b) {
    b.number("command", command, FieldFormat::Hex);
    b.bytes("bytes", raw);
    if (command == 0 && raw.size >= 5) {
        b.fixed("uid", be32(raw, 0), FieldFormat::Hex);
        b.fixed("subcommand", raw.bytes[4], FieldFormat::Hex);
    }
}

} // namespace stellwerk::cs2
