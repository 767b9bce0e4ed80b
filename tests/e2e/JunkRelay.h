#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QObject>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <cstdint>

namespace stellwerk::e2e {

// A man in the middle between the app's TcpTransport and the station: passes the bytes on both ways and
// lets a test put junk into the stream towards the app, as a broken gateway would.
class JunkRelay : public QObject {
public:
    explicit JunkRelay(std::uint16_t stationPort) : stationPort_(stationPort) {
        listening_ = server_.listen(QHostAddress::LocalHost, 0);
        connect(&server_, &QTcpServer::newConnection, this, &JunkRelay::accept);
    }

    bool listening() const { return listening_; }
    std::uint16_t port() const { return server_.serverPort(); }
    int connections() const { return connections_; }

    // Bytes for the app, between what the station sent.
    void injectToApp(const QByteArray& bytes) {
        if (app_)
            app_->write(bytes);
    }
    // Sends the bytes, then ends the app's connection (the bytes are delivered first).
    void endAppConnectionAfter(const QByteArray& bytes) {
        if (!app_)
            return;
        app_->write(bytes);
        app_->disconnectFromHost();
    }

private:
    void accept() {
        while (QTcpSocket* app = server_.nextPendingConnection()) {
            auto* station = new QTcpSocket(app); // goes when the app's connection goes
            station->connectToHost(QHostAddress::LocalHost, stationPort_);
            connect(app, &QTcpSocket::readyRead, station, [app, station] { station->write(app->readAll()); });
            connect(station, &QTcpSocket::readyRead, app, [app, station] { app->write(station->readAll()); });
            connect(app, &QTcpSocket::disconnected, app, &QObject::deleteLater);
            app_ = app;
            ++connections_;
        }
    }

    std::uint16_t stationPort_;
    QTcpServer server_;
    QPointer<QTcpSocket> app_;
    int connections_ = 0;
    bool listening_ = false;
};

} // namespace stellwerk::e2e
