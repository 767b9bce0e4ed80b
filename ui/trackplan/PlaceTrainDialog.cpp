#include "trackplan/PlaceTrainDialog.h"

#include "model/Railway.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int DefaultLengthMm = 200; // lokomotive.cs2 says no length: a locomotive of H0

} // namespace

PlaceTrainDialog::PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph,
                                   int block, QWidget* parent)
    : QDialog(parent), m_block(block) {
    setObjectName(QStringLiteral("placeTrainDialog"));
    const QString name = QString::fromStdString(graph.block(block).name);
    setWindowTitle(tr("Place a train in %1").arg(name));
    m_locomotive = new QComboBox(this);
    m_locomotive->setObjectName(QStringLiteral("placeLocomotive"));
    std::vector<const model::Locomotive*> locomotives;
    for (const model::Locomotive& locomotive : railway.state().locomotives().items())
        locomotives.push_back(&locomotive);
    std::sort(locomotives.begin(), locomotives.end(), [](const auto* a, const auto* b) {
        return QString::localeAwareCompare(a->displayName(), b->displayName()) < 0;
    });
    for (const model::Locomotive* locomotive : locomotives)
        m_locomotive->addItem(locomotive->displayName(), locomotive->id().value());
    m_end = new QComboBox(this);
    m_end->setObjectName(QStringLiteral("placeEnd"));
    for (const trackgraph::End end : {trackgraph::End::B, trackgraph::End::A})
        m_end->addItem(
            tr("End %1, %2")
                .arg(QString::fromLatin1(trackgraph::endName(end).data()), beyond(graph, block, end)),
            int(end));
    m_length = new QSpinBox(this);
    m_length->setObjectName(QStringLiteral("placeLength"));
    m_length->setRange(50, 5000);
    m_length->setSingleStep(10);
    m_length->setSuffix(tr(" mm"));
    m_length->setValue(DefaultLengthMm);
    auto* form = new QFormLayout;
    form->addRow(tr("Locomotive:"), m_locomotive);
    form->addRow(tr("Facing:"), m_end);
    form->addRow(tr("Length:"), m_length);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Place"));
    buttons->button(QDialogButtonBox::Ok)->setEnabled(m_locomotive->count() > 0);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    auto* intro =
        new QLabel(tr("The train is tracked from here on: put it on the track in %1 first.").arg(name), this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

std::uint32_t PlaceTrainDialog::locomotive() const {
    return m_locomotive->currentData().toUInt();
}

bool PlaceTrainDialog::chooseLocomotive(std::uint32_t locId) {
    const int index = m_locomotive->findData(locId);
    if (index >= 0)
        m_locomotive->setCurrentIndex(index);
    return index >= 0;
}

trackgraph::End PlaceTrainDialog::towards() const {
    return trackgraph::End(m_end->currentData().toInt());
}

void PlaceTrainDialog::setTowards(trackgraph::End end) {
    m_end->setCurrentIndex(m_end->findData(int(end)));
}

int PlaceTrainDialog::lengthMm() const {
    return m_length->value();
}

void PlaceTrainDialog::setLengthMm(int lengthMm) {
    m_length->setValue(lengthMm);
}

QString PlaceTrainDialog::beyond(const trackgraph::TrackGraph& graph, int block, trackgraph::End end) {
    const trackgraph::BlockEnd from{block, end};
    QStringList next;
    for (const int id : graph.connectionsFrom(from)) {
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
