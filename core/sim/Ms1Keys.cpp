#include "sim/Ms1Keys.h"

namespace stellwerk::sim {

namespace {

constexpr std::uint16_t TakeState = 0x0008; // "Anmeldung am Slave" (document 7.6)
constexpr std::uint8_t Take = 0;
constexpr std::uint8_t ChooseAgain = 1;
constexpr std::uint8_t StopGoType = 1;

} // namespace

bool Ms1Keys::take(std::size_t stackIndex, Ms1Outbox& out) {
    if (stackIndex >= memory_.stack.size())
        return false;
    memory_.shown = stackIndex;
    memory_.choosingAgain = false;
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return throttle(Take, out);
}

bool Ms1Keys::chooseAgain(Ms1Outbox& out) {
    return memory_.shown && throttle(ChooseAgain, out);
}

bool Ms1Keys::throttle(std::uint8_t control, Ms1Outbox& out) {
    const Ms1Loco& loco = memory_.stack[*memory_.shown];
    memory_.control = Ms1Control::Asked;
    out.send(mcan::Throttle{memory_.link.at(loco.handle, mcan::prio::Throttle), control, TakeState, 1});
    return true;
}

Ms1Loco* Ms1Keys::drivable() {
    if (!memory_.shown || memory_.control != Ms1Control::Granted)
        return nullptr;
    return &memory_.stack[*memory_.shown];
}

bool Ms1Keys::drive(int speed, bool reverse, Ms1Outbox& out) {
    Ms1Loco* loco = drivable();
    if (!loco || speed < 0 || speed > 127)
        return false;
    loco->speed = std::uint8_t(speed);
    loco->reverse = reverse;
    const auto value = std::uint8_t(speed | (reverse ? 0x80 : 0));
    out.send(mcan::FunctionValue{memory_.link.at(loco->handle, mcan::prio::SlaveDrive), 1, value});
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

bool Ms1Keys::function(int number, bool on, Ms1Outbox& out) {
    Ms1Loco* loco = drivable();
    if (!loco || number < 0 || std::size_t(number) >= loco->functions.size())
        return false;
    loco->functions[std::size_t(number)].value = on ? 1 : 0;
    const auto fkt = std::uint8_t(number + 2);
    out.send(mcan::FunctionValue{memory_.link.at(loco->handle, mcan::prio::SlaveDrive), fkt,
                                 std::uint8_t(on ? 1 : 0)});
    out.tell(Ms1Outbox::Event::DisplayChanged);
    return true;
}

bool Ms1Keys::stopKey(bool stop, Ms1Outbox& out) {
    if (memory_.link.syHandle == 0)
        return false;
    const mcan::Address at = memory_.link.at(memory_.link.syHandle, mcan::prio::SlaveDrive);
    out.send(mcan::StatusValue{at, memory_.statusIndexOf(StopGoType), std::uint8_t(stop ? 1 : 0)});
    return true;
}

} // namespace stellwerk::sim
