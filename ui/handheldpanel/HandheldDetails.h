#pragma once

#include "mcanhandhelds/Handheld.h"

#include <QGroupBox>
#include <QString>
#include <cstdint>
#include <functional>
#include <vector>

class QComboBox;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace stellwerk::ui {

// One handheld's name and locomotive stack, as a person changes them: rename it, add, remove and reorder
// the locomotives it offers (at most its stack size). Only a handheld logged in at Stellwerk can be changed.
class HandheldDetails final : public QGroupBox {
    Q_OBJECT

public:
    // A locomotive that can go onto a stack.
    struct Choice {
        std::uint32_t locId = 0;
        QString name;
    };

    explicit HandheldDetails(QWidget* parent = nullptr);

    // The handheld to show (null: none), and whether Stellwerk may change it now (it is the master).
    void show(const mcanhandhelds::Handheld* handheld, bool changeable);
    void setChoices(std::vector<Choice> choices);
    void retranslate();

signals:
    void renameRequested(quint32 uid, const QString& name);
    void stackChanged(quint32 uid, const std::vector<std::uint32_t>& stack);

private:
    QString nameOf(std::uint32_t locId) const;
    std::vector<std::uint32_t> stack() const;
    void fillStack(const std::vector<std::uint32_t>& stack);
    void changeStack(std::vector<std::uint32_t> stack);
    void move(int by);
    void updateButtons();

    QLineEdit* m_name;
    QPushButton* m_rename;
    QListWidget* m_stack;
    QComboBox* m_add;
    QPushButton* m_addButton;
    QPushButton* m_remove;
    QPushButton* m_up;
    QPushButton* m_down;
    std::vector<Choice> m_choices;
    std::uint32_t m_uid = 0;
    int m_stackSize = 10;
    bool m_changeable = false;
};

} // namespace stellwerk::ui
