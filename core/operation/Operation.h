#pragma once

#include "automation/Automation.h"
#include "operation/TrainBook.h"
#include "operation/TrainBookFile.h"

#include <QObject>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace stellwerk::model {
class LayoutInUse;
class Railway;
} // namespace stellwerk::model

namespace stellwerk::operation {

// The desktop's automatic operation, the one object the window and the panels ask: an Automation for the
// railway of the session and the layout in use's track graph (made anew when either changes), and the book
// of trains kept beside the layout, so that after a restart the trains stand where they stood and their
// schedules go on. Nothing moves by itself: a train runs only once the user started it, or pressed Resume
// for the trains that ran when the program was closed. STOP halts the automation and GO does not undo it.
class Operation final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(Operation)

public:
    struct Options {
        std::filesystem::path dataDir; // where the books of stations' layouts are kept
        automation::Dispatcher::Options dispatcher;
        std::chrono::milliseconds tick{20};  // 0: the caller ticks automation() (tests)
        automation::Automation::Clock clock; // empty: the steady clock
    };

    Operation(model::LayoutInUse& layout, Options options, QObject* parent = nullptr);
    ~Operation() override;

    // What names the station whose layout is in use (its address; empty for the built-in simulated one),
    // asked whenever the automation is made anew.
    void setStationName(std::function<std::string()> name) { stationName_ = std::move(name); }
    // The railway of the session (null: none); see RailwayBinding::railwayChanged.
    void setRailway(model::Railway* railway);

    automation::Automation* automation() const { return automation_.get(); }
    model::Railway* railway() const { return railway_; }
    const TrainBook& book() const { return book_; }
    const std::filesystem::path& bookPath() const { return bookFile_.path(); }
    // The last trouble with the book's file (unreadable, put aside, not written); empty when none.
    const std::string& bookProblem() const { return bookProblem_; }
    // Why a train of the book stands nowhere now (its block is not on this plan); empty when placed.
    std::string notPlaced(std::uint32_t locId) const;
    // A train that ran when the program was closed: it stands until the user presses Resume.
    bool waitsForResume(std::uint32_t locId) const { return waiting_.contains(locId); }
    // A throttle took the train: it is manual until handed back.
    bool takenByHand(std::uint32_t locId) const { return byHand_.contains(locId); }
    // The sentence of the train's last fault (a fault, lost, an overrun), until it is started again.
    std::string lastFault(std::uint32_t locId) const;
    // The same fault in parts (Why::None: none), for the window to say in the user's language.
    automation::StopReason lastStopReason(std::uint32_t locId) const;
    // Automation stopped by STOP, the track power, the station's silence or an overrun, or trains waiting
    // for Resume: nothing moves until resume().
    bool halted() const;

    // Puts the train in the block (its graph id) facing `towards`; a train the automation drives is made
    // manual first. The sentence says why not.
    std::optional<std::string> place(std::uint32_t locId, int block, trackgraph::End towards, int lengthMm,
                                     bool pushPull);
    // The train is driven by the automation from where it stands (a manual one, one taken by a throttle,
    // one stopped by a fault); after STOP it stands until resume(). The sentence says why not.
    std::optional<std::string> start(std::uint32_t locId);
    // The train becomes manual and stops; its blocks stay reserved for it.
    void stop(std::uint32_t locId);
    void remove(std::uint32_t locId);
    // The train's schedule (no stops: none); kept in the book even for a train not placed now.
    std::optional<std::string> setSchedule(std::uint32_t locId, automation::Schedule schedule);
    // After STOP, a fault or a restart: every automatic train (and every train that ran when the program
    // was closed) goes on. Refused while the track power is off.
    std::optional<std::string> resume();
    // Every automatic train runs on to its next stop and stays there, manual.
    void stopAllAtNextStop();

signals:
    // A new automation (or null while there is none); the previous one is deleted right after.
    void automationChanged(stellwerk::automation::Automation* automation);
    // The book or a train's state changed.
    void changed();
    void happened(const stellwerk::automation::AutomationEvent& event);
    void bookTrouble(const QString& sentence);

private:
    void remake();
    void openBook();
    void placeBooked(const BookedTrain& train);
    int bookedBlock(const BookedTrain& train) const;
    void eventHappened(const automation::AutomationEvent& event);
    // The train is no longer the operation's: out of the book and every list.
    void forget(std::uint32_t locId);
    void writeBook();
    void noteBookProblem(const std::string& problem);
    bool powerOff() const;

    model::LayoutInUse& layout_;
    Options options_;
    model::Railway* railway_ = nullptr;
    std::function<std::string()> stationName_;
    std::shared_ptr<const trackgraph::TrackGraph> graph_;
    std::unique_ptr<automation::Automation> automation_;
    TrainBook book_;
    TrainBookFile bookFile_{{}};
    std::string written_; // the book as last written
    std::string bookProblem_;
    std::map<std::uint32_t, std::string> notPlaced_;
    std::map<std::uint32_t, automation::StopReason> faults_;
    std::set<std::uint32_t> waiting_;
    std::set<std::uint32_t> byHand_;
    bool stopping_ = false; // the Manual event now is the user's Stop, not a throttle
};

} // namespace stellwerk::operation
