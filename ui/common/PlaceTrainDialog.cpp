#include "common/PlaceTrainDialog.h"

#include "model/Railway.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

namespace stellwerk::ui {
namespace {

void select(QComboBox* box, const QVariant& value) {
    if (const int index = box->findData(value); index >= 0)
        box->setCurrentIndex(index);
}

QComboBox* locomotivesOf(const model::Railway& railway, QWidget* parent) {
    auto* box = new QComboBox(parent);
    box->setObjectName(QStringLiteral("placeLocomotive"));
    std::vector<const model::Locomotive*> locomotives;
    for (const model::Locomotive& locomotive : railway.state().locomotives().items())
        locomotives.push_back(&locomotive);
    std::sort(locomotives.begin(), locomotives.end(), [](const auto* a, const auto* b) {
        return QString::localeAwareCompare(a->displayName(), b->displayName()) < 0;
    });
    for (const model::Locomotive* locomotive : locomotives)
        box->addItem(locomotive->displayName(), QVariant::fromValue(locomotive->id().value()));
    return box;
}

} // namespace

PlaceTrainDialog::PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph,
                                   const Choice& start, QWidget* parent)
    : QDialog(parent), m_graph(graph) {
    setObjectName(QStringLiteral("placeTrainDialog"));
    setWindowTitle(tr("Place a train"));
    m_locomotive = locomotivesOf(railway, this);
    select(m_locomotive, QVariant::fromValue(start.locId));
    m_block = new QComboBox(this);
    m_block->setObjectName(QStringLiteral("placeBlock"));
    for (const trackgraph::Block& block : graph.blocks())
        m_block->addItem(QString::fromStdString(block.name), block.id);
    select(m_block, start.block);
    m_end = new QComboBox(this);
    m_end->setObjectName(QStringLiteral("placeEnd"));
    m_length = new QSpinBox(this);
    m_length->setObjectName(QStringLiteral("placeLength"));
    m_length->setRange(20, 5000);
    m_length->setSingleStep(10);
    m_length->setSuffix(tr(" mm"));
    m_length->setValue(start.lengthMm);
    m_pushPull = new QCheckBox(tr("May change direction in any block (push-pull)"), this);
    m_pushPull->setChecked(start.pushPull);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Place"));
    buttons->button(QDialogButtonBox::Ok)->setEnabled(m_locomotive->count() > 0 && m_block->count() > 0);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* form = new QFormLayout;
    form->addRow(tr("Locomotive:"), m_locomotive);
    form->addRow(tr("Block:"), m_block);
    form->addRow(tr("Its front faces:"), m_end);
    form->addRow(tr("Length:"), m_length);
    form->addRow(QString(), m_pushPull);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addLayout(form);
    layout->addWidget(buttons);
    connect(m_block, &QComboBox::currentIndexChanged, this, &PlaceTrainDialog::blockChosen);
    blockChosen();
    setTowards(start.towards);
}

// The ends are told by what lies beyond them in the block chosen, and the user where to put the train.
void PlaceTrainDialog::blockChosen() {
    const int block = m_block->currentData().toInt();
    const QVariant end = m_end->currentData();
    m_end->clear();
    if (block <= 0) {
        m_intro->clear();
        return;
    }
    for (const trackgraph::End each : {trackgraph::End::B, trackgraph::End::A})
        m_end->addItem(
            tr("End %1, %2")
                .arg(QString::fromLatin1(trackgraph::endName(each).data()), beyond(m_graph, block, each)),
            int(each));
    select(m_end, end);
    m_intro->setText(tr("The train is tracked from here on: put it on the track in %1 first.")
                         .arg(QString::fromStdString(m_graph.block(block).name)));
}

PlaceTrainDialog::Choice PlaceTrainDialog::choice() const {
    return {m_locomotive->currentData().value<std::uint32_t>(), m_block->currentData().toInt(),
            trackgraph::End(m_end->currentData().toInt()), m_length->value(), m_pushPull->isChecked()};
}

bool PlaceTrainDialog::chooseLocomotive(std::uint32_t locId) {
    const int index = m_locomotive->findData(QVariant::fromValue(locId));
    if (index >= 0)
        m_locomotive->setCurrentIndex(index);
    return index >= 0;
}

void PlaceTrainDialog::setTowards(trackgraph::End end) {
    select(m_end, int(end));
}

void PlaceTrainDialog::setLengthMm(int lengthMm) {
    m_length->setValue(lengthMm);
}

QString PlaceTrainDialog::beyond(const trackgraph::TrackGraph& graph, int block, trackgraph::End end) {
    QStringList next;
    for (const int id : graph.connectionsFrom(trackgraph::BlockEnd{block, end})) {
        const QString name = QString::fromStdString(graph.block(graph.connection(id).to.block).name);
        if (!next.contains(name))
            next << name;
    }
    if (!next.isEmpty())
        return tr("towards %1").arg(next.join(tr(" or ")));
    switch (graph.block(block).end(end).beyond) {
    case trackgraph::EndKind::BufferStop:
        return tr("towards a buffer stop");
    case trackgraph::EndKind::Turntable:
        return tr("towards a turntable");
    default:
        return tr("towards the end of the track");
    }
}

} // namespace stellwerk::ui
