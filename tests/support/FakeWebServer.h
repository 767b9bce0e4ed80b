#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <map>

namespace stellwerk::support {

// A station's web server under the test's control, on a free loopback port: it serves pictures, or
// breaks the way a station on a layout does (gone mid-picture, garbage, silent, a huge answer, away).
class FakeWebServer : public QObject {
public:
    enum class Mode { Serve, CutMidBody, Garbage, Silent, Huge, Html };

    FakeWebServer() {
        connect(&server_, &QTcpServer::newConnection, this, &FakeWebServer::accept);
        start();
    }
    // Listens again on the same port after stop() (the first time on a free one).
    bool start() {
        if (!server_.listen(QHostAddress::LocalHost, port_))
            return false;
        port_ = server_.serverPort();
        return true;
    }
    // Away: the port refuses connections and open ones are cut.
    void stop() {
        server_.close();
        for (QTcpSocket* socket : server_.findChildren<QTcpSocket*>())
            socket->abort();
    }
    QString address() const { return QStringLiteral("http://127.0.0.1:%1").arg(port_); }

    void setMode(Mode mode) { mode_ = mode; }
    void add(const QByteArray& name, const QByteArray& bytes) { files_[name] = bytes; }
    int requests() const { return requests_; }
    int mostAtOnce() const { return mostAtOnce_; }

private:
    void accept() {
        while (QTcpSocket* socket = server_.nextPendingConnection()) {
            socket->setParent(&server_);
            ++open_;
            mostAtOnce_ = std::max(mostAtOnce_, open_);
            connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
                --open_;
                socket->deleteLater();
            });
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] { read(socket); });
        }
    }
    void read(QTcpSocket* socket) {
        QByteArray& request = pending_[socket];
        request += socket->readAll();
        if (!request.contains("\r\n\r\n"))
            return;
        ++requests_;
        const QByteArray target = request.split(' ').value(1);
        pending_.erase(socket);
        answer(socket, QByteArray::fromPercentEncoding(target.mid(QByteArray("/icons/").size())));
    }
    void answer(QTcpSocket* socket, const QByteArray& name) {
        const auto file = files_.find(name);
        switch (mode_) {
        case Mode::Silent:
            return;
        case Mode::Garbage:
            socket->write("\x01\x02 garbage from the station\r\n\r\n\xff\xfe");
            break;
        case Mode::Html:
            socket->write(response("200 OK", "text/html", "<html><body>Lokbild</body></html>"));
            break;
        case Mode::Huge:
            socket->write(response("200 OK", "image/png", QByteArray(600 * 1024, 'x')));
            break;
        case Mode::CutMidBody:
            if (file != files_.end()) {
                const QByteArray whole = response("200 OK", "image/png", file->second);
                socket->write(whole.left(whole.size() - file->second.size() / 2));
                socket->flush();
                socket->abort(); // the station is switched off while it sends
                return;
            }
            [[fallthrough]];
        case Mode::Serve:
            socket->write(file == files_.end() ? response("404 Not Found", "text/plain", "Not Found\n")
                                               : response("200 OK", "image/png", file->second));
            break;
        }
        socket->disconnectFromHost();
    }
    static QByteArray response(const QByteArray& status, const QByteArray& type, const QByteArray& body) {
        return "HTTP/1.0 " + status + "\r\nContent-Type: " + type +
               "\r\nContent-Length: " + QByteArray::number(body.size()) + "\r\nConnection: close\r\n\r\n" +
               body;
    }

    QTcpServer server_;
    std::uint16_t port_ = 0;
    Mode mode_ = Mode::Serve;
    std::map<QByteArray, QByteArray> files_;
    std::map<QTcpSocket*, QByteArray> pending_;
    int requests_ = 0;
    int open_ = 0;
    int mostAtOnce_ = 0;
};

} // namespace stellwerk::support
