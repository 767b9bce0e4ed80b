// Accessory commands (document chapter 4): switching, and the unpublished accessory configuration.

#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"

namespace stellwerk::cs2 {
namespace {

using detail::BodyResult;
using detail::Reader;

BodyResult decodeSwitch(const Reader& r) {
    if (r.size() < 6)
        return r.tooShort("accessory.switch needs a Loc-ID, position and current (6 data bytes)");
    if (r.size() != 6 && r.size() != 8)
        return r.length("accessory.switch has 6 or 8 data bytes");
    AccessorySwitch m{LocId(r.u32(0)), r.u8(4), r.u8(5), std::nullopt};
    if (m.current > 31)
        return r.reserved("accessory current is 0..31");
    if (r.size() == 8)
        m.time10ms = r.u16(6);
    return MessageBody(m);
}

} // namespace

namespace detail {

BodyResult decodeAccessory(std::uint8_t command, const Reader& r) {
    if (Command(command) == Command::AccessorySwitch)
        return decodeSwitch(r);
    return MessageBody(AccessoryConfig{r.raw()});
}

void encode(const AccessorySwitch& m, Writer& w) {
    w.u32(m.article.value()).u8(m.position).u8(m.current);
    if (m.time10ms)
        w.u16(*m.time10ms);
}
void encode(const AccessoryConfig& m, Writer& w) {
    w.raw(m.raw);
}

} // namespace detail

void AccessorySwitch::bind(FieldBinder& b) {
    b.loco("locId", article);
    b.number("position", position);
    b.number("current", current, FieldFormat::Decimal, 1, 31);
    b.number("switchTimeMs", time10ms, FieldFormat::Decimal, 10);
}

void AccessoryConfig::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
    if (raw.size >= 4)
        b.fixed("uid", detail::be32(raw, 0), FieldFormat::Hex);
}

} // namespace stellwerk::cs2
