#include "handheldpanel/HandheldDetails.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace stellwerk::ui {

HandheldDetails::HandheldDetails(QWidget* parent)
    : QGroupBox(parent), m_name(new QLineEdit(this)), m_rename(new QPushButton(this)),
      m_stack(new QListWidget(this)), m_add(new QComboBox(this)), m_addButton(new QPushButton(this)),
      m_remove(new QPushButton(this)), m_up(new QPushButton(this)), m_down(new QPushButton(this)) {
    setObjectName(QStringLiteral("handheldDetails"));
    m_name->setObjectName(QStringLiteral("handheldName"));
    m_name->setMaxLength(16); // an MS1 shows 16 characters
    m_rename->setObjectName(QStringLiteral("renameHandheld"));
    m_stack->setObjectName(QStringLiteral("handheldStack"));
    m_add->setObjectName(QStringLiteral("stackChoice"));
    m_addButton->setObjectName(QStringLiteral("addToStack"));
    m_remove->setObjectName(QStringLiteral("removeFromStack"));
    auto* nameRow = new QHBoxLayout;
    nameRow->addWidget(m_name, 1);
    nameRow->addWidget(m_rename);
    auto* addRow = new QHBoxLayout;
    addRow->addWidget(m_add, 1);
    addRow->addWidget(m_addButton);
    auto* order = new QHBoxLayout;
    order->addWidget(m_remove);
    order->addWidget(m_up);
    order->addWidget(m_down);
    order->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(nameRow);
    layout->addWidget(m_stack, 1);
    layout->addLayout(order);
    layout->addLayout(addRow);
    connect(m_rename, &QPushButton::clicked, this,
            [this] { emit renameRequested(m_uid, m_name->text().trimmed()); });
    connect(m_name, &QLineEdit::returnPressed, m_rename, &QPushButton::click);
    connect(m_addButton, &QPushButton::clicked, this, [this] {
        std::vector<std::uint32_t> changed = stack();
        changed.push_back(m_add->currentData().toUInt());
        changeStack(changed);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        std::vector<std::uint32_t> changed = stack();
        changed.erase(changed.begin() + m_stack->currentRow());
        changeStack(changed);
    });
    connect(m_up, &QPushButton::clicked, this, [this] { move(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { move(1); });
    connect(m_stack, &QListWidget::currentRowChanged, this, &HandheldDetails::updateButtons);
    connect(m_add, &QComboBox::currentIndexChanged, this, &HandheldDetails::updateButtons);
    retranslate();
    show(nullptr, false);
}

void HandheldDetails::retranslate() {
    setTitle(tr("Selected handheld"));
    m_name->setPlaceholderText(tr("Name, up to 16 characters"));
    m_rename->setText(tr("Rename"));
    m_rename->setToolTip(tr("Send the name to the handheld; it shows it from now on"));
    m_addButton->setText(tr("Add"));
    m_remove->setText(tr("Remove"));
    m_up->setText(tr("Up"));
    m_down->setText(tr("Down"));
    m_stack->setToolTip(
        tr("The locomotives the handheld offers, in its order; remembered for this handheld"));
}

void HandheldDetails::show(const mcanhandhelds::Handheld* handheld, bool changeable) {
    const bool other = !handheld || handheld->uid != m_uid;
    m_uid = handheld ? handheld->uid : 0;
    m_stackSize = handheld ? handheld->stackSize : 10;
    m_changeable = handheld && changeable && handheld->ours &&
                   handheld->state != mcanhandhelds::HandheldState::FlashMode;
    if (other || !m_name->hasFocus())
        m_name->setText(handheld ? handheld->name : QString());
    fillStack(handheld ? handheld->stack : std::vector<std::uint32_t>{});
    setEnabled(handheld != nullptr);
    updateButtons();
}

void HandheldDetails::setChoices(std::vector<Choice> choices) {
    m_choices = std::move(choices);
    m_add->clear();
    for (const Choice& choice : m_choices)
        m_add->addItem(choice.name, choice.locId);
    fillStack(stack());
    updateButtons();
}

QString HandheldDetails::nameOf(std::uint32_t locId) const {
    for (const Choice& choice : m_choices)
        if (choice.locId == locId)
            return choice.name;
    return tr("Loc-ID 0x%1").arg(locId, 4, 16, QLatin1Char('0'));
}

std::vector<std::uint32_t> HandheldDetails::stack() const {
    std::vector<std::uint32_t> locIds;
    for (int row = 0; row < m_stack->count(); ++row)
        locIds.push_back(m_stack->item(row)->data(Qt::UserRole).toUInt());
    return locIds;
}

void HandheldDetails::fillStack(const std::vector<std::uint32_t>& locIds) {
    if (locIds == stack()) {
        for (int row = 0; row < m_stack->count(); ++row) // names may have come meanwhile
            m_stack->item(row)->setText(nameOf(locIds[std::size_t(row)]));
        return;
    }
    const int current = m_stack->currentRow();
    m_stack->clear();
    for (const std::uint32_t locId : locIds) {
        auto* item = new QListWidgetItem(nameOf(locId), m_stack);
        item->setData(Qt::UserRole, locId);
    }
    m_stack->setCurrentRow(std::min(current, m_stack->count() - 1));
}

void HandheldDetails::changeStack(std::vector<std::uint32_t> locIds) {
    fillStack(locIds);
    updateButtons();
    emit stackChanged(m_uid, locIds);
}

void HandheldDetails::move(int by) {
    const int row = m_stack->currentRow();
    std::vector<std::uint32_t> locIds = stack();
    if (row < 0 || row + by < 0 || row + by >= int(locIds.size()))
        return;
    std::swap(locIds[std::size_t(row)], locIds[std::size_t(row + by)]);
    changeStack(locIds);
    m_stack->setCurrentRow(row + by);
}

void HandheldDetails::updateButtons() {
    const int row = m_stack->currentRow();
    const std::vector<std::uint32_t> locIds = stack();
    const bool full = int(locIds.size()) >= m_stackSize;
    const std::uint32_t chosen = m_add->currentData().toUInt();
    const bool onStack = std::find(locIds.begin(), locIds.end(), chosen) != locIds.end();
    m_name->setEnabled(m_changeable);
    m_rename->setEnabled(m_changeable);
    m_add->setEnabled(m_changeable && !full);
    m_addButton->setEnabled(m_changeable && !full && m_add->count() > 0 && !onStack);
    m_remove->setEnabled(m_changeable && row >= 0);
    m_up->setEnabled(m_changeable && row > 0);
    m_down->setEnabled(m_changeable && row >= 0 && row + 1 < int(locIds.size()));
    m_addButton->setToolTip(full ? tr("The stack is full (%1 locomotives)").arg(m_stackSize) : QString());
}

} // namespace stellwerk::ui
