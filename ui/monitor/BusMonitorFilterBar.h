#pragma once

#include <QStringList>
#include <QWidget>

class QComboBox;
class QLineEdit;
class QTimer;

namespace stellwerk::ui {

class BusMonitorFilter;

// The bus monitor's filter line (find text, protocol, handheld, command, Loc-ID), so that the panel does
// not read what people type: it hands what was chosen or typed (typing once it pauses) to the
// BusMonitorFilter, and says what it could not read.
class BusMonitorFilterBar final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorFilterBar)

public:
    explicit BusMonitorFilterBar(BusMonitorFilter* filter, QWidget* parent = nullptr);

    // Each applies at once. The text ones return false (and filter nothing by it) for a text they cannot
    // read, the lists for a name they do not hold.
    void setFilterText(const QString& text);
    bool setProtocolFilter(const QString& name);
    bool setCommandFilter(const QString& name);
    bool setLocIdFilter(const QString& text);
    bool setHandheldFilter(const QString& text);
    // What was typed but not understood, one short sentence each, for the monitor's counter line.
    QStringList problems() const;

signals:
    // The filter took what the bar shows.
    void applied();

protected:
    void changeEvent(QEvent* event) override;

private:
    QLineEdit* lineEdit(const char* name);
    QComboBox* protocolBox();
    QComboBox* commandBox();
    void apply();
    void showValidity(QLineEdit* edit, bool valid);
    void retranslate();

    BusMonitorFilter* m_filter;
    QLineEdit* m_textEdit = nullptr;
    QComboBox* m_protocolBox = nullptr;
    QLineEdit* m_handheldEdit = nullptr;
    QComboBox* m_commandBox = nullptr;
    QLineEdit* m_locIdEdit = nullptr;
    QTimer* m_delay = nullptr;
    bool m_locIdValid = true;
    bool m_handheldValid = true;
};

} // namespace stellwerk::ui
