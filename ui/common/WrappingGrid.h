#pragma once

#include <QList>
#include <QWidget>

class QGridLayout;

namespace stellwerk::ui {

// Lays widgets of one kind (throttles, gauges) out in as many columns as its width holds, then in rows
// below, so a narrow panel stacks them (scrolling down) and a wide one puts them side by side, never
// cutting one off at the side.
class WrappingGrid final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(WrappingGrid)

public:
    explicit WrappingGrid(QWidget* parent = nullptr);

    void add(QWidget* widget);
    void remove(QWidget* widget);
    int columns() const { return m_columns; }
    // The room between two widgets.
    int spacing() const;
    // One column wide, as tall as the rows the widgets are in now.
    QSize minimumSizeHint() const override;
    // How many columns fit `width` for widgets of the width they ask for.
    int columnsFor(int width) const;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void arrange(int columns);
    int cellWidth() const;

    QGridLayout* m_grid;
    QList<QWidget*> m_widgets;
    int m_columns = 1;
};

} // namespace stellwerk::ui
