#pragma once

#include "cs2/Codec.h"
#include "cs2/Header.h"

#include <string>
#include <string_view>

namespace stellwerk::cs2 {

// The vocabulary name a frame's command would have (used when decoding failed), e.g. "loco.speed".
std::string_view intendedName(const CanFrame& frame);

// A decoded frame written for people and for scripts: one line each, never several.
class FrameReport {
public:
    explicit FrameReport(const CanFrame& frame);

    bool ok() const { return result_.hasValue(); }
    const DecodeResult& result() const { return result_; }
    std::string_view name() const;

    // "00084711 6 00 00 C0 03 01 20  loco.speed  locId=0xC003 protocol=dcc address=3 speed=288"
    std::string text() const;
    // The parts of text(), for tables: the frame in document notation, and "key=value ..." (or the
    // error message when the frame did not decode).
    std::string frameText() const;
    std::string detailText() const;
    // {"id":"00084711","prio":0,"command":4,"response":false,"hash":"4711","dlc":6,"data":"0000C0030120",
    //  "name":"loco.speed","fields":{...}}
    std::string json() const;

private:
    CanFrame frame_;
    DecodeResult result_;
};

} // namespace stellwerk::cs2
