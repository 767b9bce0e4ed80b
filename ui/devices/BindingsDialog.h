#pragma once

#include "model/DeviceBindings.h"

#include <QDialog>
#include <QStringList>
#include <functional>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// Which keyboard articles a device output switches and which contacts a device input lights: two lists
// to remove from and a line each to add with (the article or contact, then the relay, decoder output,
// encoder input or module input). What is bound here is what the track plan, the keyboard and routes use.
class BindingsDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BindingsDialog)

public:
    // `modules`: the RO modules' names; `decoders`/`encoders`: the OpenRailCAN bus ids / UIDs known now.
    struct Choices {
        QStringList modules;
        QList<std::uint16_t> decoders;
        QList<std::uint32_t> encoders;
        QString note; // where the bindings are kept
    };
    BindingsDialog(model::DeviceBindings bindings, const model::Railway& railway, Choices choices,
                   QWidget* parent = nullptr);

    const model::DeviceBindings& bindings() const { return m_bindings; }
    // Adds what the accessory / contact line says; false (and a reason under it) when it cannot.
    bool addAccessory();
    bool addContact();
    QComboBox& accessoryChoice() const { return *m_accessory; }
    QComboBox& accessoryKind() const { return *m_outputKind; }
    QComboBox& accessorySource() const { return *m_outputSource; }
    QSpinBox& accessoryNumber() const { return *m_outputNumber; }
    QComboBox& contactChoice() const { return *m_contact; }
    QComboBox& contactKind() const { return *m_inputKind; }
    QComboBox& contactSource() const { return *m_inputSource; }
    QSpinBox& contactNumber() const { return *m_inputNumber; }
    QTableWidget& accessoryTable() const { return *m_accessories; }
    QTableWidget& contactTable() const { return *m_contacts; }
    QString problem() const;

    // "relay 3 of “Demo RO”", "OpenRailCAN decoder 0x0101, output 0", ...
    static QString describe(const model::AccessoryBinding& binding);
    static QString describe(const model::ContactBinding& binding);

private:
    struct LineFields {
        QComboBox* item;
        QComboBox* kind;
        QComboBox* source;
        QSpinBox* number;
    };
    QWidget* accessoryLine();
    QWidget* bindingLine(const LineFields& fields, const QString& addName, const std::function<void()>& add,
                         const std::function<void()>& remove);
    QWidget* contactLine();
    void outputKindChanged();
    void inputKindChanged();
    void fillTables();
    void removeSelected(QTableWidget* table);
    QString accessoryName(std::int64_t id) const;
    QString contactName(model::ContactKey key) const;
    void refuse(const QString& why);

    model::DeviceBindings m_bindings;
    const model::Railway& m_railway;
    Choices m_choices;
    QTableWidget* m_accessories;
    QComboBox* m_accessory;
    QComboBox* m_outputKind;
    QComboBox* m_outputSource;
    QSpinBox* m_outputNumber;
    QTableWidget* m_contacts;
    QComboBox* m_contact;
    QComboBox* m_inputKind;
    QComboBox* m_inputSource;
    QSpinBox* m_inputNumber;
    QLabel* m_problem;
};

} // namespace stellwerk::ui
