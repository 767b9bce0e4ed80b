#include "ServeCommand.h"

#include "model/Railway.h"
#include "model/Z21Addresses.h"
#include "phones/ListenAddress.h"
#include "station/StartupSequence.h"
#include "withrottleserver/MdnsAnnouncement.h"
#include "withrottleserver/WiThrottleServer.h"
#include "z21server/Z21Server.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>
#include <memory>
#include <ostream>

namespace stellwerk::cli {
namespace {

using phones::ListenAddress;

struct ServeOptions {
    std::optional<ListenAddress> z21;
    std::optional<ListenAddress> withrottle;
    int seconds = 0; // 0: until Ctrl-C
    bool json = false;
};

Expected<ServeOptions, std::string> parseOptions(const std::vector<std::string>& arguments) {
    ServeOptions options;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& word = arguments[i];
        const bool hasValue = i + 1 < arguments.size() && arguments[i + 1].rfind("--", 0) != 0;
        if (word == "--json") {
            options.json = true;
        } else if (word == "--z21") {
            options.z21 =
                ListenAddress::parse(hasValue ? QString::fromStdString(arguments[++i]) : QString(), 21105);
            if (!options.z21)
                return std::string("serve: --z21: expected [HOST:]PORT");
        } else if (word == "--withrottle") {
            options.withrottle =
                ListenAddress::parse(hasValue ? QString::fromStdString(arguments[++i]) : QString(), 12090);
            if (!options.withrottle)
                return std::string("serve: --withrottle: expected [HOST:]PORT");
        } else if (word == "--seconds" && hasValue) {
            options.seconds = std::atoi(arguments[++i].c_str());
            if (options.seconds < 1)
                return std::string("serve: --seconds: not a number of seconds");
        } else {
            return "serve: unknown argument '" + word + "'";
        }
    }
    if (!options.z21 && !options.withrottle)
        options.z21 = ListenAddress{QHostAddress::Any, 21105};
    return options;
}

const char* kindName(z21server::Z21Event::Kind kind) {
    switch (kind) {
    case z21server::Z21Event::Kind::Joined:
        return "joined";
    case z21server::Z21Event::Kind::LoggedOff:
        return "logged-off";
    case z21server::Z21Event::Kind::TimedOut:
        return "timed-out";
    case z21server::Z21Event::Kind::Dropped:
        return "dropped";
    case z21server::Z21Event::Kind::Drove:
        return "drove";
    case z21server::Z21Event::Kind::TakenOver:
        return "taken-over";
    case z21server::Z21Event::Kind::Refused:
        return "refused";
    case z21server::Z21Event::Kind::Flooding:
        return "flooding";
    }
    return "event";
}

const char* kindName(withrottleserver::WiThrottleEvent::Kind kind) {
    using Kind = withrottleserver::WiThrottleEvent::Kind;
    switch (kind) {
    case Kind::Joined:
        return "joined";
    case Kind::Named:
        return "named";
    case Kind::Acquired:
        return "acquired";
    case Kind::Released:
        return "released";
    case Kind::StealNeeded:
        return "steal-needed";
    case Kind::TakenOver:
        return "taken-over";
    case Kind::Refused:
        return "refused";
    case Kind::Flooding:
        return "flooding";
    case Kind::Quit:
        return "quit";
    case Kind::Left:
        return "left";
    case Kind::TimedOut:
        return "timed-out";
    case Kind::Dropped:
        return "dropped";
    }
    return "event";
}

// The station read, the railway and the servers in front of it, living as long as the command.
class ServeRun final : public QObject {
public:
    ServeRun(StationClient& client, ServeOptions options, std::ostream& out, std::ostream& err)
        : QObject(&client), client_(client), options_(std::move(options)), out_(out), err_(err) {
        railway_ = std::make_unique<model::Railway>(client.session());
        station::StartupOptions startupOptions;
        startupOptions.readStatusData = false;
        startup_ = std::make_unique<station::StartupSequence>(client.session(), startupOptions);
        connect(startup_.get(), &station::StartupSequence::ready, this, &ServeRun::stationRead);
        startup_->start();
        client.whenInterrupted([this] { end(); });
    }
    ~ServeRun() override {
        z21_.reset();
        announcement_.reset();
        withrottle_.reset();
        startup_.reset();
        railway_.reset();
    }

private:
    void stationRead(const station::StartupResult& result) {
        railway_->load(result);
        if ((options_.z21 && !startZ21()) || (options_.withrottle && !startWiThrottle()))
            return client_.finish(3);
        if (options_.seconds > 0)
            QTimer::singleShot(options_.seconds * 1000, this, &ServeRun::end);
    }

    bool startZ21() {
        z21server::Z21ServerOptions z21Options;
        z21Options.address = options_.z21->address;
        z21Options.port = options_.z21->port;
        z21_ = std::make_unique<z21server::Z21Server>(addresses_, z21Options);
        if (!z21_->listen()) {
            err_ << "stellwerk-cli serve: Z21 server: " << z21_->errorString().toStdString() << '\n';
            return false;
        }
        z21_->setRailway(railway_.get());
        connect(z21_.get(), &z21server::Z21Server::event, this, [this](const z21server::Z21Event& event) {
            print(kindName(event.kind), event.client, event.address, event.detail);
        });
        print("listening", QStringLiteral("server"), 0,
              QStringLiteral("Z21 LAN on %1:%2").arg(options_.z21->address.toString()).arg(z21_->port()));
        return true;
    }

    bool startWiThrottle() {
        withrottleserver::WiThrottleServerOptions wiOptions;
        wiOptions.address = options_.withrottle->address;
        wiOptions.port = options_.withrottle->port;
        withrottle_ = std::make_unique<withrottleserver::WiThrottleServer>(addresses_, wiOptions);
        if (!withrottle_->listen()) {
            err_ << "stellwerk-cli serve: WiThrottle server: " << withrottle_->errorString().toStdString()
                 << '\n';
            return false;
        }
        withrottle_->setRailway(railway_.get());
        connect(withrottle_.get(), &withrottleserver::WiThrottleServer::event, this,
                [this](const withrottleserver::WiThrottleEvent& event) {
                    print(kindName(event.kind), event.client, 0, event.detail);
                });
        print("listening", QStringLiteral("server"), 0,
              QStringLiteral("WiThrottle on %1:%2")
                  .arg(options_.withrottle->address.toString())
                  .arg(withrottle_->port()));
        announcement_ = std::make_unique<withrottleserver::MdnsAnnouncement>();
        announcement_->announce(QStringLiteral("Stellwerk"), withrottle_->port());
        print("mdns", QStringLiteral("server"), 0, announcement_->why());
        return true;
    }

    void print(const char* kindText, const QString& client, std::uint16_t address, const QString& detail) {
        const QString kind = QString::fromLatin1(kindText);
        if (!options_.json) {
            out_ << kind.toStdString() << ": " << client.toStdString();
            if (address)
                out_ << " loco " << address;
            if (!detail.isEmpty())
                out_ << " (" << detail.toStdString() << ')';
            out_ << std::endl;
            return;
        }
        QJsonObject line{{"event", kind}, {"client", client}};
        if (address)
            line["address"] = address;
        if (!detail.isEmpty())
            line["detail"] = detail;
        out_ << QJsonDocument(line).toJson(QJsonDocument::Compact).toStdString() << std::endl;
    }

    // Every locomotive a client drove is stopped; the station's answers are given a moment.
    void end() {
        if (ending_)
            return;
        ending_ = true;
        if (z21_)
            z21_->stopAll();
        if (withrottle_)
            withrottle_->stopAll();
        QTimer::singleShot(300, this, [this] { client_.finish(Acknowledged); });
    }

    StationClient& client_;
    ServeOptions options_;
    std::ostream& out_;
    std::ostream& err_;
    model::Z21Addresses addresses_;
    std::unique_ptr<model::Railway> railway_;
    std::unique_ptr<station::StartupSequence> startup_;
    std::unique_ptr<z21server::Z21Server> z21_;
    std::unique_ptr<withrottleserver::WiThrottleServer> withrottle_;
    std::unique_ptr<withrottleserver::MdnsAnnouncement> announcement_;
    bool ending_ = false;
};

} // namespace

std::optional<ParsedJob> parseServeCommand(const std::string& command,
                                           const std::vector<std::string>& arguments, std::ostream& out,
                                           std::ostream& err) {
    if (command != "serve")
        return std::nullopt;
    auto options = parseOptions(arguments);
    if (!options)
        return ParsedJob(options.error());
    return ParsedJob(StationJob{
        [options = *options, &out, &err](StationClient& client) { new ServeRun(client, options, out, err); },
        std::nullopt});
}

} // namespace stellwerk::cli
