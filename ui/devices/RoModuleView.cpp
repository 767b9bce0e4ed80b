#include "devices/RoModuleView.h"

#include "common/NotReported.h"
#include "connection/DeviceSettings.h"
#include "devices/SignalGrid.h"
#include "romodule/RoModuleSession.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace stellwerk::ui {

using romodule::RoModuleSession;

namespace {
constexpr int CountersPeriodMs = 500;
}

RoModuleView::RoModuleView(QWidget* parent)
    : QWidget(parent), m_title(new QLabel(this)), m_state(new QLabel(this)), m_relaysLabel(new QLabel(this)),
      m_relays(new SignalGrid(SignalGrid::Kind::Switches, this)), m_allOff(new QPushButton(this)),
      m_inputsLabel(new QLabel(this)), m_inputs(new SignalGrid(SignalGrid::Kind::Lamps, this)),
      m_problem(new QLabel(this)), m_counters(new QLabel(this)) {
    setObjectName(QStringLiteral("roModuleView"));
    m_relays->setObjectName(QStringLiteral("relayGrid"));
    m_inputs->setObjectName(QStringLiteral("inputGrid"));
    m_allOff->setObjectName(QStringLiteral("allRelaysOff"));
    m_state->setObjectName(QStringLiteral("moduleState"));
    m_problem->setObjectName(QStringLiteral("moduleProblem"));
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    for (QLabel* label : {m_state, m_problem, m_counters})
        label->setWordWrap(true);
    m_counters->setForegroundRole(QPalette::PlaceholderText);
    auto* relayRow = new QHBoxLayout;
    relayRow->addWidget(m_relaysLabel, 1);
    relayRow->addWidget(m_allOff);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_title);
    layout->addWidget(m_state);
    layout->addLayout(relayRow);
    layout->addWidget(m_relays);
    layout->addWidget(m_inputsLabel);
    layout->addWidget(m_inputs);
    layout->addWidget(m_problem);
    layout->addWidget(m_counters);
    layout->addStretch(1);
    connect(m_relays, &SignalGrid::switchRequested, this, [this](int number, bool on) {
        if (!m_session || !m_session->setOutput(number, on))
            failed(tr("Relay %1 was not switched: the module does not answer.").arg(number));
    });
    connect(m_allOff, &QPushButton::clicked, this, [this] {
        if (!m_session || !m_session->switchAllOff())
            failed(tr("The relays were not switched off: the module does not answer."));
    });
    // The conversation's counters change with every poll, which no signal announces.
    auto* clock = new QTimer(this);
    connect(clock, &QTimer::timeout, this, [this] {
        if (isVisible())
            update();
    });
    clock->start(CountersPeriodMs);
    retranslate();
}

void RoModuleView::setModule(const connection::RoModuleSettings& settings, RoModuleSession* session,
                             const QString& why) {
    m_name = QString::fromStdString(settings.profile.name);
    m_why = why;
    m_relays->setCount(settings.profile.outputs.count);
    m_inputs->setCount(settings.profile.inputs.count);
    if (session != m_session)
        attach(session);
    update();
}

void RoModuleView::attach(RoModuleSession* session) {
    if (m_session)
        m_session->disconnect(this);
    m_session = session;
    m_problem->clear();
    m_relays->stopWaiting();
    if (!session)
        return;
    connect(session, &RoModuleSession::stateChanged, this, &RoModuleView::update);
    connect(session, &RoModuleSession::outputsChanged, this, &RoModuleView::update);
    connect(session, &RoModuleSession::inputsChanged, this, &RoModuleView::update);
    connect(session, &RoModuleSession::requestFinished, this, &RoModuleView::update);
    connect(session, &RoModuleSession::outputsFailed, this,
            [this](std::uint32_t, const QString& why) { failed(tr("Not switched: %1").arg(why)); });
}

void RoModuleView::update() {
    const bool online = m_session && m_session->state() == RoModuleSession::State::Online;
    m_relays->setStates(online ? m_session->outputs() : std::nullopt);
    m_relays->setSwitchable(online);
    m_inputs->setStates(online ? m_session->inputs() : std::nullopt);
    m_allOff->setEnabled(online && m_session->outputs().has_value() && m_relays->count() > 0);
    m_state->setText(stateText());
    if (m_session) {
        const romodule::SessionCounters& c = m_session->counters();
        m_counters->setText(
            tr("Answers %1 · repeated %2 · timed out %3 · refused %4 · late or foreign %5 · unreadable %6")
                .arg(c.ok)
                .arg(c.duplicates)
                .arg(c.timeouts)
                .arg(c.invalid)
                .arg(c.stale + c.unsolicited)
                .arg(c.malformed));
    } else {
        m_counters->clear();
    }
    m_title->setText(m_name);
}

QString RoModuleView::countersText() const {
    return m_counters->text();
}

QString RoModuleView::stateText() const {
    if (!m_session)
        return m_why;
    switch (m_session->state()) {
    case RoModuleSession::State::Starting:
        return tr("Reading the relays…");
    case RoModuleSession::State::Online:
        return tr("Online. A relay changes colour once the module confirmed it.");
    case RoModuleSession::State::Offline:
        return tr("Offline: the module does not answer. Relays and inputs are %1 until it answers again.")
            .arg(NotReported::word());
    }
    return {};
}

void RoModuleView::failed(const QString& why) {
    m_relays->stopWaiting();
    m_problem->setText(why);
}

void RoModuleView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void RoModuleView::retranslate() {
    m_relaysLabel->setText(tr("Relays (click one to switch it)"));
    m_allOff->setText(tr("All relays off"));
    m_inputsLabel->setText(tr("Inputs"));
    update();
}

} // namespace stellwerk::ui
