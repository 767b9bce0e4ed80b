#include "common/LayoutStateBanner.h"

#include "model/Railway.h"

#include <QEvent>

namespace stellwerk::ui {
namespace {

// Dark red with light text: the same family as the STOP / GO key's "track power off" look.
const QString stoppedStyle = QStringLiteral(
    "QLabel { background: #4a0d0d; color: #ffe082; border: 2px solid #e53935; border-radius: 4px; "
    "padding: 6px 10px; font-weight: bold; }");
// Grey: nothing here can be vouched for.
const QString unknownStyle = QStringLiteral("QLabel { background: #616161; color: white; border-radius: 4px; "
                                            "padding: 6px 10px; font-weight: bold; }");

} // namespace

LayoutStateBanner::LayoutStateBanner(QWidget* parent) : QLabel(parent) {
    setObjectName(QStringLiteral("layoutStateBanner"));
    setWordWrap(true);
    setAlignment(Qt::AlignCenter);
    refresh();
}

void LayoutStateBanner::setRailway(const model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway) {
        connect(m_railway, &model::Railway::powerChanged, this, &LayoutStateBanner::refresh);
        connect(m_railway, &model::Railway::stateReportedChanged, this, &LayoutStateBanner::refresh);
        connect(m_railway, &QObject::destroyed, this, &LayoutStateBanner::refresh);
    }
    refresh();
}

LayoutStateBanner::Shows LayoutStateBanner::showsFor(const model::Railway* railway) {
    if (!railway)
        return Shows::Nothing;
    if (!railway->isStateReported())
        return Shows::NotReported;
    const auto power = railway->power();
    if (!power)
        return Shows::PowerNotReported;
    switch (*power) {
    case station::PowerState::Running:
        return Shows::Nothing;
    case station::PowerState::Halted:
        return Shows::Halted;
    case station::PowerState::Stopped:
        break;
    }
    return Shows::Stopped;
}

void LayoutStateBanner::refresh() {
    m_shows = showsFor(m_railway);
    switch (m_shows) {
    case Shows::Nothing:
        setText(QString());
        break;
    case Shows::NotReported:
        setText(tr("Not reported: the station is silent or being reconnected. Greyed states are the "
                   "last it reported."));
        break;
    case Shows::PowerNotReported:
        setText(tr("Track power not reported yet: the station has not said whether trains may run."));
        break;
    case Shows::Stopped:
        setText(
            tr("LAYOUT STOPPED: track power is off. Press the power key in the toolbar to switch it on."));
        break;
    case Shows::Halted:
        setText(tr("LAYOUT HALTED: every train was halted. Press the power key in the toolbar to go on."));
        break;
    }
    setStyleSheet(m_shows == Shows::Stopped || m_shows == Shows::Halted ? stoppedStyle : unknownStyle);
    setVisible(m_shows != Shows::Nothing);
}

void LayoutStateBanner::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QLabel::changeEvent(event);
}

} // namespace stellwerk::ui
