#include "station/StartupSequence.h"

#include "cs2/Request.h"
#include "cs2config/Document.h"
#include "cs2config/TrackLayout.h"
#include "station/StateQueries.h"
#include "station/StationSession.h"

#include <QTimer>

namespace stellwerk::station {
namespace {

template <class Model>
std::optional<Model> parseAs(const std::string& key, const std::string& contents, QStringList& problems) {
    cs2config::Diagnostics diagnostics(key);
    const auto document = cs2config::Document::parse(contents, diagnostics);
    Model model = Model::read(document, diagnostics);
    if (diagnostics.hasErrors())
        problems << QString::fromStdString(diagnostics.formatAll());
    return model;
}

} // namespace

StartupSequence::StartupSequence(StationSession& session, StartupOptions options, QObject* parent)
    : QObject(parent), session_(session), options_(options), windowTimer_(new QTimer(this)) {
    windowTimer_->setSingleShot(true);
    connect(windowTimer_, &QTimer::timeout, this, &StartupSequence::devicesListed);
    connect(&session_.downloads(), &ConfigDownload::progress, this,
            [this](const QString& key, qsizetype received, qsizetype announced) {
                if (step_ == Step::Configuration)
                    emit downloadProgress(key, received, announced, filesDone_ + 1,
                                          filesDone_ + int(keys_.size()) + 1);
            });
    connect(&session_, &StationSession::connectionLost, this, &StartupSequence::abandon);
}

StartupSequence::~StartupSequence() = default;

void StartupSequence::start() {
    result_ = {};
    abandoned_ = false;
    enter(Step::Devices);
    session_.ping();
    windowTimer_->start(options_.deviceWindow);
}

void StartupSequence::abandon() {
    abandoned_ = true;
    windowTimer_->stop();
    if (queries_)
        queries_->abandon();
    keys_.clear();
}

void StartupSequence::enter(Step step) {
    step_ = step;
    if (step != Step::Ready)
        emit stepStarted(step, int(step) + 1, StepCount);
}

void StartupSequence::devicesListed() {
    if (abandoned_)
        return;
    if (session_.devices().size() == 0)
        report(QStringLiteral("no device answered the ping within %1 ms").arg(options_.deviceWindow.count()));
    if (options_.wakeGleisbox)
        wakeUp();
    enter(Step::StatusData);
    nextDevice_ = 0;
    readNextDevice();
}

void StartupSequence::wakeUp() {
    enter(Step::WakeUp);
    cs2::BootloaderCan go;
    go.raw.size = 5;
    go.raw.bytes[4] = 0x11; // UID 0, "start the application"
    session_.send(cs2::request(go));
    session_.request(cs2::request(cs2::TrackProtocols{0, 0x07}), [this](const CommandResult& r) {
        if (!r.succeeded() && !abandoned_)
            report(QStringLiteral("Gleisbox wake-up: enabling MM2, mfx and DCC: %1")
                       .arg(QLatin1String(commandStatusName(r.status))));
    });
}

void StartupSequence::readNextDevice() {
    const auto& devices = session_.devices().devices();
    if (!options_.readStatusData || nextDevice_ >= devices.size()) {
        result_.devices = devices;
        enter(Step::Configuration);
        keys_ = options_.downloadConfiguration ? std::deque<std::string>{"loks", "mags", "fs", "gbs"}
                                               : std::deque<std::string>{};
        downloadNext();
        return;
    }
    const auto identity = devices[nextDevice_++].identity;
    session_.statusData().read(identity,
                               [this](const DeviceDescription& device, const QStringList& problems) {
                                   if (abandoned_)
                                       return;
                                   session_.devices().describe(device);
                                   for (const auto& message : problems)
                                       report(message);
                                   readNextDevice();
                               });
}

void StartupSequence::downloadNext() {
    if (keys_.empty()) {
        enter(Step::States);
        queueStateQueries();
        return;
    }
    const std::string key = keys_.front();
    keys_.pop_front();
    auto request = cs2config::ConfigRequest::forKey(key);
    session_.downloads().fetch(std::move(*request),
                               [this, key](const DownloadResult& result) { fileArrived(key, result); });
}

void StartupSequence::fileArrived(const std::string& key, const DownloadResult& result) {
    if (abandoned_)
        return;
    ++filesDone_;
    if (result)
        keep(key, result->contents);
    else
        report(result.error());
    downloadNext();
}

void StartupSequence::keep(const std::string& key, const std::string& contents) {
    result_.files[key] = contents;
    auto& problems = result_.problems;
    if (key == "loks") {
        result_.locomotives = parseAs<cs2config::LocomotiveFile>(key, contents, problems);
    } else if (key == "mags") {
        result_.accessories = parseAs<cs2config::AccessoryFile>(key, contents, problems);
    } else if (key == "fs") {
        result_.routes = parseAs<cs2config::RouteFile>(key, contents, problems);
    } else if (key == "gbs") {
        result_.trackPlan = parseAs<cs2config::TrackPlan>(key, contents, problems);
        for (const auto& page : result_.trackPlan->pages)
            keys_.push_back(cs2config::trackPageStreamKey(page.id));
    } else if (key.starts_with("gbs-")) {
        const std::int64_t id = std::stoll(key.substr(4));
        const auto* entry = result_.trackPlan ? result_.trackPlan->pageWithId(id) : nullptr;
        if (auto page = parseAs<cs2config::TrackPage>(key, contents, problems))
            result_.pages.push_back({id, entry ? entry->name : std::string(), std::move(*page)});
    }
}

void StartupSequence::queueStateQueries() {
    std::vector<cs2::Message> queries;
    if (options_.queryStates && result_.locomotives) {
        for (const auto& loco : result_.locomotives->locomotives) {
            if (loco.isEmpty())
                continue;
            std::vector<int> functions;
            for (const auto& function : loco.functions)
                functions.push_back(function.number);
            for (cs2::Message& query : locomotiveQueries(cs2::LocId(loco.uid), functions))
                queries.push_back(std::move(query));
        }
    }
    if (options_.queryStates) {
        for (const auto& page : result_.pages)
            for (const auto& element : page.page.elements)
                if (element.category() == cs2config::TrackCategory::Feedback && element.hasArticle())
                    queries.push_back(contactQuery(element.deviceId, element.article));
    }
    result_.stateQueries = queries.size();
    queries_ = std::make_unique<StateQueryRound>(session_, std::move(queries), options_.queriesInFlight);
    connect(queries_.get(), &StateQueryRound::problem, this, &StartupSequence::report);
    connect(queries_.get(), &StateQueryRound::finished, this, [this] {
        result_.stateAnswers = queries_->answered();
        enter(Step::Ready);
        emit ready(result_);
    });
    queries_->start();
}

void StartupSequence::report(const QString& message) {
    result_.problems << message;
    emit problem(message);
}

} // namespace stellwerk::station
