#pragma once

#include <QHash>
#include <QList>
#include <QObject>
#include <QString>
#include <cstdint>
#include <optional>

namespace stellwerk::model {

class Railway;

// How a locomotive runs, in the railway's words, as every kind of throttle reads it.
struct LocoRun {
    int speed = 0; // 0..1000
    bool forward = true;
    std::uint32_t functions = 0; // bit n: function n is on

    bool operator==(const LocoRun&) const = default;
};

// Who drives which locomotive, across every kind of throttle (MS1 handhelds, OpenRailCAN throttles, Z21 and
// WiThrottle clients): one throttle at a time (the MS1 rule), and the last one to drive takes it over, the
// one before told (takenOver), as the Z21 protocol's last writer and WiThrottle's steal allow.
class LocoOwners final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocoOwners)

public:
    explicit LocoOwners(QObject* parent = nullptr) : QObject(parent) {}

    // The throttle that drives the locomotive now; empty: nobody.
    QString driverOf(quint32 loco) const { return drivers_.value(loco); }
    QList<quint32> drivenBy(const QString& throttle) const;
    // The throttle drives the locomotive from now on; the one that drove it before (empty: nobody, or the
    // same throttle) is returned and told with takenOver.
    QString take(quint32 loco, const QString& throttle);
    // The throttle lets go of the locomotive (no-op when another drives it).
    void release(quint32 loco, const QString& throttle);
    // The throttle lets go of every locomotive it drove; those are returned.
    QList<quint32> releaseAll(const QString& throttle);

signals:
    void takenOver(quint32 loco, const QString& from, const QString& to);
    void driverChanged(quint32 loco, const QString& driver);

private:
    QHash<quint32, QString> drivers_;
};

// The one way a throttle that is not the desk drives the railway, whatever its kind: it reads a locomotive's
// state as the station confirmed it, and drives it (speed, direction, functions, emergency stop, stop all)
// with the same commands the desk sends, in the name of a throttle that the owner book then names as its
// driver. Made by the railway, one per railway.
class ThrottlePort final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ThrottlePort)

public:
    explicit ThrottlePort(Railway& railway, QObject* parent = nullptr);

    Railway& railway() const { return railway_; }
    LocoOwners& owners() { return owners_; }
    const LocoOwners& owners() const { return owners_; }

    // How the locomotive runs as the station confirmed it: nullopt for a locomotive the railway does not know
    // or while its speed and direction are not reported; functions not reported count as off.
    std::optional<LocoRun> confirmed(quint32 loco) const;
    // How the railway shows it (the last values reported, also while they are not reported now); nullopt for
    // a locomotive the railway does not know.
    std::optional<LocoRun> shown(quint32 loco) const;
    // True while the station is heard and its state reported: a throttle's command can be carried out.
    bool canDrive() const;
    // The track power; nullopt while it is not known.
    std::optional<bool> powerOn() const;

    void setSpeed(const QString& throttle, quint32 loco, int speed);
    void setDirection(const QString& throttle, quint32 loco, bool forward);
    void setFunction(const QString& throttle, quint32 loco, int function, bool on);
    void emergencyStop(const QString& throttle, quint32 loco);
    // The station's STOP (every locomotive, the track power off) or GO.
    void setPower(bool on);
    // A throttle went away: every locomotive it drove is stopped (speed 0) and let go; those are returned.
    QList<quint32> stopDrivenBy(const QString& throttle);

    // The names the railway's own kinds of throttle drive under.
    static QString handhelds() { return QStringLiteral("ms1"); }
    static QString orcThrottles() { return QStringLiteral("orc"); }

private:
    Railway& railway_;
    LocoOwners owners_;
};

} // namespace stellwerk::model
