#include "StationClient.h"

#include "transport/TransportFactory.h"

#include <QTimer>
#include <atomic>
#include <csignal>
#include <ostream>
#include <utility>

namespace stellwerk::cli {
namespace {

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) {
    interrupted = true;
}

} // namespace

StationClient::StationClient(std::ostream& err, ClientSettings settings, QObject* parent)
    : QObject(parent), err_(err), settings_(settings) {}

// A command that was not acknowledged may still sit in the connection: the connection is reset rather
// than closed, so that the station never gets it after we gave up.
StationClient::~StationClient() {
    qDeleteAll(children()); // what a command made lives on the session: it goes first
    session_.reset();
    if (!transport_)
        return;
    if (lastStatus_ != Acknowledged)
        transport_->resetConnection(QStringLiteral("command not acknowledged"));
    transport_->close();
}

int StationClient::connectTo(const QString& url) {
    auto created = transport::createTransport(url);
    if (!created) {
        err_ << "stellwerk-cli: " << created.error().toStdString() << '\n';
        return UsageError;
    }
    transport_ = std::move(created.value());
    station::StationSettings settings;
    settings.commands = settings_.commands;
    bus_ = std::make_unique<bus::Bus>(*transport_, busreading::BusProfile::centralStation());
    session_ = std::make_unique<station::StationSession>(*bus_, settings);
    // A lost connection is reported twice: the reason, then the same with the transport's retry plan,
    // which the command line does not follow. Only the reason is shown.
    connect(transport_.get(), &transport::Transport::connectionFailed, this, [this](const QString& reason) {
        retryNoteFollows_ = true;
        report(reason);
    });
    connect(transport_.get(), &transport::Transport::problem, this, [this](const QString& message) {
        if (!std::exchange(retryNoteFollows_, false))
            report(message);
    });
    return waitForConnection();
}

void StationClient::report(const QString& message) {
    if (transport_->state() == transport::Transport::State::Connected || status_)
        err_ << "stellwerk-cli: " << message.toStdString() << '\n';
    else
        problem_ = message;
}

int StationClient::waitForConnection() {
    QTimer timeout;
    timeout.setSingleShot(true);
    connect(&timeout, &QTimer::timeout, this, [this] {
        if (problem_.isEmpty())
            problem_ = QStringLiteral("%1: no connection within %2 ms")
                           .arg(transport_->description())
                           .arg(settings_.connectTimeout.count());
        finish(CannotOpen);
    });
    const auto watch =
        connect(transport_.get(), &transport::Transport::stateChanged, this, [this](auto state) {
            if (state == transport::Transport::State::Connected)
                finish(Acknowledged);
            else if (state == transport::Transport::State::Reconnecting || !problem_.isEmpty())
                finish(CannotOpen);
        });
    transport_->open();
    if (transport_->state() == transport::Transport::State::Connected)
        status_ = Acknowledged;
    else if (!problem_.isEmpty())
        status_ = CannotOpen;
    timeout.start(settings_.connectTimeout);
    const int status = status_ ? *status_ : loop_.exec();
    disconnect(watch);
    status_.reset();
    if (status == CannotOpen)
        err_ << "stellwerk-cli: cannot open the transport: " << problem_.toStdString() << '\n';
    return status;
}

int StationClient::run(const StationJob& job) {
    QTimer limit;
    limit.setSingleShot(true);
    connect(&limit, &QTimer::timeout, this, [this] {
        err_ << "stellwerk-cli: the station did not finish the command in time\n";
        finish(NotAcknowledged);
    });
    job.start(*this);
    if (status_)
        return *status_;
    if (job.limit)
        limit.start(*job.limit);
    return loop_.exec();
}

void StationClient::finish(int status) {
    if (status_)
        return;
    status_ = status;
    lastStatus_ = status;
    loop_.exit(status);
}

void StationClient::finishOnInterrupt(int status) {
    whenInterrupted([this, status] { finish(status); });
}

void StationClient::whenInterrupted(std::function<void()> action) {
    interrupted = false;
    std::signal(SIGINT, onInterrupt);
    auto* poll = new QTimer(this);
    connect(poll, &QTimer::timeout, this, [action = std::move(action)] {
        if (interrupted.exchange(false))
            action();
    });
    poll->start(100);
}

} // namespace stellwerk::cli
