#include "connect/ConnectionStatus.h"

#include <QColor>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>

namespace stellwerk::ui {

namespace {

using State = connection::StationConnection::State;

// A small round lamp in the colour of the state, as on a signal box's panel.
QPixmap lamp(State state, int size) {
    QColor colour(Qt::gray);
    if (state == State::Ready)
        colour = QColor(0x2e, 0x9d, 0x3c);
    else if (state == State::Connecting || state == State::LoadingConfiguration)
        colour = QColor(0xe0, 0xa1, 0x1b);
    else if (state == State::Silent || state == State::Failed)
        colour = QColor(0xc8, 0x2c, 0x2c);
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(colour.darker(140));
    painter.setBrush(colour);
    painter.drawEllipse(QRectF(1, 1, size - 2, size - 2));
    return pixmap;
}

} // namespace

ConnectionStatus::ConnectionStatus(QWidget* parent)
    : QWidget(parent), m_lamp(new QLabel(this)), m_text(new QLabel(this)) {
    setObjectName(QStringLiteral("connectionStatus"));
    m_lamp->setObjectName(QStringLiteral("stationLamp"));
    m_text->setObjectName(QStringLiteral("stationStatus"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_lamp);
    layout->addWidget(m_text);
    refresh();
}

void ConnectionStatus::setConnection(const connection::StationConnection* station) {
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = station;
    if (m_connection) {
        connect(m_connection, &connection::StationConnection::stateChanged, this, &ConnectionStatus::refresh);
        connect(m_connection, &connection::StationConnection::progressChanged, this,
                &ConnectionStatus::refresh);
        connect(m_connection, &connection::StationConnection::problem, this, &ConnectionStatus::refresh);
        connect(m_connection, &QObject::destroyed, this, [this] { setConnection(nullptr); });
    }
    refresh();
}

QString ConnectionStatus::text() const {
    return m_text->text();
}

void ConnectionStatus::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QWidget::changeEvent(event);
}

void ConnectionStatus::refresh() {
    const State state = m_connection ? m_connection->state() : State::Disconnected;
    m_text->setText(statusText(m_connection));
    m_text->setToolTip(m_connection ? m_connection->lastProblem() : QString());
    const int size = m_text->fontMetrics().height() * 2 / 3;
    m_lamp->setPixmap(lamp(state, size));
}

QString ConnectionStatus::describe(const connection::StationEndpoint& endpoint) {
    using Kind = connection::StationEndpoint::Kind;
    switch (endpoint.kind) {
    case Kind::Simulated:
        return tr("Simulated CS2 (demo layout)");
    case Kind::Udp:
        return tr("CS2 at %1 (UDP)").arg(endpoint.place);
    case Kind::Tcp:
        return tr("CS2 at %1 (TCP)").arg(endpoint.place);
    case Kind::CanBus:
        return tr("CAN interface %1").arg(endpoint.place);
    case Kind::Unusable:
        break;
    }
    return tr("Station \"%1\"").arg(endpoint.place);
}

QString ConnectionStatus::advice(const connection::StationEndpoint& endpoint) {
    using Kind = connection::StationEndpoint::Kind;
    switch (endpoint.kind) {
    case Kind::Simulated:
        return tr("Try: restart Stellwerk; if it happens again, report the message above.");
    case Kind::Udp:
        return tr("Try: check that the station is on and reachable at this address, and that its CAN-UDP "
                  "gateway sends to this computer (CS2: Setup → IP → CAN gateway).");
    case Kind::Tcp:
        return tr("Try: check that the station is on and reachable at this address and port.");
    case Kind::CanBus:
        return tr("Try: check that the CAN interface exists and is up (SocketCAN: "
                  "ip link set can0 up type can bitrate 250000) and that the Gleisbox has power.");
    case Kind::Unusable:
        break;
    }
    return tr("Try: correct the address in Station → Connect…, for example udp://192.168.2.5.");
}

QString ConnectionStatus::statusText(const connection::StationConnection* station) {
    if (!station || station->state() == State::Disconnected)
        return tr("No station connected");
    const QString name = describe(station->endpoint());
    switch (station->state()) {
    case State::Connecting:
        return tr("%1 — connecting").arg(name);
    case State::LoadingConfiguration:
        return tr("%1 — loading configuration %2/%3: %4")
            .arg(name, QString::number(station->progress().stepNumber),
                 QString::number(station->progress().stepCount), loadingText(station->progress()));
    case State::Ready:
        return tr("%1 — ready: %2").arg(name, readyText(station->counts()));
    case State::Silent:
        return tr("%1 — station silent").arg(name);
    case State::Failed:
        return tr("%1 — failed: %2").arg(name, station->failureReason());
    case State::Disconnected:
        break;
    }
    return tr("No station connected");
}

// What the current step does: "lokomotive.cs2 45 %".
QString ConnectionStatus::loadingText(const connection::LoadingProgress& progress) {
    using connection::LoadingStep;
    QString what;
    switch (progress.step) {
    case LoadingStep::ListingDevices:
        what = tr("listing the devices");
        break;
    case LoadingStep::WakingUp:
        what = tr("waking up the Gleisbox");
        break;
    case LoadingStep::ReadingDevices:
        what = tr("reading the devices");
        break;
    case LoadingStep::DownloadingFiles:
        if (progress.file.isEmpty())
            what = tr("files");
        else if (const auto percent = progress.percent())
            what = tr("%1 %2 %").arg(progress.file, QString::number(*percent));
        else
            what = progress.file;
        break;
    case LoadingStep::ReadingStates:
        what = tr("locomotive and contact states");
        break;
    }
    return what;
}

// "12 locomotives, 12 accessories, 3 pages"
QString ConnectionStatus::readyText(const connection::StationCounts& counts) {
    return tr("%1, %2, %3")
        .arg(tr("%n locomotive(s)", nullptr, counts.locomotives),
             tr("%n accessory(s)", nullptr, counts.accessories), tr("%n page(s)", nullptr, counts.pages));
}

} // namespace stellwerk::ui
