#include "operation/Operation.h"

#include "model/LayoutInUse.h"
#include "model/Railway.h"

#include <algorithm>

namespace stellwerk::operation {

using automation::TrainMode;
using automation::TrainState;

Operation::Operation(model::LayoutInUse& layout, Options options, QObject* parent)
    : QObject(parent), layout_(layout), options_(std::move(options)) {
    connect(&layout_, &model::LayoutInUse::changed, this, &Operation::remake);
    remake();
}

Operation::~Operation() {
    automation_.reset();
}

void Operation::setRailway(model::Railway* railway) {
    if (railway_)
        disconnect(railway_, nullptr, this, nullptr);
    railway_ = railway;
    if (railway_)
        connect(railway_, &QObject::destroyed, this, [this] {
            railway_ = nullptr;
            remake();
        });
    remake();
}

std::string Operation::notPlaced(std::uint32_t locId) const {
    const auto found = notPlaced_.find(locId);
    return found == notPlaced_.end() ? std::string() : found->second;
}

std::string Operation::lastFault(std::uint32_t locId) const {
    return automation::describe(lastStopReason(locId));
}

automation::StopReason Operation::lastStopReason(std::uint32_t locId) const {
    const auto found = faults_.find(locId);
    return found == faults_.end() ? automation::StopReason{} : found->second;
}

bool Operation::halted() const {
    if (!automation_)
        return false;
    if (!waiting_.empty())
        return true;
    const automation::Dispatcher& dispatcher = automation_->dispatcher();
    return dispatcher.paused() &&
           std::any_of(dispatcher.trains().begin(), dispatcher.trains().end(),
                       [](const auto& entry) { return entry.second.mode == TrainMode::Automatic; });
}

// The automation for this railway and this graph, with the book's trains placed where they stood; the
// trains that ran wait for Resume.
void Operation::remake() {
    if (automation_) {
        emit automationChanged(nullptr);
        automation_.reset();
    }
    openBook();
    graph_ = layout_.graph();
    notPlaced_.clear();
    faults_.clear();
    byHand_.clear();
    waiting_.clear();
    if (railway_ && graph_ && !graph_->blocks().empty()) {
        automation_ = std::make_unique<automation::Automation>(*railway_, *graph_, options_.dispatcher);
        if (options_.clock)
            automation_->setClock(options_.clock);
        connect(automation_.get(), &automation::Automation::happened, this, &Operation::eventHappened);
        const TrainBook booked = book_; // placing writes the book
        for (const BookedTrain& train : booked.trains())
            placeBooked(train);
        automation_->run(options_.tick);
        emit automationChanged(automation_.get());
    }
    emit changed();
}

// The book of the layout in use, read when the layout (or the station) is another than before.
void Operation::openBook() {
    const std::filesystem::path path =
        TrainBookFile::placeFor(layout_, options_.dataDir, stationName_ ? stationName_() : std::string());
    if (path == bookFile_.path())
        return;
    bookFile_ = TrainBookFile(path);
    std::string problem;
    book_ = path.empty() ? TrainBook() : bookFile_.load(problem);
    written_ = book_.toJson();
    bookProblem_.clear();
    if (!problem.empty())
        noteBookProblem(problem);
}

void Operation::placeBooked(const BookedTrain& train) {
    const int block = bookedBlock(train);
    if (block == 0) {
        notPlaced_[train.locId] = "the track plan has no block \"" + train.block + "\"";
        return;
    }
    if (train.automatic)
        waiting_.insert(train.locId); // before the placing writes the book
    if (const auto problem = automation_->placeInBlock(train.locId, block, train.towards, train.lengthMm)) {
        waiting_.erase(train.locId);
        notPlaced_[train.locId] = *problem;
        return;
    }
    automation_->setPushPull(train.locId, train.pushPull);
    automation::Schedule schedule = train.schedule;
    schedule.pushPull = train.pushPull;
    if (const auto problem = automation_->setSchedule(train.locId, schedule))
        noteBookProblem(*problem);
}

// The block by its number while it still bears the name the book gives it; else by the name.
int Operation::bookedBlock(const BookedTrain& train) const {
    const auto& blocks = graph_->blocks();
    if (train.blockId > 0 && train.blockId <= int(blocks.size()) &&
        graph_->block(train.blockId).name == train.block)
        return train.blockId;
    const auto named = std::find_if(blocks.begin(), blocks.end(), [&](const trackgraph::Block& block) {
        return block.name == train.block;
    });
    return named == blocks.end() ? 0 : named->id;
}

std::optional<std::string> Operation::place(std::uint32_t locId, int block, trackgraph::End towards,
                                            int lengthMm, bool pushPull) {
    if (!automation_)
        return std::string("there is no railway with a track plan to place trains on");
    if (const automation::Train* train = automation_->dispatcher().train(locId);
        train && train->mode == TrainMode::Automatic)
        stop(locId);
    if (auto problem = automation_->placeInBlock(locId, block, towards, lengthMm))
        return problem;
    BookedTrain booked = book_.find(locId) ? *book_.find(locId) : BookedTrain{};
    booked.locId = locId;
    booked.lengthMm = lengthMm;
    booked.pushPull = pushPull;
    booked.automatic = false;
    book_.put(booked);
    automation_->setPushPull(locId, pushPull);
    booked.schedule.pushPull = pushPull;
    automation_->setSchedule(locId, booked.schedule);
    notPlaced_.erase(locId);
    waiting_.erase(locId);
    byHand_.erase(locId);
    faults_.erase(locId);
    writeBook();
    emit changed();
    return std::nullopt;
}

std::optional<std::string> Operation::start(std::uint32_t locId) {
    const automation::Train* train = automation_ ? automation_->dispatcher().train(locId) : nullptr;
    if (!train)
        return notPlaced(locId).empty() ? std::string("the train is not placed") : notPlaced(locId);
    if (train->state == TrainState::Lost)
        return train->name + " is lost: place it again first";
    const automation::Dispatcher& dispatcher = automation_->dispatcher();
    const bool othersAutomatic =
        std::any_of(dispatcher.trains().begin(), dispatcher.trains().end(), [locId](const auto& entry) {
            return entry.first != locId && entry.second.mode == TrainMode::Automatic;
        });
    // A pause nobody is held by (the power was off before any train ran) ends with the first start.
    if (dispatcher.paused() && !othersAutomatic && waiting_.empty() && !powerOff())
        automation_->resume();
    if (train->mode == TrainMode::Automatic) {
        stopping_ = true;
        automation_->stopByHand(locId, "the Automatic panel");
        stopping_ = false;
    }
    waiting_.erase(locId);
    faults_.erase(locId);
    automation_->handBack(locId);
    writeBook();
    emit changed();
    return std::nullopt;
}

void Operation::stop(std::uint32_t locId) {
    if (!automation_)
        return;
    stopping_ = true;
    automation_->stopByHand(locId, "the Automatic panel");
    stopping_ = false;
    waiting_.erase(locId);
    byHand_.erase(locId);
    writeBook();
    emit changed();
}

void Operation::remove(std::uint32_t locId) {
    if (automation_)
        automation_->remove(locId);
    forget(locId);
    writeBook();
    emit changed();
}

void Operation::forget(std::uint32_t locId) {
    book_.remove(locId);
    notPlaced_.erase(locId);
    waiting_.erase(locId);
    byHand_.erase(locId);
    faults_.erase(locId);
}

std::optional<std::string> Operation::setSchedule(std::uint32_t locId, automation::Schedule schedule) {
    BookedTrain* booked = book_.find(locId);
    if (!booked)
        return std::string("the train is not in the book");
    schedule.pushPull = booked->pushPull;
    if (schedule.next > schedule.stops.size())
        schedule.next = 0;
    if (automation_ && automation_->dispatcher().train(locId))
        if (auto problem = automation_->setSchedule(locId, schedule))
            return problem;
    booked->schedule = std::move(schedule);
    writeBook();
    emit changed();
    return std::nullopt;
}

std::optional<std::string> Operation::resume() {
    if (!automation_)
        return std::string("there is no railway with a track plan");
    if (powerOff())
        return std::string("the track power is off: switch it on (GO) first");
    if (automation_->dispatcher().paused())
        automation_->resume();
    for (const std::uint32_t locId : std::set<std::uint32_t>(waiting_)) {
        waiting_.erase(locId);
        faults_.erase(locId);
        automation_->handBack(locId);
    }
    writeBook();
    emit changed();
    return std::nullopt;
}

void Operation::stopAllAtNextStop() {
    if (!automation_)
        return;
    waiting_.clear();
    automation_->stopAtNextStop();
    writeBook();
    emit changed();
}

// The track power is known to be off (STOP); unknown counts as on: a station that has not said yet.
bool Operation::powerOff() const {
    return !railway_ || (railway_->power() && *railway_->power() != station::PowerState::Running);
}

void Operation::eventHappened(const automation::AutomationEvent& event) {
    using Kind = automation::AutomationEvent::Kind;
    if (event.kind == Kind::Fault || event.kind == Kind::Lost || event.kind == Kind::Overrun)
        faults_[event.locId] = event.reason;
    else if (event.kind == Kind::Manual && !stopping_)
        byHand_.insert(event.locId);
    else if (event.kind == Kind::Automatic)
        byHand_.erase(event.locId);
    else if (event.kind == Kind::Released && automation_ && !automation_->dispatcher().train(event.locId))
        forget(event.locId); // taken off elsewhere (the plan's block menu): not placed again after a restart
    writeBook();
    emit happened(event);
    emit changed();
}

// The book as the automation has the trains now (where they stand, their schedules' next stops, who drives
// them), written when it changed.
void Operation::writeBook() {
    if (automation_) {
        const automation::Dispatcher& dispatcher = automation_->dispatcher();
        for (const auto& [locId, train] : dispatcher.trains()) {
            BookedTrain booked = book_.find(locId) ? *book_.find(locId) : BookedTrain{};
            const automation::TrainBody* body = dispatcher.tracking().body(locId);
            booked.locId = locId;
            booked.lengthMm = train.lengthMm;
            booked.pushPull = train.pushPull;
            if (body) {
                booked.blockId = body->frontBlock;
                booked.block = dispatcher.graph().block(body->frontBlock).name;
                booked.towards = body->towards;
            }
            booked.automatic = train.mode == TrainMode::Automatic || waiting_.contains(locId);
            if (train.schedule)
                booked.schedule.next = train.schedule->next;
            book_.put(std::move(booked));
        }
    }
    const std::string json = book_.toJson();
    if (json == written_ || bookFile_.path().empty())
        return;
    if (const std::string problem = bookFile_.save(book_); !problem.empty()) {
        noteBookProblem(problem);
        return;
    }
    written_ = json;
}

void Operation::noteBookProblem(const std::string& problem) {
    bookProblem_ = problem;
    emit bookTrouble(QString::fromStdString(problem));
}

} // namespace stellwerk::operation
