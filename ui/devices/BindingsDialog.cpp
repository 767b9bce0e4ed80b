#include "devices/BindingsDialog.h"

#include "devices/HexText.h"
#include "model/Railway.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <functional>

namespace stellwerk::ui {
namespace {

using model::AccessoryBinding;
using model::ContactBinding;

enum OutputKind { RoRelay, OrcOutput, OrcPosition };
enum InputKind { RoInput, OrcInput };

QTableWidget* bindingTable(QWidget* parent, const QString& name) {
    auto* table = new QTableWidget(0, 2, parent);
    table->setObjectName(name);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->hide();
    table->horizontalHeader()->setStretchLastSection(true);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    return table;
}

} // namespace

BindingsDialog::BindingsDialog(model::DeviceBindings bindings, const model::Railway& railway, Choices choices,
                               QWidget* parent)
    : QDialog(parent), m_bindings(std::move(bindings)), m_railway(railway), m_choices(std::move(choices)),
      m_accessories(bindingTable(this, QStringLiteral("accessoryBindings"))),
      m_accessory(new QComboBox(this)), m_outputKind(new QComboBox(this)),
      m_outputSource(new QComboBox(this)), m_outputNumber(new QSpinBox(this)),
      m_contacts(bindingTable(this, QStringLiteral("contactBindings"))), m_contact(new QComboBox(this)),
      m_inputKind(new QComboBox(this)), m_inputSource(new QComboBox(this)), m_inputNumber(new QSpinBox(this)),
      m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("bindingsDialog"));
    setWindowTitle(tr("Device bindings"));
    m_accessories->setHorizontalHeaderLabels({tr("Article"), tr("Switched by")});
    m_contacts->setHorizontalHeaderLabels({tr("Contact"), tr("Lit by")});
    m_problem->setObjectName(QStringLiteral("bindingProblem"));
    m_problem->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Articles switched by a device instead of the station"), this));
    layout->addWidget(m_accessories, 1);
    layout->addWidget(accessoryLine());
    layout->addWidget(new QLabel(tr("Contacts lit by a device instead of an S88 module"), this));
    layout->addWidget(m_contacts, 1);
    layout->addWidget(contactLine());
    layout->addWidget(m_problem);
    auto* note = new QLabel(m_choices.note, this);
    note->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(note);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    fillTables();
    resize(760, 560);
}

QWidget* BindingsDialog::accessoryLine() {
    for (const model::Accessory& accessory : m_railway.state().accessories().items())
        m_accessory->addItem(accessoryName(accessory.id()), qint64(accessory.id()));
    m_outputKind->addItem(tr("RO relay"), RoRelay);
    m_outputKind->addItem(tr("OpenRailCAN decoder output"), OrcOutput);
    m_outputKind->addItem(tr("OpenRailCAN decoder (its position)"), OrcPosition);
    connect(m_outputKind, &QComboBox::currentIndexChanged, this, &BindingsDialog::outputKindChanged);
    outputKindChanged();
    return bindingLine(
        {m_accessory, m_outputKind, m_outputSource, m_outputNumber}, QStringLiteral("addAccessoryBinding"),
        [this] { addAccessory(); }, [this] { removeSelected(m_accessories); });
}

QWidget* BindingsDialog::contactLine() {
    for (const model::FeedbackContact& contact : m_railway.state().contacts().items())
        m_contact->addItem(contactName(contact.key()), quint32(contact.key()));
    m_inputKind->addItem(tr("RO input"), RoInput);
    m_inputKind->addItem(tr("OpenRailCAN encoder input"), OrcInput);
    connect(m_inputKind, &QComboBox::currentIndexChanged, this, &BindingsDialog::inputKindChanged);
    inputKindChanged();
    return bindingLine(
        {m_contact, m_inputKind, m_inputSource, m_inputNumber}, QStringLiteral("addContactBinding"),
        [this] { addContact(); }, [this] { removeSelected(m_contacts); });
}

// One line under a list: what is bound, the kind of device, which device (typed or chosen) and the
// number on it, then Add and Remove.
QWidget* BindingsDialog::bindingLine(const LineFields& fields, const QString& addName,
                                     const std::function<void()>& add, const std::function<void()>& remove) {
    fields.source->setEditable(true);
    auto* line = new QWidget(this);
    auto* row = new QHBoxLayout(line);
    row->setContentsMargins(0, 0, 0, 0);
    auto* addButton = new QPushButton(tr("Add"), line);
    addButton->setObjectName(addName);
    auto* removeButton = new QPushButton(tr("Remove"), line);
    row->addWidget(fields.item, 1);
    row->addWidget(fields.kind);
    row->addWidget(fields.source, 1);
    row->addWidget(fields.number);
    row->addWidget(addButton);
    row->addWidget(removeButton);
    connect(addButton, &QPushButton::clicked, this, add);
    connect(removeButton, &QPushButton::clicked, this, remove);
    return line;
}

void BindingsDialog::outputKindChanged() {
    const int kind = m_outputKind->currentData().toInt();
    m_outputSource->clear();
    if (kind == RoRelay)
        m_outputSource->addItems(m_choices.modules);
    else
        for (const std::uint16_t decoder : m_choices.decoders)
            m_outputSource->addItem(hexText::of(decoder, 4));
    m_outputSource->setToolTip(kind == RoRelay ? tr("The module's name")
                                               : tr("The decoder's bus id (Ziel-Id)"));
    m_outputNumber->setVisible(kind != OrcPosition);
    m_outputNumber->setRange(kind == RoRelay ? 1 : 0, kind == RoRelay ? 32 : 7);
    m_outputNumber->setPrefix(kind == RoRelay ? tr("relay ") : tr("output "));
}

void BindingsDialog::inputKindChanged() {
    const int kind = m_inputKind->currentData().toInt();
    m_inputSource->clear();
    if (kind == RoInput)
        m_inputSource->addItems(m_choices.modules);
    else
        for (const std::uint32_t encoder : m_choices.encoders)
            m_inputSource->addItem(hexText::of(encoder, 8));
    m_inputSource->setToolTip(kind == RoInput ? tr("The module's name") : tr("The encoder's UID"));
    m_inputNumber->setRange(kind == RoInput ? 1 : 0, kind == RoInput ? 32 : 31);
    m_inputNumber->setPrefix(tr("input "));
}

bool BindingsDialog::addAccessory() {
    const QString source = m_outputSource->currentText().trimmed();
    if (m_accessory->currentIndex() < 0 || source.isEmpty()) {
        refuse(tr("Choose an article and the module or decoder that switches it."));
        return false;
    }
    AccessoryBinding binding{m_accessory->currentData().toLongLong(), {}};
    const int kind = m_outputKind->currentData().toInt();
    if (kind == RoRelay) {
        binding.output = model::RoRelay{source, m_outputNumber->value()};
    } else {
        const std::optional<std::uint32_t> target = hexText::read(source);
        if (!target || *target > 0xFFFF) {
            refuse(tr("\"%1\" is no bus id: write it in hexadecimal, 0x0000 to 0xFFFF.").arg(source));
            return false;
        }
        binding.output = model::OrcOutput{
            std::uint16_t(*target),
            kind == OrcOutput ? std::optional(std::uint8_t(m_outputNumber->value())) : std::nullopt};
    }
    std::erase_if(m_bindings.accessories,
                  [&](const AccessoryBinding& b) { return b.accessory == binding.accessory; });
    m_bindings.accessories.push_back(binding);
    refuse(QString());
    fillTables();
    return true;
}

bool BindingsDialog::addContact() {
    const QString source = m_inputSource->currentText().trimmed();
    if (m_contact->currentIndex() < 0 || source.isEmpty()) {
        refuse(tr("Choose a contact and the module or encoder that lights it."));
        return false;
    }
    ContactBinding binding{model::ContactKey(m_contact->currentData().toUInt()), {}};
    if (m_inputKind->currentData().toInt() == RoInput) {
        binding.input = model::RoInput{source, m_inputNumber->value()};
    } else {
        const std::optional<std::uint32_t> uid = hexText::read(source);
        if (!uid) {
            refuse(tr("\"%1\" is no UID: write it in hexadecimal.").arg(source));
            return false;
        }
        binding.input = model::OrcInput{*uid, m_inputNumber->value()};
    }
    std::erase_if(m_bindings.contacts, [&](const ContactBinding& b) { return b.contact == binding.contact; });
    m_bindings.contacts.push_back(binding);
    refuse(QString());
    fillTables();
    return true;
}

void BindingsDialog::fillTables() {
    m_accessories->setRowCount(int(m_bindings.accessories.size()));
    for (int row = 0; row < m_accessories->rowCount(); ++row) {
        const AccessoryBinding& binding = m_bindings.accessories[std::size_t(row)];
        m_accessories->setItem(row, 0, new QTableWidgetItem(accessoryName(binding.accessory)));
        m_accessories->setItem(row, 1, new QTableWidgetItem(describe(binding)));
    }
    m_contacts->setRowCount(int(m_bindings.contacts.size()));
    for (int row = 0; row < m_contacts->rowCount(); ++row) {
        const ContactBinding& binding = m_bindings.contacts[std::size_t(row)];
        m_contacts->setItem(row, 0, new QTableWidgetItem(contactName(binding.contact)));
        m_contacts->setItem(row, 1, new QTableWidgetItem(describe(binding)));
    }
}

void BindingsDialog::removeSelected(QTableWidget* table) {
    const int row = table->currentRow();
    if (row < 0)
        return;
    if (table == m_accessories)
        m_bindings.accessories.erase(m_bindings.accessories.begin() + row);
    else
        m_bindings.contacts.erase(m_bindings.contacts.begin() + row);
    fillTables();
}

QString BindingsDialog::accessoryName(std::int64_t id) const {
    const model::Accessory* accessory = m_railway.accessory(id);
    return accessory && !accessory->name().isEmpty() ? tr("%1 %2").arg(id).arg(accessory->name())
                                                     : QString::number(id);
}

QString BindingsDialog::contactName(model::ContactKey key) const {
    return tr("module %1, contact %2").arg(key >> 16).arg(key & 0xFFFF);
}

QString BindingsDialog::describe(const AccessoryBinding& binding) {
    if (const auto* relay = std::get_if<model::RoRelay>(&binding.output))
        return tr("relay %1 of “%2”").arg(relay->relay).arg(relay->module);
    const auto& output = std::get<model::OrcOutput>(binding.output);
    return output.output ? tr("OpenRailCAN decoder %1, output %2")
                               .arg(hexText::of(output.target, 4))
                               .arg(*output.output)
                         : tr("OpenRailCAN decoder %1 (its position)").arg(hexText::of(output.target, 4));
}

QString BindingsDialog::describe(const ContactBinding& binding) {
    if (const auto* input = std::get_if<model::RoInput>(&binding.input))
        return tr("input %1 of “%2”").arg(input->input).arg(input->module);
    const auto& input = std::get<model::OrcInput>(binding.input);
    return tr("OpenRailCAN encoder %1, input %2").arg(hexText::of(input.encoderUid, 8)).arg(input.input);
}

QString BindingsDialog::problem() const {
    return m_problem->text();
}

void BindingsDialog::refuse(const QString& why) {
    m_problem->setText(why);
}

} // namespace stellwerk::ui
