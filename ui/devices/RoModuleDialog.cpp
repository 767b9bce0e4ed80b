#include "devices/RoModuleDialog.h"

#include "devices/HexText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QVBoxLayout>

namespace stellwerk::ui {
namespace {

constexpr int MaximumBus = 8;

QLineEdit* hexField(QWidget* parent) {
    auto* field = new QLineEdit(parent);
    field->setValidator(new QRegularExpressionValidator(
        QRegularExpression(QStringLiteral("(0[xX])?[0-9A-Fa-f]{1,8}")), field));
    field->setPlaceholderText(QStringLiteral("0x…"));
    return field;
}

} // namespace

RoModuleDialog::RoModuleDialog(const connection::RoModuleSettings& module, QStringList takenNames,
                               QWidget* parent)
    : QDialog(parent), m_taken(std::move(takenNames)), m_name(new QLineEdit(this)), m_bus(new QSpinBox(this)),
      m_format(new QComboBox(this)), m_requestId(hexField(this)), m_answerId(hexField(this)),
      m_outputs(blockFields(module.profile.outputs)), m_inputs(blockFields(module.profile.inputs)),
      m_hasFlags(new QCheckBox(tr("Change flags at"), this)),
      m_flags(blockFields(module.profile.changeFlags.value_or(ro::RegisterBlock{}))),
      m_poll(new QSpinBox(this)), m_problem(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("roModuleDialog"));
    setWindowTitle(module.profile.name.empty() ? tr("Add RO module") : tr("Edit RO module"));
    m_name->setObjectName(QStringLiteral("moduleName"));
    m_requestId->setObjectName(QStringLiteral("requestId"));
    m_answerId->setObjectName(QStringLiteral("answerId"));
    m_problem->setObjectName(QStringLiteral("moduleProblem"));
    m_problem->setWordWrap(true);
    m_bus->setRange(0, MaximumBus);
    m_bus->setSpecialValueText(tr("0 (the station's bus)"));
    m_format->addItem(tr("29-bit (extended)"), true);
    m_format->addItem(tr("11-bit (standard, CAN adapters only)"), false);
    m_poll->setRange(50, 10000);
    m_poll->setSingleStep(50);
    m_poll->setSuffix(tr(" ms"));
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Bus"), m_bus);
    form->addRow(tr("Frames"), m_format);
    form->addRow(tr("Request id"), m_requestId);
    form->addRow(tr("Answer id"), m_answerId);
    form->addRow(tr("Relays at"), blockRow(m_outputs));
    form->addRow(tr("Inputs at"), blockRow(m_inputs));
    form->addRow(m_hasFlags, blockRow(m_flags));
    form->addRow(tr("Read inputs every"), m_poll);
    auto* note = new QLabel(tr("RO modules name no ids and no register map; take them from the module's "
                               "manual or its switches. The user guide (Help) lists Stellwerk's defaults."),
                            this);
    note->setWordWrap(true);
    note->setForegroundRole(QPalette::PlaceholderText);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    fill(module);
    for (QLineEdit* field :
         {m_name, m_requestId, m_answerId, m_outputs.address, m_inputs.address, m_flags.address})
        connect(field, &QLineEdit::textChanged, this, &RoModuleDialog::check);
    for (QComboBox* box : {m_format, m_outputs.width, m_inputs.width, m_flags.width})
        connect(box, &QComboBox::currentIndexChanged, this, &RoModuleDialog::check);
    for (QSpinBox* box : {m_bus, m_outputs.count, m_inputs.count, m_flags.count, m_poll})
        connect(box, &QSpinBox::valueChanged, this, &RoModuleDialog::check);
    connect(m_hasFlags, &QCheckBox::toggled, this, &RoModuleDialog::check);
    check();
}

RoModuleDialog::BlockFields RoModuleDialog::blockFields(const ro::RegisterBlock& block) {
    BlockFields fields{hexField(this), new QComboBox(this), new QSpinBox(this)};
    fields.address->setText(hexText::of(block.address));
    for (const ro::Width width : {ro::Width::Byte, ro::Width::Word, ro::Width::Long})
        fields.width->addItem(QString::fromUtf8(ro::widthName(width).data()), int(width));
    fields.width->setCurrentIndex(std::max(0, fields.width->findData(int(block.width))));
    fields.count->setRange(0, 32);
    fields.count->setValue(block.count);
    return fields;
}

QWidget* RoModuleDialog::blockRow(const BlockFields& fields) {
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(fields.address, 1);
    layout->addWidget(fields.width);
    layout->addWidget(new QLabel(tr("count"), row));
    layout->addWidget(fields.count);
    return row;
}

void RoModuleDialog::fill(const connection::RoModuleSettings& module) {
    m_name->setText(QString::fromStdString(module.profile.name));
    m_bus->setValue(module.bus);
    m_format->setCurrentIndex(module.profile.ids.extended ? 0 : 1);
    m_requestId->setText(hexText::of(module.profile.ids.request));
    m_answerId->setText(hexText::of(module.profile.ids.answer));
    m_hasFlags->setChecked(module.profile.changeFlags.has_value());
    m_poll->setValue(int(module.pollPeriod.count()));
}

connection::RoModuleSettings RoModuleDialog::module() const {
    const auto block = [](const BlockFields& fields) {
        return ro::RegisterBlock{std::uint16_t(hexText::read(fields.address->text()).value_or(0)),
                                 ro::Width(fields.width->currentData().toInt()),
                                 std::uint8_t(fields.count->value())};
    };
    connection::RoModuleSettings module;
    module.profile.name = m_name->text().trimmed().toStdString();
    module.profile.ids = {hexText::read(m_requestId->text()).value_or(0),
                          hexText::read(m_answerId->text()).value_or(0), m_format->currentData().toBool()};
    module.profile.outputs = block(m_outputs);
    module.profile.inputs = block(m_inputs);
    if (m_hasFlags->isChecked())
        module.profile.changeFlags = block(m_flags);
    module.bus = m_bus->value();
    module.pollPeriod = std::chrono::milliseconds(m_poll->value());
    return module;
}

QString RoModuleDialog::problem() const {
    const QString name = m_name->text().trimmed();
    if (name.isEmpty())
        return tr("The module needs a name.");
    if (m_taken.contains(name))
        return tr("Another module is called \"%1\".").arg(name);
    for (const QLineEdit* field :
         {m_requestId, m_answerId, m_outputs.address, m_inputs.address, m_flags.address})
        if (!hexText::read(field->text()) && (field != m_flags.address || m_hasFlags->isChecked()))
            return tr("Every id and address is a hexadecimal number.");
    if (hexText::read(m_outputs.address->text()) > 0xFFFFu ||
        hexText::read(m_inputs.address->text()) > 0xFFFFu ||
        (m_hasFlags->isChecked() && hexText::read(m_flags.address->text()) > 0xFFFFu))
        return tr("Register addresses go up to 0xFFFF.");
    const std::string why = module().profile.problem();
    return why.empty() ? QString() : tr("The module cannot be used so: %1").arg(QString::fromStdString(why));
}

void RoModuleDialog::check() {
    m_flags.address->setEnabled(m_hasFlags->isChecked());
    m_flags.width->setEnabled(m_hasFlags->isChecked());
    m_flags.count->setEnabled(m_hasFlags->isChecked());
    const QString why = problem();
    m_problem->setText(why);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

} // namespace stellwerk::ui
