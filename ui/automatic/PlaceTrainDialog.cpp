#include "automatic/PlaceTrainDialog.h"

#include "model/Railway.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace stellwerk::ui {

namespace {

void select(QComboBox* box, const QVariant& value) {
    if (const int index = box->findData(value); index >= 0)
        box->setCurrentIndex(index);
}

} // namespace

PlaceTrainDialog::PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph,
                                   const Choice& start, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("placeTrainDialog"));
    setWindowTitle(tr("Place a train"));
    m_locomotive = new QComboBox(this);
    for (const model::Locomotive& loco : railway.state().locomotives().items())
        m_locomotive->addItem(loco.displayName(), QVariant::fromValue(loco.id().value()));
    select(m_locomotive, QVariant::fromValue(start.locId));
    m_block = new QComboBox(this);
    for (const trackgraph::Block& block : graph.blocks())
        m_block->addItem(QString::fromStdString(block.name), block.id);
    select(m_block, start.block);
    m_end = new QComboBox(this);
    m_end->addItem(tr("End A"), int(trackgraph::End::A));
    m_end->addItem(tr("End B"), int(trackgraph::End::B));
    select(m_end, int(start.towards));
    m_length = new QSpinBox(this);
    m_length->setRange(20, 5000);
    m_length->setSingleStep(10);
    m_length->setSuffix(tr(" mm"));
    m_length->setValue(start.lengthMm);
    m_pushPull = new QCheckBox(tr("May change direction in any block (push-pull)"), this);
    m_pushPull->setChecked(start.pushPull);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Place"));
    buttons->button(QDialogButtonBox::Ok)->setEnabled(m_locomotive->count() > 0 && m_block->count() > 0);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* form = new QFormLayout(this);
    form->addRow(tr("Locomotive:"), m_locomotive);
    form->addRow(tr("Block:"), m_block);
    form->addRow(tr("Its front faces:"), m_end);
    form->addRow(tr("Length:"), m_length);
    form->addRow(QString(), m_pushPull);
    form->addRow(buttons);
}

PlaceTrainDialog::Choice PlaceTrainDialog::choice() const {
    return {m_locomotive->currentData().value<std::uint32_t>(), m_block->currentData().toInt(),
            trackgraph::End(m_end->currentData().toInt()), m_length->value(), m_pushPull->isChecked()};
}

} // namespace stellwerk::ui
