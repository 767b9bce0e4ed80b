#include "devices/DevicesPanel.h"

#include "common/SideBySide.h"
#include "common/StellwerkSettings.h"
#include "connection/ConnectionDevices.h"
#include "devices/BindingsDialog.h"
#include "devices/DeviceTableModel.h"
#include "devices/OrcDeviceView.h"
#include "devices/RoModuleDialog.h"
#include "devices/RoModuleView.h"
#include "model/Railway.h"
#include "model/RailwayDevices.h"
#include "orccentral/OrcSession.h"
#include "romodule/RoModuleSession.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableView>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

using connection::DeviceSettings;
using romodule::RoModuleSession;

constexpr std::uint8_t EncoderType = 3; // 001 §CAN-ID: CAN Enkoder

QStringList moduleNames(const DeviceSettings& devices) {
    QStringList names;
    for (const connection::RoModuleSettings& module : devices.roModules)
        names << QString::fromStdString(module.profile.name);
    return names;
}

// The module the simulator would answer as next: a sensible start for a new one.
connection::RoModuleSettings newModule(const DeviceSettings& devices) {
    connection::RoModuleSettings module;
    module.profile = ro::RoProfile::simulator(std::uint16_t(devices.roModules.size() + 1));
    module.profile.name.clear();
    return module;
}

} // namespace

DevicesPanel::DevicesPanel(QWidget* parent)
    : QWidget(parent), m_summary(new QLabel(this)), m_view(new QTableView(this)),
      m_model(new DeviceTableModel(this)), m_details(new QStackedWidget(this)), m_hint(new QLabel(m_details)),
      m_moduleView(new RoModuleView(m_details)), m_orcView(new OrcDeviceView(m_details)),
      m_add(new QPushButton(this)), m_edit(new QPushButton(this)), m_remove(new QPushButton(this)),
      m_bindings(new QPushButton(this)), m_note(new QLabel(this)) {
    setObjectName(QStringLiteral("devicesPanel"));
    m_summary->setObjectName(QStringLiteral("devicesSummary"));
    m_note->setObjectName(QStringLiteral("devicesNote"));
    m_view->setObjectName(QStringLiteral("deviceTable"));
    m_add->setObjectName(QStringLiteral("addModule"));
    m_edit->setObjectName(QStringLiteral("editModule"));
    m_remove->setObjectName(QStringLiteral("removeModule"));
    m_bindings->setObjectName(QStringLiteral("editBindings"));
    for (QLabel* label : {m_summary, m_note, m_hint})
        label->setWordWrap(true);
    m_note->setForegroundRole(QPalette::PlaceholderText);
    m_hint->setAlignment(Qt::AlignCenter);
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_details->addWidget(m_hint);
    m_details->addWidget(m_moduleView);
    m_details->addWidget(m_orcView);
    auto* parts = new QSplitter(this);
    parts->addWidget(m_view);
    parts->addWidget(m_details);
    parts->setStretchFactor(0, 3);
    parts->setStretchFactor(1, 2);
    parts->setChildrenCollapsible(false);
    // The buttons beside the summary: a bottom dock is short, and they must never scroll out of sight.
    auto* top = new QHBoxLayout;
    top->addWidget(m_summary, 1);
    for (QPushButton* button : {m_add, m_edit, m_remove, m_bindings})
        top->addWidget(button);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addWidget(m_note);
    layout->addWidget(parts, 1);
    SideBySide::arrange(this, parts, 720);
    connect(m_model, &QAbstractItemModel::modelReset, this, &DevicesPanel::updateDetails);
    connect(m_model, &QAbstractItemModel::dataChanged, this, &DevicesPanel::updateDetails);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &DevicesPanel::updateDetails);
    connect(m_add, &QPushButton::clicked, this, [this] { editModule(QString()); });
    connect(m_edit, &QPushButton::clicked, this, [this] { editModule(selectedModule()); });
    connect(m_remove, &QPushButton::clicked, this, &DevicesPanel::askRemove);
    connect(m_bindings, &QPushButton::clicked, this, &DevicesPanel::editBindings);
    retranslate();
}

DevicesPanel::~DevicesPanel() = default;

void DevicesPanel::setDevices(connection::ConnectionDevices* devices) {
    if (m_devices)
        m_devices->disconnect(this);
    m_devices = devices;
    m_model->setDevices(devices);
    if (devices)
        connect(devices, &connection::ConnectionDevices::devicesChanged, this, &DevicesPanel::attachSessions);
    attachSessions();
}

void DevicesPanel::setRailway(model::Railway* railway) {
    m_railway = railway;
    updateButtons();
}

// Follows the sessions there are now: their changes refresh the rows.
void DevicesPanel::attachSessions() {
    if (m_devices) {
        if (orccentral::OrcSession* orc = m_devices->orcSession())
            connect(orc, &orccentral::OrcSession::deviceChanged, this, &DevicesPanel::refresh,
                    Qt::UniqueConnection);
        for (RoModuleSession* module : m_devices->roModules())
            connect(module, &RoModuleSession::stateChanged, this, &DevicesPanel::refresh,
                    Qt::UniqueConnection);
    }
    refresh();
}

void DevicesPanel::refresh() {
    const DeviceTableModel::Row selected = m_view->currentIndex().isValid()
                                               ? m_model->rows()[std::size_t(m_view->currentIndex().row())]
                                               : DeviceTableModel::Row{};
    m_model->refresh();
    if (const int row = m_model->rowOf(selected); row >= 0 && m_view->currentIndex().row() != row)
        selectRow(row);
    else if (row < 0 && m_model->rowCount() > 0)
        selectRow(0); // something to look at rather than an empty half
    m_summary->setText(summaryText());
    m_note->setText(noteText());
    updateButtons();
}

void DevicesPanel::selectRow(int row) {
    m_view->selectRow(row);
    m_view->setCurrentIndex(m_model->index(row, 0));
}

void DevicesPanel::updateDetails() {
    const QModelIndex current = m_view->currentIndex();
    if (!m_devices || !current.isValid() || current.row() >= m_model->rowCount()) {
        m_details->setCurrentWidget(m_hint);
        updateButtons();
        return;
    }
    const DeviceTableModel::Row& row = m_model->rows()[std::size_t(current.row())];
    if (row.orc) {
        m_orcView->setDevice(m_devices->orcSession(), row.uid);
        m_details->setCurrentWidget(m_orcView);
    } else if (const connection::RoModuleSettings* settings = m_devices->active().roModule(row.module)) {
        m_moduleView->setModule(
            *settings, m_devices->roModule(row.module),
            m_model->data(m_model->index(current.row(), DeviceTableModel::State)).toString());
        m_details->setCurrentWidget(m_moduleView);
    }
    updateButtons();
}

void DevicesPanel::updateButtons() {
    m_add->setEnabled(m_devices != nullptr);
    const QString module = selectedModule();
    const bool saved = m_devices && m_devices->settings().roModule(module);
    m_edit->setEnabled(saved);
    m_remove->setEnabled(saved);
    m_bindings->setEnabled(railwayDevices() != nullptr);
}

QString DevicesPanel::selectedModule() const {
    const QModelIndex current = m_view->currentIndex();
    if (!current.isValid() || current.row() >= m_model->rowCount())
        return {};
    const DeviceTableModel::Row& row = m_model->rows()[std::size_t(current.row())];
    return row.orc ? QString() : row.module;
}

bool DevicesPanel::onDemo() const {
    return m_devices && m_devices->onLocalStation();
}

model::RailwayDevices* DevicesPanel::railwayDevices() const {
    return m_railway ? m_railway->findChild<model::RailwayDevices*>() : nullptr;
}

QString DevicesPanel::summaryText() const {
    if (!m_devices || !m_devices->isOpen())
        return tr("Not connected.");
    QStringList parts;
    const orccentral::OrcSession* orc = m_devices->orcSession();
    if (!m_devices->active().orc.on)
        parts << tr("OpenRailCAN: Stellwerk is not the central.");
    else if (!orc)
        parts << tr("OpenRailCAN: its bus is not connected.");
    else {
        const auto online = std::count_if(orc->devices().begin(), orc->devices().end(), [](const auto& d) {
            return d.state == orccentral::OrcDevice::State::Online;
        });
        parts
            << tr("OpenRailCAN: %1 of %n device(s) online.", nullptr, int(orc->devices().size())).arg(online);
    }
    const std::vector<RoModuleSession*> modules = m_devices->roModules();
    const auto online = std::count_if(modules.begin(), modules.end(), [](const RoModuleSession* m) {
        return m->state() == RoModuleSession::State::Online;
    });
    parts
        << tr("RO modules: %1 of %n online.", nullptr, int(m_devices->active().roModules.size())).arg(online);
    for (const QString& refusal : m_devices->refusals())
        parts << tr("Refused: %1.").arg(refusal);
    return parts.join(QLatin1Char(' '));
}

QString DevicesPanel::noteText() const {
    if (!m_devices)
        return {};
    if (onDemo())
        return tr("The demo station brings its own devices; modules you add are for your own station.");
    return tr("Modules you add or change are used from the next connection (Station ▸ Connect).");
}

RoModuleDialog* DevicesPanel::editModule(const QString& name) {
    if (!m_devices)
        return nullptr;
    const DeviceSettings& devices = m_devices->settings();
    const connection::RoModuleSettings* existing = devices.roModule(name);
    QStringList taken = moduleNames(devices);
    taken.removeAll(name);
    auto* dialog = new RoModuleDialog(existing ? *existing : newModule(devices), taken, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, name] { saveModule(name, *dialog); });
    dialog->open();
    return dialog;
}

void DevicesPanel::saveModule(const QString& oldName, const RoModuleDialog& dialog) {
    if (!m_devices || !dialog.problem().isEmpty())
        return;
    DeviceSettings devices = m_devices->settings();
    const std::string old = oldName.toStdString();
    const auto found = std::find_if(devices.roModules.begin(), devices.roModules.end(),
                                    [&](const auto& module) { return module.profile.name == old; });
    if (found != devices.roModules.end())
        *found = dialog.module();
    else
        devices.roModules.push_back(dialog.module());
    QSettings settings = stellwerkSettings();
    devices.save(settings);
    m_devices->setSettings(std::move(devices));
    refresh();
}

void DevicesPanel::askRemove() {
    const QString module = selectedModule();
    if (module.isEmpty())
        return;
    const auto answer = QMessageBox::question(
        this, tr("Remove RO module"),
        tr("Remove the module \"%1\" from the station settings? Its bindings stay until you remove them.")
            .arg(module));
    if (answer == QMessageBox::Yes)
        removeModule(module);
}

void DevicesPanel::removeModule(const QString& name) {
    if (!m_devices)
        return;
    DeviceSettings devices = m_devices->settings();
    const std::string wanted = name.toStdString();
    std::erase_if(devices.roModules, [&](const auto& module) { return module.profile.name == wanted; });
    QSettings settings = stellwerkSettings();
    devices.save(settings);
    m_devices->setSettings(std::move(devices));
    refresh();
}

BindingsDialog* DevicesPanel::editBindings() {
    model::RailwayDevices* devices = railwayDevices();
    if (!devices || !m_railway)
        return nullptr;
    BindingsDialog::Choices choices;
    if (m_devices) {
        choices.modules = moduleNames(m_devices->active());
        if (const orccentral::OrcSession* orc = m_devices->orcSession())
            for (const orccentral::OrcDevice& device : orc->devices()) {
                if (device.type == EncoderType)
                    choices.encoders.append(device.uid);
                else
                    choices.decoders.append(device.busId);
            }
    }
    choices.note = onDemo() ? tr("The demo's bindings: what you change here lasts until you connect again.")
                            : tr("Saved with the station settings.");
    auto* dialog = new BindingsDialog(devices->bindings(), *m_railway, std::move(choices), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { applyBindings(*dialog); });
    dialog->open();
    return dialog;
}

void DevicesPanel::applyBindings(const BindingsDialog& dialog) {
    model::RailwayDevices* devices = railwayDevices();
    if (!devices)
        return;
    devices->setBindings(dialog.bindings());
    if (!onDemo()) {
        QSettings settings = stellwerkSettings();
        dialog.bindings().save(settings);
    }
}

void DevicesPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void DevicesPanel::retranslate() {
    m_add->setText(tr("Add RO module…"));
    m_edit->setText(tr("Change…"));
    m_remove->setText(tr("Remove"));
    m_bindings->setText(tr("Bindings…"));
    m_hint->setText(tr("Choose a device to see its relays, outputs and inputs."));
    refresh();
}

} // namespace stellwerk::ui
