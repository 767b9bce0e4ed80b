#pragma once

#include "trackgraph/TrackGraph.h"

#include <QDialog>
#include <cstdint>

class QComboBox;
class QLabel;
class QSpinBox;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// "Place a train here...": which locomotive of the railway stands in the block, which end it faces (told by
// what lies beyond each end) and how long it is; the plan places it when accepted.
class PlaceTrainDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PlaceTrainDialog)

public:
    PlaceTrainDialog(const model::Railway& railway, const trackgraph::TrackGraph& graph, int block,
                     QWidget* parent = nullptr);

    int block() const { return m_block; }
    std::uint32_t locomotive() const;
    // Chooses a locomotive by Loc-ID; false when the railway has none with it.
    bool chooseLocomotive(std::uint32_t locId);
    trackgraph::End towards() const;
    void setTowards(trackgraph::End end);
    int lengthMm() const;
    void setLengthMm(int lengthMm);

    // "towards Block 3", "towards a buffer stop": what lies beyond the block's end.
    static QString beyond(const trackgraph::TrackGraph& graph, int block, trackgraph::End end);

private:
    int m_block = 0;
    QComboBox* m_locomotive = nullptr;
    QComboBox* m_end = nullptr;
    QSpinBox* m_length = nullptr;
};

} // namespace stellwerk::ui
