#pragma once

#include "trackplan/BlockShades.h"

#include <QWidget>
#include <vector>

class QLabel;

namespace stellwerk::ui {

// One line above the plan while an automation runs: each shade of a block with its pattern and what it
// means (free, reserved, occupied, unknown occupant, fault), so that nobody has to tell colours apart.
class BlockLegend final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BlockLegend)

public:
    explicit BlockLegend(QWidget* parent = nullptr);

    // The words shown, in order (for tests).
    QStringList texts() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void redraw();
    void retranslate();

    struct Entry {
        BlockShade shade;
        QLabel* swatch;
        QLabel* text;
    };
    std::vector<Entry> m_entries;
    QLabel* m_title = nullptr;
};

} // namespace stellwerk::ui
