#include "trackplan/TrackTileInfo.h"

#include "model/TrackLayout.h"

namespace stellwerk::ui {
namespace {

using C = cs2config::TrackCategory;

} // namespace

QString TrackTileInfo::typeName(const QString& type, cs2config::TrackCategory category) {
    static const std::pair<const char*, const char*> names[] = {
        {"gerade", QT_TR_NOOP("Straight track")},
        {"bogen", QT_TR_NOOP("Curve")},
        {"doppelbogen", QT_TR_NOOP("Double curve")},
        {"kreuzung", QT_TR_NOOP("Crossing")},
        {"unterfuehrung", QT_TR_NOOP("Underpass")},
        {"prellbock", QT_TR_NOOP("Buffer stop")},
        {"tunnel", QT_TR_NOOP("Tunnel")},
        {"linksweiche", QT_TR_NOOP("Left turnout")},
        {"rechtsweiche", QT_TR_NOOP("Right turnout")},
        {"yweiche", QT_TR_NOOP("Y turnout")},
        {"dreiwegweiche", QT_TR_NOOP("Three-way turnout")},
        {"dkweiche", QT_TR_NOOP("Double slip")},
        {"dkweiche_2", QT_TR_NOOP("Double slip (two drives)")},
        {"hosentraeger", QT_TR_NOOP("Scissors crossover")},
        {"s88kontakt", QT_TR_NOOP("S88 contact")},
        {"s88bogen", QT_TR_NOOP("S88 contact (curve)")},
        {"s88doppelbogen", QT_TR_NOOP("S88 contact (double curve)")},
        {"pfeil", QT_TR_NOOP("Link to a page")},
        {"fahrstrasse", QT_TR_NOOP("Route button")},
        {"text", QT_TR_NOOP("Text")},
        {"bahnschranke", QT_TR_NOOP("Level crossing")},
    };
    for (const auto& [word, name] : names)
        if (type == QLatin1String(word))
            return tr(name);
    switch (category) {
    case C::Turnout:
        return tr("Slip turnout");
    case C::Signal:
        return type.startsWith(QLatin1String("signal_f")) ? tr("Semaphore signal") : tr("Signal");
    case C::Uncoupler:
        return tr("Uncoupler");
    case C::Output:
        return type.startsWith(QLatin1String("lampe")) ? tr("Lamp") : tr("Output");
    case C::Turntable:
        return tr("Turntable");
    case C::TransferTable:
        return tr("Transfer table");
    default:
        break;
    }
    return tr("Unknown element (%1)").arg(type);
}

QString TrackTileInfo::positionName(const QString& type, cs2config::TrackCategory category, int position) {
    if (category == C::Signal) {
        static const char* aspects[] = {QT_TR_NOOP("Stop (Hp0)"), QT_TR_NOOP("Proceed (Hp1)"),
                                        QT_TR_NOOP("Slow (Hp2)"), QT_TR_NOOP("Shunting (Sh1)")};
        if (type == QLatin1String("signal_sh01"))
            return position == 0 ? tr("Stop (Sh0)") : tr("Shunting (Sh1)");
        if (position >= 0 && position < 4)
            return tr(aspects[position]);
    }
    if (type == QLatin1String("dreiwegweiche") && position >= 0 && position < 3) {
        static const char* legs[] = {QT_TR_NOOP("Left"), QT_TR_NOOP("Straight"), QT_TR_NOOP("Right")};
        return tr(legs[position]);
    }
    if (type == QLatin1String("yweiche") && position >= 0 && position < 2)
        return position == 0 ? tr("Left") : tr("Right");
    if (category == C::Turnout && position >= 0 && position < 2)
        return position == 0 ? tr("Diverging") : tr("Straight");
    if (position >= 0 && position < 2)
        return position == 0 ? tr("Off") : tr("On");
    return tr("Position %1").arg(position);
}

QString TrackTileInfo::toolTip(const model::LayoutTile& tile, const QString& name) {
    QStringList lines{typeName(tile.type, tile.category)};
    if (tile.accessory)
        lines << tr("Accessory %1").arg(*tile.accessory);
    if (tile.contact)
        lines << tr("Contact %1 (device %2)").arg(*tile.contact & 0xFFFF).arg(*tile.contact >> 16);
    if (tile.route)
        lines << tr("Route %1").arg(*tile.route);
    if (!name.isEmpty())
        lines << name;
    else if (!tile.text.isEmpty())
        lines << tile.text;
    return lines.join(QLatin1Char('\n'));
}

} // namespace stellwerk::ui
