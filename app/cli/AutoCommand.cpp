#include "AutoCommand.h"

#include "automation/Automation.h"
#include "automation/Placement.h"
#include "automation/Schedule.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "station/Liveness.h"
#include "station/StartupSequence.h"
#include "station/StationSession.h"
#include "transport/Transport.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QObject>
#include <QSaveFile>
#include <QTimer>
#include <algorithm>
#include <memory>
#include <ostream>

namespace stellwerk::cli {
namespace {

struct AutoOptions {
    std::vector<automation::Placement> placements;
    std::string layoutFolder;
    std::string scheduleFile;
    int seconds = 60;
    bool json = false;
};

QString locText(std::uint32_t locId) {
    return QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0'));
}

// The station read, the railway, the graph and the automation, living as long as the command.
class AutoRun final : public QObject {
public:
    AutoRun(StationClient& client, AutoOptions options, std::ostream& out, std::ostream& err)
        : QObject(&client), client_(client), options_(std::move(options)), out_(out), err_(err) {
        railway_ = std::make_unique<model::Railway>(client.session());
        station::StartupOptions startupOptions;
        startupOptions.readStatusData = false;
        startup_ = std::make_unique<station::StartupSequence>(client.session(), startupOptions);
        connect(startup_.get(), &station::StartupSequence::ready, this, &AutoRun::stationRead);
        startup_->start();
        client.whenInterrupted([this] { end(); });
    }
    ~AutoRun() override {
        automation_.reset();
        startup_.reset();
        railway_.reset();
    }

private:
    void stationRead(const station::StartupResult& result) {
        railway_->load(result);
        layout_.useStationDownload(result);
        if (!options_.layoutFolder.empty())
            if (const std::string problem = openFolder(); !problem.empty())
                return fail("--layout: " + problem);
        graph_ = layout_.graph();
        if (!graph_ || graph_->blocks().empty())
            return fail("the track plan has no block to run trains in");
        watchStation();
        railway_->go();
        QTimer::singleShot(5000, this, [this] {
            if (!automation_)
                fail("the station did not switch the track power on");
        });
        connect(railway_.get(), &model::Railway::powerChanged, this, [this](station::PowerState state) {
            if (state == station::PowerState::Running && !automation_)
                startAutomation();
        });
        if (railway_->power() == station::PowerState::Running)
            startAutomation();
    }

    // The station's silence is noticed within seconds (pings), and when it answers again, or the connection
    // is made again, its state is read once more (the start-up) before the automation hears it is back.
    void watchStation() {
        station::Liveness& liveness = client_.session().liveness();
        connect(&liveness, &station::Liveness::stationRecovered, this, &AutoRun::readAgain);
        connect(&liveness, &station::Liveness::stationSilent, this, [this] { rereading_ = false; });
        connect(&client_.transport(), &transport::Transport::stateChanged, this,
                [this](transport::Transport::State state) {
                    rereading_ = rereading_ && state == transport::Transport::State::Connected;
                    if (state == transport::Transport::State::Connected)
                        readAgain();
                });
        liveness.start();
    }

    void readAgain() {
        if (!automation_ || ending_ || rereading_ || railway_->isStateReported())
            return;
        rereading_ = true;
        startup_.release()->deleteLater(); // finished or abandoned; it may be the sender of this signal
        station::StartupOptions startupOptions;
        startupOptions.readStatusData = false;
        startup_ = std::make_unique<station::StartupSequence>(client_.session(), startupOptions);
        connect(startup_.get(), &station::StartupSequence::ready, this,
                [this](const station::StartupResult& result) {
                    rereading_ = false;
                    railway_->load(result); // reported again unless the station fell silent meanwhile
                });
        startup_->start();
    }

    // --layout DIR as the layout in use instead of the station's download; why not, else empty.
    std::string openFolder() {
        if (std::string problem = layout_.open(options_.layoutFolder); !problem.empty())
            return problem;
        const std::vector<cs2config::TrackLayoutPage>& pages = layout_.files()->pages;
        if (std::none_of(pages.begin(), pages.end(),
                         [](const cs2config::TrackLayoutPage& page) { return page.loaded; }))
            return "no page of the track plan in " + layout_.folder().string() + " could be read";
        return {};
    }

    void startAutomation() {
        automation_ = std::make_unique<automation::Automation>(*railway_, *graph_);
        connect(automation_.get(), &automation::Automation::happened, this, &AutoRun::print);
        for (const automation::Placement& placement : options_.placements)
            if (const auto problem =
                    automation_->place(placement.locId, placement.contact, placement.towards))
                return fail(*problem);
        if (!options_.scheduleFile.empty() && !giveSchedules())
            return;
        automation_->start();
        QTimer::singleShot(options_.seconds * 1000, this, &AutoRun::end);
    }

    // The schedule file's schedules to the placed trains; false (and the run fails) when it cannot be.
    bool giveSchedules() {
        QFile file(QString::fromStdString(options_.scheduleFile));
        if (!file.open(QIODevice::ReadOnly))
            return refuse("--schedule: cannot read " + options_.scheduleFile);
        const QByteArray text = file.readAll();
        const auto schedules =
            automation::parseSchedules(std::string_view(text.data(), std::size_t(text.size())));
        if (!schedules)
            return refuse("--schedule: " + schedules.error());
        for (const auto& [locId, schedule] : *schedules)
            if (const auto problem = automation_->setSchedule(locId, schedule))
                return refuse("--schedule: " + *problem);
        return true;
    }

    // Where every scheduled train is in its schedule, written back to the file, so that the next run goes on
    // from there.
    void saveSchedules() {
        std::map<std::uint32_t, automation::Schedule> schedules;
        for (const auto& [locId, train] : automation_->dispatcher().trains())
            if (train.schedule)
                schedules[locId] = *train.schedule;
        QSaveFile file(QString::fromStdString(options_.scheduleFile));
        const std::string text = automation::schedulesJson(schedules);
        if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), qint64(text.size())) < 0 ||
            !file.commit())
            err_ << "stellwerk-cli auto run: cannot write " << options_.scheduleFile << '\n';
    }

    // Every train it drove stopped (and the station's answer waited for), everything given back.
    void end() {
        if (!automation_ || ending_)
            return client_.finish(NotAcknowledged);
        ending_ = true;
        connect(railway_.get(), &model::Railway::locomotiveCommandSent, this, [this] { ++stopsAwaited_; });
        connect(railway_.get(), &model::Railway::locomotiveCommandAcknowledged, this,
                [this] { countAnswer(); });
        connect(railway_.get(), &model::Railway::locomotiveCommandFailed, this, [this] { countAnswer(); });
        automation_->finish();
        if (stopsAwaited_ == 0)
            return summarize();
        QTimer::singleShot(5000, this, &AutoRun::summarize);
    }

    void countAnswer() {
        if (--stopsAwaited_ == 0)
            summarize();
    }

    void print(const automation::AutomationEvent& event) {
        if (event.kind == automation::AutomationEvent::Kind::Arrived && !options_.scheduleFile.empty())
            saveSchedules();
        const QString name = trainName(event.locId);
        if (!options_.json) {
            out_ << eventKindName(event.kind) << ": " << event.text << std::endl;
            return;
        }
        QJsonObject line{{"event", QString::fromStdString(std::string(eventKindName(event.kind)))},
                         {"text", QString::fromStdString(event.text)}};
        if (event.locId != 0) {
            line["loc"] = locText(event.locId);
            line["train"] = name;
        }
        if (event.block != 0) {
            line["block"] = event.block;
            line["blockName"] = QString::fromStdString(graph_->block(event.block).name);
        }
        out_ << QJsonDocument(line).toJson(QJsonDocument::Compact).toStdString() << std::endl;
    }

    void summarize() {
        if (summarized_)
            return;
        summarized_ = true;
        const automation::Dispatcher& dispatcher = automation_->dispatcher();
        QJsonArray trains;
        for (const auto& [locId, train] : dispatcher.trains()) {
            const automation::TrainBody* body = dispatcher.tracking().body(locId);
            trains.append(
                QJsonObject{{"loc", locText(locId)},
                            {"train", QString::fromStdString(train.name)},
                            {"state", QString::fromStdString(std::string(trainStateName(train.state)))},
                            {"block", body ? body->frontBlock : 0}});
        }
        const QJsonObject summary{{"event", "summary"},
                                  {"blockMoves", dispatcher.blockMoves()},
                                  {"faults", dispatcher.faults()},
                                  {"trains", trains}};
        out_ << QJsonDocument(summary).toJson(QJsonDocument::Compact).toStdString() << std::endl;
        client_.finish(dispatcher.faults() == 0 ? Acknowledged : NotAcknowledged);
    }

    QString trainName(std::uint32_t locId) const {
        const automation::Train* train = automation_ ? automation_->dispatcher().train(locId) : nullptr;
        return train ? QString::fromStdString(train->name) : locText(locId);
    }

    void fail(const std::string& message) {
        err_ << "stellwerk-cli auto run: " << message << '\n';
        client_.finish(NotAcknowledged);
    }

    bool refuse(const std::string& message) {
        fail(message);
        return false;
    }

    StationClient& client_;
    AutoOptions options_;
    std::ostream& out_;
    std::ostream& err_;
    std::unique_ptr<model::Railway> railway_;
    std::unique_ptr<station::StartupSequence> startup_;
    model::LayoutInUse layout_; // the station's download, or --layout DIR
    std::shared_ptr<const trackgraph::TrackGraph> graph_;
    std::unique_ptr<automation::Automation> automation_;
    bool ending_ = false;
    bool rereading_ = false; // the start-up runs again after the station came back
    bool summarized_ = false;
    int stopsAwaited_ = 0;
};

Expected<AutoOptions, std::string> parseOptions(const std::vector<std::string>& arguments) {
    if (arguments.empty() || arguments[0] != "run")
        return std::string("auto: the command is 'auto run'");
    AutoOptions options;
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        const std::string& word = arguments[i];
        const bool hasValue = i + 1 < arguments.size();
        if (word == "--json") {
            options.json = true;
        } else if ((word == "--place" || word == "--layout" || word == "--schedule" || word == "--seconds") &&
                   !hasValue) {
            return "auto run: " + word + " needs a value";
        } else if (word == "--place") {
            auto placement = automation::parsePlacement(arguments[++i]);
            if (!placement)
                return "auto run: --place: " + placement.error();
            options.placements.push_back(*placement);
        } else if (word == "--layout") {
            options.layoutFolder = arguments[++i];
        } else if (word == "--schedule") {
            options.scheduleFile = arguments[++i];
        } else if (word == "--seconds") {
            const std::string& text = arguments[++i];
            options.seconds =
                text.find_first_not_of("0123456789") == std::string::npos && !text.empty() && text.size() < 7
                    ? std::stoi(text)
                    : 0;
            if (options.seconds < 1)
                return "auto run: --seconds: '" + text + "' is not a number of seconds";
        } else {
            return "auto run: unknown argument '" + word + "'";
        }
    }
    if (options.placements.empty())
        return std::string("auto run: place at least one train with --place LOC=CONTACT[:END]");
    return options;
}

} // namespace

std::optional<ParsedJob> parseAutoCommand(const std::string& command,
                                          const std::vector<std::string>& arguments, std::ostream& out,
                                          std::ostream& err) {
    if (command != "auto")
        return std::nullopt;
    auto options = parseOptions(arguments);
    if (!options)
        return ParsedJob(options.error());
    return ParsedJob(StationJob{
        [options = *options, &out, &err](StationClient& client) { new AutoRun(client, options, out, err); },
        std::nullopt});
}

} // namespace stellwerk::cli
