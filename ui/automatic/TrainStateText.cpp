#include "automatic/TrainStateText.h"

#include "automatic/StopReasonText.h"
#include "operation/Operation.h"

namespace stellwerk::ui {

using automation::TrainMode;
using automation::TrainState;

namespace {

QString automaticState(const operation::Operation& operation, const automation::Train& train) {
    const QString fault = StopReasonText::of(operation.lastStopReason(train.locId));
    switch (train.state) {
    case TrainState::Waiting:
        return TrainStateText::tr("automatic, waiting");
    case TrainState::SettingWay:
        return TrainStateText::tr("automatic, setting its way");
    case TrainState::Running:
        return TrainStateText::tr("automatic, running");
    case TrainState::Braking:
        return TrainStateText::tr("automatic, braking");
    case TrainState::Stopped:
        return operation.automation()->dispatcher().paused()
                   ? TrainStateText::tr("stopped, waiting for Resume")
                   : TrainStateText::tr("stopped");
    case TrainState::Unknown:
        return TrainStateText::tr("stopped, state unknown (the station was silent)");
    case TrainState::Fault:
        return TrainStateText::tr("fault: %1").arg(fault);
    case TrainState::Lost:
        return TrainStateText::tr("lost: %1").arg(fault);
    }
    return {};
}

} // namespace

QString TrainStateText::state(const operation::Operation& operation, std::uint32_t locId) {
    if (const std::string why = operation.notPlaced(locId); !why.empty())
        return tr("not placed: %1").arg(QString::fromStdString(why));
    const automation::Train* train =
        operation.automation() ? operation.automation()->dispatcher().train(locId) : nullptr;
    if (!train)
        return tr("not placed");
    if (operation.waitsForResume(locId))
        return tr("automatic, waiting for Resume");
    if (train->mode == TrainMode::Manual)
        return operation.takenByHand(locId) ? tr("manual (taken by a throttle)") : tr("manual");
    return automaticState(operation, *train);
}

bool TrainStateText::trouble(const operation::Operation& operation, std::uint32_t locId) {
    const automation::Train* train =
        operation.automation() ? operation.automation()->dispatcher().train(locId) : nullptr;
    return !operation.notPlaced(locId).empty() ||
           (train && train->mode == TrainMode::Automatic &&
            (train->state == TrainState::Fault || train->state == TrainState::Lost ||
             train->state == TrainState::Unknown));
}

QString TrainStateText::schedule(const automation::Schedule& schedule) {
    if (schedule.stops.empty())
        return tr("none: any free block");
    QStringList stops;
    for (std::size_t i = 0; i < schedule.stops.size(); ++i) {
        const automation::ScheduleStop& stop = schedule.stops[i];
        const QString marker = i == schedule.next ? QStringLiteral("▸") : QString();
        stops << tr("%1%2 (%3 s)")
                     .arg(marker, QString::fromStdString(stop.block))
                     .arg(double(stop.dwellMs) / 1000.0, 0, 'g', 4);
    }
    const QString joined = stops.join(QStringLiteral(" → "));
    if (schedule.done())
        return tr("%1, done").arg(joined);
    return schedule.loop ? tr("%1, loop").arg(joined) : tr("%1, once").arg(joined);
}

} // namespace stellwerk::ui
