#pragma once

#include <QObject>

class QSocketNotifier;

namespace stellwerk::simapp {

// Turns SIGINT and SIGTERM into a Qt signal on the event loop (the handler only writes a byte to a
// socket pair), so that Ctrl-C closes the sockets and quits cleanly.
class ShutdownSignal : public QObject {
    Q_OBJECT

public:
    explicit ShutdownSignal(QObject* parent = nullptr);
    ~ShutdownSignal() override;

    bool installed() const { return notifier_ != nullptr; }

signals:
    void requested();

private:
    static void handle(int signal);

    QSocketNotifier* notifier_ = nullptr;
};

} // namespace stellwerk::simapp
