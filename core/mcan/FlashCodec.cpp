#include "mcan/CodecDetail.h"

// The flash layout (node 127, document 9): decoded and shown, never started by Stellwerk.

namespace stellwerk::mcan::detail {

Message decodeFlash(const can::CanFrame& frame) {
    const FlashId f = readFlash(frame.id);
    const Data d{frame};
    const std::size_t n = frame.size();
    if (f.request == 0b101 && f.stage == 0 && f.flags == 0 && f.handle == 0 && n == 4)
        return FlashReady{d.u32(0)};
    if (f.request != 0)
        return unknown(frame, "flash request bits other than 000 and 101");
    if (f.flags == 0 && f.stage >= 1 && f.stage <= 3 && (n == 4 || n == 8)) {
        if (n == 4)
            return FlashQuery{f.handle, f.stage, d.u32(0)};
        return FlashAnswer{f.handle, f.stage, d.u32(0), d.u32(4)};
    }
    if (f.stage != 0)
        return unknown(frame, "flash stage without a documented form");
    if (f.flags == 0 && n == 4)
        return FlashStart{f.handle, d.u32(0)};
    if (f.flags == 1 && n == 8)
        return FlashDataRequest{f.handle, d.u32(0), d.u32(4)};
    if (f.flags == 2 && (n == 8 || n == 6))
        return FlashData{f.handle, d.u32(0), std::uint8_t(n - 4), {d[4], d[5], d[6], d[7]}};
    if (f.flags == 3 && n == 4)
        return FlashEnd{f.handle, d.u32(0)};
    return unknown(frame, "flash frame without a documented form");
}

namespace {

std::uint32_t flashFrameId(std::uint8_t handle, std::uint8_t request, std::uint8_t stage,
                           std::uint8_t flags) {
    return flashId({handle, request, stage, flags});
}

} // namespace

can::CanFrame encodeOne(const FlashReady& m) {
    return Payload().u32(m.uid).frame(flashFrameId(0, 0b101, 0, 0));
}

can::CanFrame encodeOne(const FlashQuery& m) {
    return Payload().u32(m.uid).frame(flashFrameId(m.handle, 0, m.stage, 0));
}

can::CanFrame encodeOne(const FlashAnswer& m) {
    return Payload().u32(m.uid).u32(m.value).frame(flashFrameId(m.handle, 0, m.stage, 0));
}

can::CanFrame encodeOne(const FlashStart& m) {
    return Payload().u32(m.uid).frame(flashFrameId(m.handle, 0, 0, 0));
}

can::CanFrame encodeOne(const FlashDataRequest& m) {
    return Payload().u32(m.offset).u32(m.count).frame(flashFrameId(m.handle, 0, 0, 1));
}

can::CanFrame encodeOne(const FlashData& m) {
    Payload payload;
    payload.u32(m.offset);
    for (std::uint8_t i = 0; i < m.count && i < 4; ++i)
        payload.byte(m.bytes[i]);
    return payload.frame(flashFrameId(m.handle, 0, 0, 2));
}

can::CanFrame encodeOne(const FlashEnd& m) {
    return Payload().u32(m.uid).frame(flashFrameId(m.handle, 0, 0, 3));
}

} // namespace stellwerk::mcan::detail
