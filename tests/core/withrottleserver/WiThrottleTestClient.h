#pragma once

// A WiThrottle client of the tests' own, written from the codec: it sends lines (or any bytes) to the
// server over loopback and keeps every line it reads, as text and as read by the codec.

#include "ReceivedMessages.h"
#include "withrottle/LineSplitter.h"
#include "withrottle/ServerLines.h"

#include <QTcpSocket>
#include <QTest>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::withrottleserver::test {

class WiThrottleTestClient : public support::ReceivedMessages<withrottle::ServerLine> {
public:
    explicit WiThrottleTestClient(quint16 serverPort) {
        QObject::connect(&socket_, &QTcpSocket::readyRead, &socket_, [this] { read(); });
        socket_.connectToHost(QHostAddress::LocalHost, serverPort);
        socket_.waitForConnected(5000);
    }

    void send(const withrottle::ClientMessage& message) {
        sendText(withrottle::formatClientLine(message) + "\n");
    }
    void sendText(const std::string& bytes) {
        socket_.write(bytes.data(), qint64(bytes.size()));
        socket_.flush();
    }
    void close() { socket_.abort(); }
    bool connected() const { return socket_.state() == QAbstractSocket::ConnectedState; }

    bool waitForText(const std::string& text, int timeoutMs = 5000) {
        return QTest::qWaitFor([&] { return hasText(text); }, timeoutMs);
    }
    bool hasText(const std::string& text) const {
        return std::find(texts.begin(), texts.end(), text) != texts.end();
    }
    // The last speed the server told of a loco key, in 0..126.
    std::optional<int> speedOf(const std::string& key) const {
        std::optional<int> speed;
        for (const auto& status : all<withrottle::LocoStatus>())
            if (status.key == key)
                if (const auto* s = std::get_if<withrottle::SpeedState>(&status.update))
                    speed = s->speed;
        return speed;
    }
    std::optional<bool> functionOf(const std::string& key, int function) const {
        std::optional<bool> on;
        for (const auto& status : all<withrottle::LocoStatus>())
            if (const auto* f = std::get_if<withrottle::FunctionState>(&status.update);
                f && status.key == key && f->function == function)
                on = f->on;
        return on;
    }

    std::vector<std::string> texts;

private:
    void read() {
        const QByteArray bytes = socket_.readAll();
        for (const std::string& text :
             splitter_.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())))) {
            texts.push_back(text);
            if (auto line = withrottle::parseServerLine(text))
                received.push_back(std::move(*line));
        }
    }

    QTcpSocket socket_;
    withrottle::LineSplitter splitter_{1 << 20};
};

} // namespace stellwerk::withrottleserver::test
