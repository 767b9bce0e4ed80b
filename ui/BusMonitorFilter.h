#pragma once

#include <QSortFilterProxyModel>
#include <QString>
#include <cstdint>
#include <optional>

namespace stellwerk::ui {

// The bus monitor's three filters at once: a command (by its vocabulary name), a Loc-ID and a piece of
// text. A row is shown when it passes all that are set; the cheap tests run first, and a row is decoded
// only when a Loc-ID or text is asked for.
class BusMonitorFilter final : public QSortFilterProxyModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorFilter)

public:
    explicit BusMonitorFilter(QObject* parent = nullptr);

    // "loco.speed"; empty = every command.
    void setCommand(const QString& name);
    QString command() const { return m_command; }
    // nullopt = every Loc-ID (and rows without one).
    void setLocId(std::optional<std::uint32_t> locId);
    std::optional<std::uint32_t> locId() const { return m_locId; }
    // Case-insensitive, in the message name, the details and the frame bytes; empty = any.
    void setText(const QString& text);
    QString text() const { return m_text; }
    bool isFiltering() const { return !m_command.isEmpty() || m_locId || !m_text.isEmpty(); }

    // Reads a Loc-ID as a user writes it: "0xC003", "49155" or a protocol and address ("dcc 3", "mfx 5",
    // "mm2 80"); nullopt when the text is none of these.
    static std::optional<std::uint32_t> parseLocId(const QString& text);

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

private:
    QString m_command;
    std::optional<std::uint32_t> m_locId;
    QString m_text;
};

} // namespace stellwerk::ui
