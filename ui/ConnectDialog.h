#pragma once

#include <QDialog>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace stellwerk::ui {

// Station → Connect…: the address of a station (with examples) or the simulated one. Connect checks the
// address and stores the choice in the settings (StationUrlSettings), so the next start uses it too.
class ConnectDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectDialog)

public:
    // `url` is the station in use; empty for the simulated one.
    explicit ConnectDialog(const QString& url, QWidget* parent = nullptr);

    // The chosen address; empty when the simulated station was chosen.
    QString url() const;

    void accept() override;

protected:
    void changeEvent(QEvent* event) override;

private:
    void createWidgets();
    void retranslate();
    void check();

    QLabel* m_urlLabel = nullptr;
    QLineEdit* m_url = nullptr;
    QLabel* m_examples = nullptr;
    QLabel* m_error = nullptr;
    QCheckBox* m_simulated = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QPushButton* m_connect = nullptr;
};

} // namespace stellwerk::ui
