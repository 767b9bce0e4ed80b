#include "SimOrcDevices.h"

#include <QTextStream>

namespace stellwerk::simapp {

namespace {

QTextStream& out() {
    static QTextStream stream(stdout);
    return stream;
}

QString hex(std::uint32_t value, int digits) {
    return "0x" + QString::number(value, 16).toUpper().rightJustified(digits, '0');
}

} // namespace

SimOrcDevices::SimOrcDevices(sim::SimulatedBus& bus, const SimOptions& options) : options_(options) {
    if (options.orcBooster) {
        booster_ = std::make_unique<sim::SimulatedOrcBooster>(BoosterUid);
        bus.attach(*booster_);
    }
    for (int n = 0; n < options.orcDecoders; ++n) {
        auto& decoder = decoders_.emplace_back(
            std::make_unique<sim::SimulatedOrcDecoder>(FirstDecoderUid + std::uint32_t(n)));
        bus.attach(*decoder);
        QObject::connect(decoder.get(), &sim::SimulatedOrcDecoder::switched, decoder.get(),
                         [busId = decoder->busId()](std::uint8_t outputs) {
                             out() << "ORC decoder " << hex(busId, 4) << ": outputs "
                                   << QString::number(outputs, 2).rightJustified(8, '0') << Qt::endl;
                         });
    }
    for (int n = 0; n < options.orcEncoders; ++n) {
        auto& encoder = encoders_.emplace_back(
            std::make_unique<sim::SimulatedOrcEncoder>(FirstEncoderUid + std::uint32_t(n)));
        bus.attach(*encoder);
    }
    if (options.orcThrottleLoco) {
        throttle_ = std::make_unique<sim::SimulatedOrcThrottle>(ThrottleUid);
        bus.attach(*throttle_);
    }
    QObject::connect(&overloadClock_, &QTimer::timeout, [this] { toggleOverload(); });
    QObject::connect(&throttleClock_, &QTimer::timeout, [this] { driveNow(); });
    QObject::connect(&inputClock_, &QTimer::timeout, [this] { toggleInputs(); });
}

void SimOrcDevices::plugIn() {
    if (booster_)
        booster_->plugIn();
    for (const auto& decoder : decoders_)
        decoder->plugIn();
    for (const auto& encoder : encoders_)
        encoder->plugIn();
    if (throttle_)
        throttle_->plugIn();
    if (empty())
        return;
    out() << "OpenRailCAN: " << (booster_ ? "a booster, " : "") << decoders_.size() << " decoder(s), "
          << encoders_.size() << " encoder(s)" << (throttle_ ? ", a throttle" : "")
          << " on the station's bus (no M-CAN master there)" << Qt::endl;
    if (throttle_)
        throttleClock_.start(options_.orcThrottleEvery);
    if (booster_ && options_.orcOverloadAfter.count() > 0)
        overloadClock_.start(options_.orcOverloadAfter);
    if (!encoders_.empty() && options_.orcEncoderToggle.count() > 0)
        inputClock_.start(options_.orcEncoderToggle);
}

// Überlast on the port, then "Nix" (cleared) the next time.
void SimOrcDevices::toggleOverload() {
    overloaded_ = !overloaded_;
    const auto port = std::uint8_t(options_.orcOverloadPort);
    if (overloaded_)
        booster_->injectOverload(port);
    else
        booster_->clearOverload(port);
    out() << "ORC booster: port " << int(port) << (overloaded_ ? " overloaded" : " overload cleared")
          << Qt::endl;
}

// Lok Speed for its loco: 300, 0, 300, ... (forward).
void SimOrcDevices::driveNow() {
    nextSpeed_ = nextSpeed_ == 0 ? 300 : 0;
    throttle_->drive(*options_.orcThrottleLoco, std::uint16_t(nextSpeed_));
    out() << "ORC throttle: Lok Speed " << hex(*options_.orcThrottleLoco, 4) << ' ' << nextSpeed_ << Qt::endl;
}

void SimOrcDevices::toggleInputs() {
    const int input = nextInput_;
    nextInput_ = (nextInput_ + 1) % 32;
    for (const auto& encoder : encoders_)
        encoder->setInput(input, !(encoder->inputs() >> input & 1));
}

} // namespace stellwerk::simapp
