#pragma once

#include "trackgraph/TrackGraph.h"

#include <QDialog>
#include <cstdint>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// Where the user puts a train for the automation, from the Automatic panel or a block's menu on the plan:
// which locomotive, in which block, facing which end (told by what lies beyond it), how long it is and
// whether it may change direction anywhere (push-pull).
class PlaceTrainDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PlaceTrainDialog)

public:
    struct Choice {
        std::uint32_t locId = 0;
        int block = 0;
        trackgraph::End towards = trackgraph::End::B;
        int lengthMm = 200; // lokomotive.cs2 says no length: a locomotive of H0
        bool pushPull = false;
    };

    PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph, const Choice& start,
                     QWidget* parent = nullptr);

    Choice choice() const;
    // Chooses a locomotive by Loc-ID; false when the railway has none with it.
    bool chooseLocomotive(std::uint32_t locId);
    void setTowards(trackgraph::End end);
    void setLengthMm(int lengthMm);
    QComboBox* locomotiveBox() const { return m_locomotive; }
    QComboBox* blockBox() const { return m_block; }
    QComboBox* endBox() const { return m_end; }
    QSpinBox* lengthBox() const { return m_length; }
    QCheckBox* pushPullBox() const { return m_pushPull; }

    // "towards Block 3", "towards a buffer stop": what lies beyond the block's end.
    static QString beyond(const trackgraph::TrackGraph& graph, int block, trackgraph::End end);

private:
    void blockChosen();

    const trackgraph::TrackGraph& m_graph;
    QLabel* m_intro = nullptr;
    QComboBox* m_locomotive = nullptr;
    QComboBox* m_block = nullptr;
    QComboBox* m_end = nullptr;
    QSpinBox* m_length = nullptr;
    QCheckBox* m_pushPull = nullptr;
};

} // namespace stellwerk::ui
