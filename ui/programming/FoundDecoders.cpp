#include "programming/FoundDecoders.h"

#include <QEvent>
#include <QHeaderView>

namespace stellwerk::ui {

FoundDecoders::FoundDecoders(QWidget* parent) : QTableWidget(0, 2, parent) {
    setObjectName(QStringLiteral("foundDecoders"));
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    verticalHeader()->hide();
    horizontalHeader()->setStretchLastSection(true);
    retranslate();
}

QString FoundDecoders::uidText(std::uint32_t uid) {
    return QStringLiteral("0x%1").arg(uid, 8, 16, QLatin1Char('0'));
}

void FoundDecoders::show(std::uint32_t mfxUid, Say state) {
    const int row = rowOf(mfxUid);
    item(row, 1)->setText(state());
    m_states.insert(mfxUid, std::move(state));
    resizeColumnToContents(0);
}

int FoundDecoders::rowOf(std::uint32_t mfxUid) {
    for (int row = 0; row < rowCount(); ++row)
        if (item(row, 0)->data(Qt::UserRole).toUInt() == mfxUid)
            return row;
    const int row = rowCount();
    insertRow(row);
    auto* uid = new QTableWidgetItem(uidText(mfxUid));
    uid->setData(Qt::UserRole, mfxUid);
    setItem(row, 0, uid);
    setItem(row, 1, new QTableWidgetItem);
    selectRow(row);
    return row;
}

std::optional<std::uint32_t> FoundDecoders::selectedUid() const {
    const QList<QTableWidgetItem*> selected = selectedItems();
    if (selected.isEmpty())
        return std::nullopt;
    return std::uint32_t(item(selected.first()->row(), 0)->data(Qt::UserRole).toUInt());
}

void FoundDecoders::clearDecoders() {
    setRowCount(0);
    m_states.clear();
}

void FoundDecoders::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTableWidget::changeEvent(event);
}

void FoundDecoders::retranslate() {
    setHorizontalHeaderLabels({tr("mfx UID"), tr("State")});
    for (int row = 0; row < rowCount(); ++row)
        if (const Say state = m_states.value(item(row, 0)->data(Qt::UserRole).toUInt()))
            item(row, 1)->setText(state());
}

} // namespace stellwerk::ui
