// Feedback commands (document chapter 5): S88 polling, S88 events and Selectrix events.

#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"

namespace stellwerk::cs2 {
namespace {

using detail::BodyResult;
using detail::Reader;

BodyResult decodePoll(const Reader& r) {
    if (r.size() == 5)
        return MessageBody(S88Poll{r.u32(0), r.u8(4), std::nullopt, std::nullopt});
    if (r.size() == 7)
        return MessageBody(S88Poll{r.u32(0), std::nullopt, r.u8(4), r.u16(5)});
    return r.size() < 5 ? r.tooShort("feedback.s88-poll needs a UID and a module count (5 data bytes)")
                        : r.length("feedback.s88-poll has 5 (request) or 7 (answer) data bytes");
}

BodyResult decodeEvent(const Reader& r) {
    if (r.size() < 4)
        return r.tooShort("feedback.s88-event needs a device id and a contact (4 data bytes)");
    S88Event m{r.u16(0), r.u16(2), std::nullopt, std::nullopt, std::nullopt};
    switch (r.size()) {
    case 4:
        break;
    case 5:
        m.parameter = r.u8(4);
        break;
    case 7:
        m.lastContact = r.u16(4), m.parameter = r.u8(6);
        break;
    case 8:
        m.change = S88Change{r.u8(4), r.u8(5), r.u16(6)};
        break;
    default:
        return r.length("feedback.s88-event has 4, 5, 7 or 8 data bytes");
    }
    return MessageBody(m);
}

BodyResult decodeSx1(const Reader& r) {
    if (r.size() == 5)
        return MessageBody(Sx1Event{r.u32(0), r.u8(4), std::nullopt});
    if (r.size() == 6)
        return MessageBody(Sx1Event{r.u32(0), r.u8(4), r.u8(5)});
    return r.size() < 5 ? r.tooShort("feedback.sx1-event needs a UID and an address (5 data bytes)")
                        : r.length("feedback.sx1-event has 5 or 6 data bytes");
}

} // namespace

namespace detail {

BodyResult decodeFeedback(std::uint8_t command, const Reader& r) {
    switch (Command(command)) {
    case Command::S88Poll:
        return decodePoll(r);
    case Command::S88Event:
        return decodeEvent(r);
    default:
        return decodeSx1(r);
    }
}

void encode(const S88Poll& m, Writer& w) {
    w.u32(m.device);
    if (m.module || m.state)
        w.u8(m.module.value_or(0)).u16(m.state.value_or(0));
    else
        w.u8(m.moduleCount.value_or(0));
}
void encode(const S88Event& m, Writer& w) {
    w.u16(m.device).u16(m.contact);
    if (m.change)
        w.u8(m.change->oldState).u8(m.change->newState).u16(m.change->time10ms);
    else if (m.lastContact)
        w.u16(*m.lastContact).u8(m.parameter.value_or(0));
    else if (m.parameter)
        w.u8(*m.parameter);
}
void encode(const Sx1Event& m, Writer& w) {
    w.u32(m.uid).u8(m.address);
    if (m.state)
        w.u8(*m.state);
}

} // namespace detail

void S88Poll::bind(FieldBinder& b) {
    b.number("uid", device, FieldFormat::Hex);
    b.number("count", moduleCount);
    b.number("module", module);
    b.number("state", state, FieldFormat::Hex);
}

void S88Event::bind(FieldBinder& b) {
    b.number("device", device, FieldFormat::Hex);
    b.number("contact", contact);
    b.number("lastContact", lastContact);
    b.number("parameter", parameter, FieldFormat::Hex);
    std::optional<std::uint8_t> oldState, newState;
    std::optional<std::uint16_t> time;
    if (change)
        oldState = change->oldState, newState = change->newState, time = change->time10ms;
    b.number("oldState", oldState);
    b.number("newState", newState);
    b.number("timeMs", time, FieldFormat::Decimal, 10);
    if (oldState || newState || time)
        change = S88Change{oldState.value_or(0), newState.value_or(0), time.value_or(0)};
}

void Sx1Event::bind(FieldBinder& b) {
    b.number("uid", uid, FieldFormat::Hex);
    b.number("address", address);
    b.number("state", state);
}

} // namespace stellwerk::cs2
