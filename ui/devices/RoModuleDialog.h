#pragma once

#include "connection/DeviceSettings.h"

#include <QDialog>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace stellwerk::ui {

// Adding or editing an RO module: its name, the bus it is wired to, its CAN ids and frame format, where its
// relays, inputs and change flags are, and how often its inputs are read. What the module cannot be (an id
// too wide for its format, equal ids, a register block past the end, a name already used) is said under
// the form, and OK stays off until it is right.
class RoModuleDialog final : public QDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RoModuleDialog)

public:
    // `takenNames`: the other modules' names.
    RoModuleDialog(const connection::RoModuleSettings& module, QStringList takenNames,
                   QWidget* parent = nullptr);

    // The module as the form says; meaningful when problem() is empty.
    connection::RoModuleSettings module() const;
    // Why the module cannot be saved as it is; empty when it can.
    QString problem() const;

private:
    struct BlockFields {
        QLineEdit* address;
        QComboBox* width;
        QSpinBox* count;
    };
    BlockFields blockFields(const ro::RegisterBlock& block);
    QWidget* blockRow(const BlockFields& fields);
    void fill(const connection::RoModuleSettings& module);
    void check();

    QStringList m_taken;
    QLineEdit* m_name;
    QSpinBox* m_bus;
    QComboBox* m_format;
    QLineEdit* m_requestId;
    QLineEdit* m_answerId;
    BlockFields m_outputs;
    BlockFields m_inputs;
    QCheckBox* m_hasFlags;
    BlockFields m_flags;
    QSpinBox* m_poll;
    QLabel* m_problem;
    QDialogButtonBox* m_buttons;
};

} // namespace stellwerk::ui
