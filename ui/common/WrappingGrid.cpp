#include "common/WrappingGrid.h"

#include <QGridLayout>
#include <QResizeEvent>
#include <algorithm>

namespace stellwerk::ui {

WrappingGrid::WrappingGrid(QWidget* parent) : QWidget(parent) {
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 0, 0, 0);
    // The grid may become narrower than its current columns (it then wraps): minimumSizeHint() says how far.
    m_grid->setSizeConstraint(QLayout::SetNoConstraint);
}

void WrappingGrid::add(QWidget* widget) {
    m_widgets.push_back(widget);
    arrange(columnsFor(width()));
}

void WrappingGrid::remove(QWidget* widget) {
    if (!m_widgets.removeOne(widget))
        return;
    m_grid->removeWidget(widget);
    arrange(columnsFor(width()));
}

QSize WrappingGrid::minimumSizeHint() const {
    QSize least = m_grid->minimumSize();
    if (const int cell = cellWidth(); cell > 0)
        least.setWidth(std::min(least.width(), cell));
    return least;
}

int WrappingGrid::spacing() const {
    return m_grid->horizontalSpacing();
}

int WrappingGrid::cellWidth() const {
    int widest = 0;
    for (const QWidget* widget : m_widgets)
        widest = std::max(widest, widget->sizeHint().width());
    return widest;
}

int WrappingGrid::columnsFor(int width) const {
    const int cell = cellWidth();
    if (cell <= 0)
        return 1;
    const int spacing = m_grid->horizontalSpacing();
    return std::max(1, (width + spacing) / (cell + spacing));
}

void WrappingGrid::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (const int columns = columnsFor(event->size().width()); columns != m_columns)
        arrange(columns);
}

// Widget n goes to row n / columns, column n % columns: the numbering reads like a page.
void WrappingGrid::arrange(int columns) {
    m_columns = columns;
    for (QWidget* widget : m_widgets)
        m_grid->removeWidget(widget);
    for (qsizetype i = 0; i < m_widgets.size(); ++i)
        m_grid->addWidget(m_widgets[i], int(i) / columns, int(i) % columns);
    // The spare height goes below the last row, not into the widgets.
    const int rows = (int(m_widgets.size()) + columns - 1) / columns;
    for (int row = 0; row < m_grid->rowCount(); ++row)
        m_grid->setRowStretch(row, row == rows ? 1 : 0);
    m_grid->setRowStretch(rows, 1);
    // Fewer widgets than columns keep their width; the spare width stays empty on the right.
    const int used = std::min(columns, int(m_widgets.size()));
    for (int column = 0; column < m_grid->columnCount(); ++column)
        m_grid->setColumnStretch(column, column == used && used < columns ? 1 : 0);
    if (used < columns)
        m_grid->setColumnStretch(used, 1);
}

} // namespace stellwerk::ui
