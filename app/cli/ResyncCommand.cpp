#include "ResyncCommand.h"

#include "binding/RailwayBinding.h"
#include "model/Railway.h"
#include "station/StartupSequence.h"

#include <QObject>
#include <ostream>

namespace stellwerk::cli {
namespace {

// A locomotive's line: "BR 218 Ost (0x4001): speed 0, forward, on: F0 F2".
std::string locomotiveLine(const model::Locomotive& loco) {
    std::string line = loco.displayName().toStdString() + " (" +
                       QStringLiteral("0x%1").arg(loco.id().value(), 4, 16, QLatin1Char('0')).toStdString() +
                       "): ";
    line +=
        loco.isSpeedReported() ? "speed " + std::to_string(loco.speed()) : std::string("speed not reported");
    line += loco.isDirectionReported()
                ? (loco.direction() == cs2::Direction::Backward ? ", backward" : ", forward")
                : ", direction not reported";
    std::string on;
    int unknown = 0;
    for (const model::LocomotiveFunction& function : loco.functions()) {
        if (!loco.isFunctionReported(function.number))
            ++unknown;
        else if (loco.functionOn(function.number))
            on += " F" + std::to_string(function.number);
    }
    if (!loco.functions().empty())
        line += on.empty() ? ", no function on" : ", on:" + on;
    if (unknown)
        line += ", " + std::to_string(unknown) + " functions not reported";
    return line;
}

// The railway (bound by the RailwayBinding) and the start-up that loads it, living as long as the command.
class ResyncRun final : public QObject {
public:
    ResyncRun(StationClient& client, bool stop, std::ostream& out, std::ostream& err)
        : QObject(&client), client_(client), out_(out), err_(err) {
        railways_.sessionStarted(client.session(), nullptr); // before the start-up: it keeps its answers
        model::Railway* railway = railways_.railway();
        railway->setAftermath(stop ? model::Aftermath::StopLocomotives : model::Aftermath::RestoreConfirmed);
        connect(railway, &model::Railway::locomotiveCommandFailed, this,
                [this](quint32, auto, int, const QString& reason) { fail(reason); });
        connect(railway, &model::Railway::problem, this, [this](const QString& message) { fail(message); });
        connect(railway, &model::Railway::backInStep, this, &ResyncRun::done);
        station::StartupOptions options;
        options.readStatusData = false;
        startup_ = std::make_unique<station::StartupSequence>(client.session(), options);
        connect(startup_.get(), &station::StartupSequence::problem, this,
                [this](const QString& message) { err_ << "note: " << message.toStdString() << '\n'; });
        connect(startup_.get(), &station::StartupSequence::ready, this,
                [this](const station::StartupResult& result) {
                    railways_.configurationLoaded(result);
                    railways_.railway()->bringBackInStep();
                });
        startup_->start();
    }
    ~ResyncRun() override {
        startup_.reset(); // before the railway: the start-up feeds it
    }

private:
    void fail(const QString& message) {
        ++failures_;
        err_ << "error: " << message.toStdString() << '\n';
    }

    void done(int answered, int unanswered) {
        const model::Railway& railway = *railways_.railway();
        const auto& locomotives = railway.state().locomotives().items();
        out_ << (railway.aftermath() == model::Aftermath::StopLocomotives ? "ok: stopped " : "ok: sent ")
             << locomotives.size()
             << (railway.aftermath() == model::Aftermath::StopLocomotives
                     ? " locomotives"
                     : " locomotives their confirmed speed")
             << " and read " << answered << " states again" << (unanswered ? ", " : "")
             << (unanswered ? std::to_string(unanswered) + " unanswered" : std::string()) << '\n';
        for (const model::Locomotive& loco : locomotives)
            out_ << locomotiveLine(loco) << '\n';
        client_.finish(unanswered == 0 && failures_ == 0 ? Acknowledged : NotAcknowledged);
    }

    StationClient& client_;
    std::ostream& out_;
    std::ostream& err_;
    binding::RailwayBinding railways_;
    std::unique_ptr<station::StartupSequence> startup_;
    int failures_ = 0;
};

} // namespace

std::optional<ParsedJob> parseResyncCommand(const std::string& command,
                                            const std::vector<std::string>& arguments, std::ostream& out,
                                            std::ostream& err) {
    if (command != "resync")
        return std::nullopt;
    bool stop = false;
    for (const std::string& word : arguments) {
        if (word != "--stop")
            return ParsedJob("resync: unknown argument '" + word + "' (takes --stop)");
        stop = true;
    }
    return ParsedJob(
        StationJob{[stop, &out, &err](StationClient& client) { new ResyncRun(client, stop, out, err); },
                   std::chrono::milliseconds(60000)});
}

} // namespace stellwerk::cli
