#pragma once

#include <QDialog>

class QButtonGroup;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace stellwerk::ui {

// Station → Connect…: the simulated station, a CS2/CS3 over UDP or TCP by its host, a CAN interface from
// the ones Qt's CAN plugins offer, or any address typed in full; the recent choices one click away.
// Further buses (a USB-CAN adapter wired to modules) can be listed beside the station, comma-separated.
// Connect checks the addresses and stores the choice (StationUrlSettings), so the next start uses it too.
// Connecting itself happens afterwards, in the background: the dialog never waits for a station.
class ConnectDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectDialog)

public:
    enum class Kind { Simulated, Udp, Tcp, CanBus };

    // `url` is the station in use; empty for the simulated one.
    explicit ConnectDialog(const QString& url, QWidget* parent = nullptr);

    // The chosen address; empty when the simulated station was chosen.
    QString url() const;
    Kind kind() const;
    // Fills the dialog from an address (as stored, typed or recent); an unreadable one is kept as typed.
    void setUrl(const QString& url);
    // The further buses' addresses, as listed (empty entries left out).
    QStringList furtherBuses() const;
    void setFurtherBuses(const QStringList& addresses);
    // Lists the CAN interfaces the plugins offer now.
    void refreshInterfaces();
    void accept() override;

protected:
    void changeEvent(QEvent* event) override;

private:
    void createWidgets();
    QLayout* createChoices();
    void createRecent();
    void retranslate();
    void chooseKind(Kind kind);
    void composeUrl();
    void readUrl();
    void check();
    QString furtherBusError() const;

    QComboBox* m_recent = nullptr;
    QLabel* m_recentLabel = nullptr;
    QButtonGroup* m_kinds = nullptr;
    QRadioButton* m_simulated = nullptr;
    QRadioButton* m_udp = nullptr;
    QRadioButton* m_tcp = nullptr;
    QRadioButton* m_can = nullptr;
    QLabel* m_hostLabel = nullptr;
    QLineEdit* m_host = nullptr;
    QLabel* m_interfaceLabel = nullptr;
    QComboBox* m_interface = nullptr;
    QPushButton* m_refresh = nullptr;
    QLabel* m_urlLabel = nullptr;
    QLineEdit* m_url = nullptr;
    QLabel* m_examples = nullptr;
    QLabel* m_furtherLabel = nullptr;
    QLineEdit* m_further = nullptr;
    QLabel* m_furtherHint = nullptr;
    QLabel* m_error = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QPushButton* m_connect = nullptr;
    bool m_syncing = false; // fields and address are being matched to each other
};

} // namespace stellwerk::ui
