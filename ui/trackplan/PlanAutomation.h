#pragma once

#include "automation/Automation.h"
#include "trackgraph/TrackGraph.h"
#include "trackplan/BlockOutlines.h"
#include "trackplan/TrainsOnPlan.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <optional>

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The plan's side of automatic operation: follows an Automation (which may be deleted or replaced at any
// time), reads what it says about the blocks once per batch of its events and of the railway's contacts
// (TrainsOnPlan), says it in words for the blocks' tabs and tooltips, and places and removes trains
// through it.
class PlanAutomation final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(PlanAutomation)

public:
    explicit PlanAutomation(QObject* parent = nullptr);

    // Null: none. The railway whose contacts it watches (the plan's).
    void setAutomation(automation::Automation* automation);
    void setRailway(model::Railway* railway);
    automation::Automation* automation() const { return m_automation; }
    // True while an automation runs on the layout the plan shows.
    bool isActive() const { return m_automation && m_matches; }
    // The graph the plan shows: the automation's marks apply only while it has the automation's blocks
    // (the same layout; another graph derived from the same files has the same ids).
    void setShownGraph(const trackgraph::TrackGraph* graph);

    const TrainsOnPlan& trains() const { return m_trains; }
    // The shade and the words beside a block's name.
    BlockOutlines::Mark markOf(int block) const;
    // A line for the block's tooltip: "Automation: reserved for BR 218".
    QString toolTipOf(int block) const;

    // Puts a locomotive of the railway in the block facing `towards` (a push-pull train may change direction
    // in any block); the reason in words when refused.
    std::optional<QString> place(std::uint32_t locId, int block, trackgraph::End towards, int lengthMm,
                                 bool pushPull = false);
    bool remove(std::uint32_t locId);

    // Reads the automation again now (instead of after the batch); the tests' and the plan's own after a
    // placing.
    void refresh();

signals:
    // What the blocks show changed.
    void changed();

private:
    void schedule();
    void match();

    QPointer<automation::Automation> m_automation;
    QPointer<model::Railway> m_railway;
    const trackgraph::TrackGraph* m_shownGraph = nullptr;
    bool m_matches = false; // the automation's graph has the blocks of the one shown
    TrainsOnPlan m_trains;
    bool m_wasActive = false; // at the last changed()
    QTimer m_batch;
};

} // namespace stellwerk::ui
