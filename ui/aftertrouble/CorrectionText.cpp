#include "aftertrouble/CorrectionText.h"

#include "model/Railway.h"

namespace stellwerk::ui {

using Kind = model::CommandTarget::Kind;

QString CorrectionText::of(const model::Correction& correction, const model::Railway* railway) {
    const QString name = targetName(correction.target, railway);
    const QString failed = value(correction.target, correction.failedValue);
    if (!correction.sentValue)
        return tr("%1: the station carried out a command late that had failed (%2); it stays, as it "
                  "brings nothing into motion.")
            .arg(name, failed);
    const QString back = correction.target.kind == Kind::Speed && *correction.sentValue == 0
                             ? tr("stopped")
                             : tr("set back to %1").arg(value(correction.target, *correction.sentValue));
    if (correction.carriedOutLate)
        return tr("%1: the station carried out a command late that had failed (%2); %3.")
            .arg(name, failed, back);
    return tr("%1: a command that had failed (%2) could still reach the station; %3.")
        .arg(name, failed, back);
}

QString CorrectionText::targetName(const model::CommandTarget& target, const model::Railway* railway) {
    switch (target.kind) {
    case Kind::Speed:
    case Kind::Direction:
    case Kind::Function: {
        const model::Locomotive* loco = railway ? railway->locomotive(std::uint32_t(target.id)) : nullptr;
        return loco ? loco->displayName()
                    : model::Locomotive(cs2::LocId(std::uint32_t(target.id))).displayName();
    }
    case Kind::Accessory: {
        const model::Accessory* accessory = railway ? railway->accessory(target.id) : nullptr;
        return accessory && !accessory->name().isEmpty() ? accessory->name()
                                                         : tr("Accessory %1").arg(target.id);
    }
    case Kind::Address:
        return tr("Address %1").arg(target.id);
    case Kind::Power:
        return tr("Track power");
    }
    return {};
}

QString CorrectionText::value(const model::CommandTarget& target, int value) {
    switch (target.kind) {
    case Kind::Speed:
        return tr("speed %1 %").arg(value / 10);
    case Kind::Direction:
        return value ? tr("backward") : tr("forward");
    case Kind::Function:
        return value ? tr("F%1 on").arg(target.functionNumber) : tr("F%1 off").arg(target.functionNumber);
    case Kind::Accessory:
    case Kind::Address:
        return tr("position %1").arg(value);
    case Kind::Power:
        return value ? tr("on") : tr("off");
    }
    return {};
}

} // namespace stellwerk::ui
