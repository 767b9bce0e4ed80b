#include "handheldpanel/HandheldsPanel.h"

#include "common/SideBySide.h"
#include "common/StellwerkSettings.h"
#include "connection/ConnectionHandhelds.h"
#include "handheldpanel/HandheldDetails.h"
#include "handheldpanel/HandheldTableModel.h"
#include "handheldpanel/OtherThrottles.h"
#include "handheldpanel/ThrottleTableModel.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "model/Railway.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

const QString ActAsMasterKey = QStringLiteral("mcanhandhelds/actAsMaster");

const mcanhandhelds::Handheld* inBootLoader(const HandheldTableModel& model) {
    for (const mcanhandhelds::Handheld& handheld : model.handhelds())
        if (handheld.state == mcanhandhelds::HandheldState::FlashMode)
            return &handheld;
    return nullptr;
}

} // namespace

HandheldsPanel::HandheldsPanel(QWidget* parent)
    : QWidget(parent), m_role(new QLabel(this)), m_actAsMaster(new QCheckBox(this)),
      m_bootLoader(new QLabel(this)), m_silence(new QPushButton(this)), m_view(new QTableView(this)),
      m_model(new HandheldTableModel(this)), m_details(new HandheldDetails(this)),
      m_otherSource(new OtherThrottles(this)), m_others(new ThrottleTableModel(this)),
      m_othersTitle(new QLabel(this)), m_othersView(new QTableView(this)),
      m_disconnect(new QPushButton(this)), m_othersClock(new QTimer(this)), m_kinds(new QTabWidget(this)) {
    setObjectName(QStringLiteral("handheldsPanel"));
    m_role->setObjectName(QStringLiteral("handheldRole"));
    m_role->setWordWrap(true);
    m_actAsMaster->setObjectName(QStringLiteral("actAsMaster"));
    m_actAsMaster->setChecked(stellwerkSettings().value(ActAsMasterKey, true).toBool());
    m_bootLoader->setObjectName(QStringLiteral("bootLoaderWarning"));
    m_bootLoader->setWordWrap(true);
    m_silence->setObjectName(QStringLiteral("silenceBootLoader"));
    m_view->setObjectName(QStringLiteral("handheldTable"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto* top = new QHBoxLayout;
    top->addWidget(m_role, 1);
    top->addWidget(m_actAsMaster);
    auto* warning = new QHBoxLayout;
    warning->addWidget(m_bootLoader, 1);
    warning->addWidget(m_silence);
    auto* parts = new QSplitter(this);
    parts->addWidget(m_view);
    parts->addWidget(m_details);
    parts->setStretchFactor(0, 3);
    parts->setStretchFactor(1, 2);
    parts->setChildrenCollapsible(false);
    auto* handhelds = new QWidget(this);
    auto* handheldsLayout = new QVBoxLayout(handhelds);
    handheldsLayout->setContentsMargins(0, 0, 0, 0);
    handheldsLayout->addLayout(top);
    handheldsLayout->addLayout(warning);
    handheldsLayout->addWidget(parts, 1);
    m_kinds->setObjectName(QStringLiteral("throttleKinds"));
    m_kinds->setDocumentMode(true);
    m_kinds->addTab(handhelds, QString());
    m_kinds->addTab(makeOthers(), QString());
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_kinds, 1);
    SideBySide::arrange(this, parts, 720);
    connect(m_actAsMaster, &QCheckBox::toggled, this, &HandheldsPanel::chooseRole);
    connect(m_model, &QAbstractItemModel::modelReset, this, &HandheldsPanel::updateDetails);
    connect(m_model, &QAbstractItemModel::dataChanged, this, &HandheldsPanel::updateDetails);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &HandheldsPanel::updateDetails);
    connect(m_details, &HandheldDetails::renameRequested, this, [this](quint32 uid, const QString& name) {
        if (m_master && !name.isEmpty())
            m_master->rename(uid, name);
    });
    connect(m_details, &HandheldDetails::stackChanged, this,
            [this](quint32 uid, const std::vector<std::uint32_t>& stack) {
                if (m_master)
                    m_master->setStack(uid, stack);
            });
    connect(m_silence, &QPushButton::clicked, this, [this] {
        if (const mcanhandhelds::Handheld* handheld = inBootLoader(*m_model); handheld && m_master)
            m_master->silenceBootLoader(handheld->uid);
    });
    m_model->setLocoName([this](std::uint32_t locId) {
        const model::Locomotive* loco = m_railway ? m_railway->locomotive(locId) : nullptr;
        return loco ? loco->displayName() : QString();
    });
    retranslate();
}

HandheldsPanel::~HandheldsPanel() = default;

// The other throttles: a title, their table, and the Disconnect button for the selected phone.
QWidget* HandheldsPanel::makeOthers() {
    m_othersTitle->setObjectName(QStringLiteral("otherThrottlesTitle"));
    m_othersTitle->setWordWrap(true);
    m_othersView->setObjectName(QStringLiteral("otherThrottleTable"));
    m_othersView->setModel(m_others);
    m_othersView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_othersView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_othersView->verticalHeader()->hide();
    m_othersView->horizontalHeader()->setStretchLastSection(true);
    m_othersView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_disconnect->setObjectName(QStringLiteral("disconnectThrottle"));
    auto* title = new QHBoxLayout;
    title->addWidget(m_othersTitle, 1);
    title->addWidget(m_disconnect);
    auto* others = new QWidget(this);
    auto* layout = new QVBoxLayout(others);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(title);
    layout->addWidget(m_othersView, 1);
    connect(m_otherSource, &OtherThrottles::changed, this, &HandheldsPanel::refreshOthers);
    connect(m_othersClock, &QTimer::timeout, this, &HandheldsPanel::refreshOthers);
    m_othersClock->setInterval(1000); // the last messages of clients that only send heartbeats
    m_othersClock->start();
    connect(m_othersView->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &HandheldsPanel::updateDisconnect);
    connect(m_others, &QAbstractItemModel::modelReset, this, &HandheldsPanel::updateDisconnect);
    connect(m_disconnect, &QPushButton::clicked, this, &HandheldsPanel::disconnectSelected);
    updateDisconnect();
    return others;
}

void HandheldsPanel::setPhoneServers(z21server::Z21Server* z21,
                                     withrottleserver::WiThrottleServer* withrottle) {
    m_otherSource->setServers(z21, withrottle);
}

// Keeps the selected throttle selected when rows come and go.
void HandheldsPanel::refreshOthers() {
    const QModelIndexList rows = m_othersView->selectionModel()->selectedRows();
    const ThrottleRow* selected = rows.isEmpty() ? nullptr : m_others->row(rows.first().row());
    const QString key = selected ? selected->key : QString();
    m_others->show(m_otherSource->rows());
    updateTabs();
    if (const int row = key.isEmpty() ? -1 : m_others->rowOf(key); row >= 0)
        m_othersView->selectRow(row);
    updateDisconnect();
}

void HandheldsPanel::updateDisconnect() {
    const QModelIndexList rows = m_othersView->selectionModel()->selectedRows();
    const ThrottleRow* selected = rows.isEmpty() ? nullptr : m_others->row(rows.first().row());
    m_disconnect->setEnabled(selected && selected->canDisconnect);
}

void HandheldsPanel::disconnectSelected() {
    const QModelIndexList rows = m_othersView->selectionModel()->selectedRows();
    if (const ThrottleRow* selected = rows.isEmpty() ? nullptr : m_others->row(rows.first().row()))
        m_otherSource->letGo(selected->key);
}

void HandheldsPanel::setHandhelds(connection::ConnectionHandhelds* handhelds) {
    if (m_handhelds)
        disconnect(m_handhelds, nullptr, this, nullptr);
    m_handhelds = handhelds;
    if (m_handhelds) {
        m_handhelds->setRole(m_actAsMaster->isChecked() ? connection::HandheldRole::Automatic
                                                        : connection::HandheldRole::Watch);
        connect(m_handhelds, &connection::ConnectionHandhelds::masterReplaced, this,
                &HandheldsPanel::attachMaster);
    }
    attachMaster();
}

// The master lives as long as one connection's session: a new one comes with each connection.
void HandheldsPanel::attachMaster() {
    mcanhandhelds::HandheldMaster* master = m_handhelds ? m_handhelds->master() : nullptr;
    if (master != m_master) {
        if (m_master)
            disconnect(m_master, nullptr, this, nullptr);
        m_master = master;
        if (m_master) {
            connect(m_master, &mcanhandhelds::HandheldMaster::handheldsChanged, this,
                    &HandheldsPanel::refresh);
            connect(m_master, &mcanhandhelds::HandheldMaster::masterChanged, this,
                    &HandheldsPanel::updateRole);
        }
    }
    refresh();
}

void HandheldsPanel::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    m_otherSource->setRailway(railway);
    if (m_railway) {
        connect(m_railway, &model::Railway::loaded, this, &HandheldsPanel::updateChoices);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    updateChoices();
}

void HandheldsPanel::refresh() {
    m_model->show(m_master ? m_master->handhelds() : std::vector<mcanhandhelds::Handheld>{});
    updateTabs();
    updateRole();
}

// Each tab says how many throttles it lists, so that a phone is seen from the MS1 tab too.
void HandheldsPanel::updateTabs() {
    m_kinds->setTabText(0, tr("MS1 handhelds (%1)").arg(m_model->rowCount()));
    m_kinds->setTabText(1, tr("Phones and other throttles (%1)").arg(m_others->rowCount()));
}

QString HandheldsPanel::roleText() const {
    if (!m_master)
        return tr("Not connected: no handhelds to show.");
    if (m_master->isMaster())
        return tr("Stellwerk is the master of the MS1 handhelds on this bus: plug one in to drive with it.");
    switch (m_master->watching()) {
    case mcanhandhelds::Watching::UntilDevicesKnown:
        return tr("Stellwerk waits until it knows the devices on the bus before it answers any handheld.");
    case mcanhandhelds::Watching::CentralStation:
        return tr("Stellwerk only watches the handhelds: the Central Station is their master.");
    case mcanhandhelds::Watching::AnotherMaster:
        if (m_master->otherMasterNode() == 0)
            return tr("Stellwerk only watches the handhelds: another master answers them.");
        return tr("Stellwerk only watches the handhelds: another master (node %1) answers them.")
            .arg(m_master->otherMasterNode());
    case mcanhandhelds::Watching::Asked:
    case mcanhandhelds::Watching::No:
        break;
    }
    return tr("Stellwerk only watches the handhelds, as chosen.");
}

void HandheldsPanel::updateRole() {
    m_role->setText(roleText());
    updateMasterChoice();
    const mcanhandhelds::Handheld* flashing = inBootLoader(*m_model);
    m_bootLoader->setVisible(flashing != nullptr);
    m_silence->setVisible(flashing != nullptr && m_master && m_master->isMaster());
    if (flashing)
        m_bootLoader->setText(
            tr("The handheld %1 sits in its boot loader: only a CS1 or an ECoS can flash it back to life. "
               "Stellwerk never sends it there and never flashes it.")
                .arg(flashing->uid, 8, 16, QLatin1Char('0')));
}

// While a Central Station or another master answers the handhelds, Stellwerk cannot be theirs: the choice
// shows off and cannot be made; the person's own choice is kept for a bus without another master.
void HandheldsPanel::updateMasterChoice() {
    const mcanhandhelds::Watching why = m_master ? m_master->watching() : mcanhandhelds::Watching::No;
    const bool otherMaster =
        why == mcanhandhelds::Watching::CentralStation || why == mcanhandhelds::Watching::AnotherMaster;
    const QSignalBlocker quiet(m_actAsMaster);
    m_actAsMaster->setEnabled(!otherMaster);
    m_actAsMaster->setChecked(!otherMaster && stellwerkSettings().value(ActAsMasterKey, true).toBool());
    m_actAsMaster->setToolTip(
        otherMaster ? tr("Another master answers the handhelds on this bus: Stellwerk only watches them")
                    : tr("Answer MS1 handhelds on the station's bus, unless a Central Station or another "
                         "master does; off: only watch them"));
}

void HandheldsPanel::updateDetails() {
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    const mcanhandhelds::Handheld* selected =
        rows.isEmpty() ? nullptr : m_model->handheld(rows.first().row());
    m_details->show(selected, m_master && m_master->isMaster());
    updateRole();
}

void HandheldsPanel::updateChoices() {
    std::vector<HandheldDetails::Choice> choices;
    if (m_railway)
        for (const model::Locomotive& loco : m_railway->state().locomotives().items())
            if (loco.inLayout())
                choices.push_back({loco.id().value(), loco.displayName()});
    m_details->setChoices(std::move(choices));
}

void HandheldsPanel::chooseRole(bool master) {
    stellwerkSettings().setValue(ActAsMasterKey, master);
    if (m_handhelds)
        m_handhelds->setRole(master ? connection::HandheldRole::Automatic : connection::HandheldRole::Watch);
    refresh();
}

void HandheldsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void HandheldsPanel::retranslate() {
    m_actAsMaster->setText(tr("Act as master for MS1 handhelds"));
    m_silence->setText(tr("Make it quiet"));
    m_silence->setToolTip(tr("Tell it to stop sending; it stays in its boot loader"));
    m_details->retranslate();
    m_othersTitle->setText(tr("Phones of the Z21 app and WLANmaus, Engine Driver and WiThrottle, and "
                              "OpenRailCAN throttles. Select a phone to disconnect it."));
    m_disconnect->setText(tr("Disconnect"));
    m_disconnect->setToolTip(tr("Let the selected phone go: its locomotives are stopped"));
    m_others->retranslate();
    updateTabs();
    updateRole();
}

} // namespace stellwerk::ui
