#include "orc/FrameReport.h"

#include "orc/Uid.h"

#include <cstdio>

namespace stellwerk::orc {
namespace {

using Fields = can::FieldList;

void origin(Fields& f, const Origin& from, bool answer) {
    f.number("prio", from.prio).text("type", deviceTypeName(from.type)).hex("sender", from.busId, 4);
    f.text("direction", answer ? "answer" : "command");
}

void target(Fields& f, const Target& t) {
    if (t.kind == Target::Kind::All)
        f.text("target", "all");
    else if (t.kind == Target::Kind::BusId)
        f.hex("target", t.value, 4);
    else
        f.hex("uid", t.value, 8);
}

// A Ziel-Id with what it means when it lies in a legacy range: "target=0x3005 legacy=mm2-decoder number=5".
void targetId(Fields& f, std::uint16_t id) {
    f.hex("target", id, 4);
    if (const std::optional<LegacyAddress> legacy = legacyAddressOf(id))
        f.text("legacy", legacy->range->name).number("number", legacy->number);
}

std::string_view actionName(GroupAction action) {
    return action == GroupAction::On ? "on" : action == GroupAction::Restore ? "restore" : "off";
}

std::string_view overloadName(std::uint8_t kind) {
    return kind == 0 ? "none" : kind == 1 ? "current" : kind == 2 ? "temperature" : "unknown";
}

std::string version(std::uint16_t v) {
    return std::to_string(v >> 8) + "." + std::to_string(v & 0xFF);
}

void add(Fields& f, const AllOff& m) {
    origin(f, m.from, false);
    target(f, m.target);
}
void add(Fields& f, const AllOn& m) {
    origin(f, m.from, false);
    target(f, m.target);
}
void add(Fields& f, const Overload& m) {
    origin(f, m.from, m.answer);
    f.number("kind", m.kind).text("overload", overloadName(m.kind));
    if (m.hasPort)
        f.number("port", m.port);
}
void add(Fields& f, const LocoStop& m) {
    origin(f, m.from, false);
    target(f, m.target);
}
void add(Fields& f, const LocoSpeedQuery& m) {
    origin(f, m.from, false);
    targetId(f, m.target);
}
void speedFields(Fields& f, std::uint16_t speed) {
    f.number("speed", speed & 0x7FFF).text("travel", (speed & 0x8000) != 0 ? "reverse" : "forward");
}
void add(Fields& f, const LocoSpeed& m) {
    origin(f, m.from, m.answer);
    targetId(f, m.target);
    speedFields(f, m.speed);
}
void add(Fields& f, const LocoSpeedQueryByUid& m) {
    origin(f, m.from, false);
    f.hex("uid", m.uid, 8);
}
void add(Fields& f, const LocoSpeedByUid& m) {
    origin(f, m.from, m.answer);
    f.hex("uid", m.uid, 8);
    speedFields(f, m.speed);
    if (m.textForm)
        f.flag("textForm", true);
}
void add(Fields& f, const LocoFunctionsQuery& m) {
    origin(f, m.from, false);
    targetId(f, m.target);
}
void add(Fields& f, const LocoFunctions& m) {
    origin(f, m.from, m.answer);
    targetId(f, m.target);
    f.hex("functions", m.functions, 8);
}
void add(Fields& f, const LocoFunctionQuery& m) {
    origin(f, m.from, false);
    targetId(f, m.target);
    f.number("function", m.function);
}
void add(Fields& f, const LocoFunction& m) {
    origin(f, m.from, m.answer);
    targetId(f, m.target);
    f.number("function", m.function).number("value", m.value);
}
void add(Fields& f, const AllDecoders& m) {
    origin(f, m.from, false);
    f.text("action", actionName(m.action));
}
void add(Fields& f, const DecoderSwitch& m) {
    origin(f, m.from, m.answer);
    targetId(f, m.target);
    f.number("position", m.position);
}
void add(Fields& f, const AllEncoders& m) {
    origin(f, m.from, false);
    f.text("action", actionName(m.action));
}
void add(Fields& f, const EncoderQuery& m) {
    origin(f, m.from, false);
    if (m.everyEncoder)
        f.text("target", "all");
    else
        f.hex("target", m.target, 4);
}
void add(Fields& f, const EncoderStatus& m) {
    origin(f, m.from, m.answer);
    f.hex("encoder", m.encoder, 4).number("inputCount", 8u * m.bytes).hex("inputs", m.inputs, 2u * m.bytes);
    f.text("event", m.answer ? "answer" : "event");
}
void add(Fields& f, const Ping& m) {
    origin(f, m.from, false);
    f.hex("uid", m.uid, 8);
}
void add(Fields& f, const PingAnswer& m) {
    origin(f, m.from, true);
    f.hex("uid", m.uid, 8).hex("version", m.version, 4).text("versionText", version(m.version));
}
void add(Fields& f, const Find& m) {
    origin(f, m.from, false);
    f.hex("uid", m.uid, 8);
}
void add(Fields& f, const FindAnswer& m) {
    origin(f, m.from, true);
    f.hex("uid", m.uid, 8).hex("version", m.version, 4).text("versionText", version(m.version));
    f.flag("extension", true);
}
void add(Fields& f, const AssignBusId& m) {
    origin(f, m.from, m.answer);
    f.hex("uid", m.uid, 8).hex("busId", m.busId, 4).flag("extension", true);
}
void add(Fields& f, const FlashCancel& m) {
    origin(f, m.from, false);
}
void add(Fields& f, const FlashInit& m) {
    origin(f, m.from, false);
    target(f, m.target);
    f.number("version", m.version);
}
void add(Fields& f, const FlashAccepted& m) {
    origin(f, m.from, true);
    f.hex("target", m.target, 4).hex("uid", m.uid, 8).number("version", m.version);
}
void add(Fields& f, const FlashSize& m) {
    origin(f, m.from, false);
    f.hex("target", m.target, 4).hex("start", m.start, 6).number("size", m.size);
    if (m.tableCode)
        f.flag("tableCode", true);
}
void add(Fields& f, const FlashSizeAnswer& m) {
    origin(f, m.from, true);
    f.hex("target", m.target, 4).number("available", m.available).number("countMax", m.countMax);
    if (m.tableCode)
        f.flag("tableCode", true);
}
void add(Fields& f, const FlashData& m) {
    origin(f, m.from, m.answer);
    f.hex("target", m.target, 4).number("count", m.count);
    f.text("bytes", can::hexDigits(m.bytes[0], 2) + can::hexDigits(m.bytes[1], 2) +
                        can::hexDigits(m.bytes[2], 2) + can::hexDigits(m.bytes[3], 2));
}
void add(Fields& f, const FlashChecksum& m) {
    origin(f, m.from, m.answer);
    f.hex("target", m.target, 4).number("count", m.count).hex("crc", m.crc, 8);
}
void add(Fields& f, const Unknown& m) {
    const Header h = readId(m.id);
    f.number("prio", h.prio).number("type", h.type).hex("group", h.group).flag("answer", h.answer);
    f.hex("sender", h.busId, 4).text("why", m.why);
}

} // namespace

std::string_view deviceTypeName(std::uint8_t type) {
    static constexpr std::string_view names[] = {"system",      "loco",           "can-decoder",
                                                 "can-encoder", "legacy-decoder", "legacy-encoder",
                                                 "free-6",      "free-7"};
    return names[type & 7];
}

std::vector<Field> describe(const Message& message) {
    Fields fields;
    std::visit([&fields](const auto& m) { add(fields, m); }, message);
    return std::move(fields.list);
}

FrameReport::FrameReport(const can::CanFrame& frame)
    : frame_(frame), message_(decode(frame)), fields_(describe(message_)) {}

std::string FrameReport::detailText() const {
    return can::fieldsText(fields_);
}

std::string FrameReport::text() const {
    return can::reportText(frame_, name(), fields_);
}

std::string FrameReport::json() const {
    return can::reportJson(frame_, name(), fields_);
}

std::optional<std::uint64_t> FrameReport::number(std::string_view key) const {
    return can::fieldNumber(fields_, key);
}

} // namespace stellwerk::orc
