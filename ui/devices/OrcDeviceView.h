#pragma once

#include <QPointer>
#include <QWidget>
#include <cstdint>
#include <map>
#include <optional>

class QLabel;

namespace stellwerk::orccentral {
class OrcSession;
}

namespace stellwerk::ui {

class SignalGrid;

// One OpenRailCAN device as the Devices panel shows it: UID, type, bus id, version and whether it answers;
// an encoder's inputs live, a decoder's outputs as it last confirmed them, a booster's overloads.
class OrcDeviceView final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(OrcDeviceView)

public:
    explicit OrcDeviceView(QWidget* parent = nullptr);

    void setDevice(orccentral::OrcSession* session, std::uint32_t uid);
    SignalGrid& signalGrid() const { return *m_signals; }
    QString detailsText() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void attach(orccentral::OrcSession* session);
    void update();
    QString overloadText() const;

    QPointer<orccentral::OrcSession> m_session;
    std::uint32_t m_uid = 0;
    std::map<std::uint16_t, std::uint8_t> m_confirmed; // Pos each decoder confirmed, by bus id
    QLabel* m_title;
    QLabel* m_details;
    QLabel* m_signalsLabel;
    SignalGrid* m_signals;
};

} // namespace stellwerk::ui
