#pragma once

#include "trackgraph/TrackGraph.h"

#include <QDialog>
#include <cstdint>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// Where the user puts a train for the automation: which locomotive, in which block, facing which end, how
// long it is and whether it may change direction anywhere (push-pull).
class PlaceTrainDialog final : public QDialog {
    Q_OBJECT

public:
    struct Choice {
        std::uint32_t locId = 0;
        int block = 0;
        trackgraph::End towards = trackgraph::End::B;
        int lengthMm = 200;
        bool pushPull = false;
    };

    PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph, const Choice& start,
                     QWidget* parent = nullptr);

    Choice choice() const;
    QComboBox* locomotiveBox() const { return m_locomotive; }
    QComboBox* blockBox() const { return m_block; }
    QComboBox* endBox() const { return m_end; }
    QSpinBox* lengthBox() const { return m_length; }
    QCheckBox* pushPullBox() const { return m_pushPull; }

private:
    QComboBox* m_locomotive = nullptr;
    QComboBox* m_block = nullptr;
    QComboBox* m_end = nullptr;
    QSpinBox* m_length = nullptr;
    QCheckBox* m_pushPull = nullptr;
};

} // namespace stellwerk::ui
