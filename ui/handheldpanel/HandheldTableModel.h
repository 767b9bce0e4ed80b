#pragma once

#include "mcanhandhelds/Handheld.h"

#include <QAbstractTableModel>
#include <QTimer>
#include <functional>
#include <vector>

namespace stellwerk::ui {

// The MS1 handhelds on the bus, one row each: name, node, state, the locomotive it drives with speed,
// direction and functions, and its stack. Rows follow the master's list; a burst of changes becomes one
// update (a handheld polls four times a second).
class HandheldTableModel final : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Name, Node, State, Locomotive, Speed, Functions, Stack, ColumnCount };
    // The name of a locomotive by its Loc-ID (empty when unknown).
    using LocoName = std::function<QString(std::uint32_t)>;

    explicit HandheldTableModel(QObject* parent = nullptr);

    // Shows `handhelds` (soon, not at once: several calls in a row make one update).
    void show(std::vector<mcanhandhelds::Handheld> handhelds);
    void setLocoName(LocoName name) { m_locoName = std::move(name); }
    const std::vector<mcanhandhelds::Handheld>& handhelds() const { return m_rows; }
    const mcanhandhelds::Handheld* handheld(int row) const;
    int rowOf(std::uint32_t uid) const;
    // Applies what show() left waiting (tests, and before reading the rows).
    void flush();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    static QString stateText(const mcanhandhelds::Handheld& handheld);

private:
    QString text(const mcanhandhelds::Handheld& handheld, int column) const;
    QString locoText(const mcanhandhelds::Handheld& handheld) const;

    std::vector<mcanhandhelds::Handheld> m_rows;
    std::vector<mcanhandhelds::Handheld> m_waiting;
    bool m_hasWaiting = false;
    QTimer m_flush;
    LocoName m_locoName;
};

} // namespace stellwerk::ui
