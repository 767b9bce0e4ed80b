#pragma once

#include "busreading/FrameClassifier.h"
#include "busreading/Handheld.h"

#include <QAbstractProxyModel>
#include <QString>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

class QTimer;

namespace stellwerk::ui {

class BusMonitorModel;

// The bus monitor's filters at once: a protocol, an MS1 handheld, a command (by its vocabulary name), a
// Loc-ID and a piece of text; a row is shown when it passes all that are set. Changing a filter tests the
// rows a slice at a time between events (a million rows take seconds to decode), so the window stays usable
// and shows progress; new rows are tested as they come, and rows the history drops leave without a new scan.
class BusMonitorFilter final : public QAbstractProxyModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorFilter)

public:
    // How long rows are tested per turn of the event loop before other events get their turn.
    static constexpr int SliceMs = 15;

    explicit BusMonitorFilter(QObject* parent = nullptr);
    ~BusMonitorFilter() override;

    void setSourceModel(QAbstractItemModel* model) override;

    // "loco.speed"; empty = every command.
    void setCommand(const QString& name);
    QString command() const { return m_command; }
    // nullopt = every Loc-ID (and rows without one).
    void setLocId(std::optional<std::uint32_t> locId);
    std::optional<std::uint32_t> locId() const { return m_locId; }
    // Case-insensitive, in the message name, the details and the frame bytes; empty = any.
    void setText(const QString& text);
    QString text() const { return m_text; }
    // All three at once, with one new scan when any changed.
    void setFilters(const QString& command, std::optional<std::uint32_t> locId, const QString& text);
    // nullopt = every protocol; else only the frames that belong to it on their bus (Foreign: to none).
    void setProtocol(std::optional<busreading::Protocol> protocol);
    std::optional<busreading::Protocol> protocol() const { return m_protocol; }
    // nullopt = every frame; else only the M-CAN frames of that handheld (either node of its pair, or the
    // name it sent).
    void setHandheld(std::optional<busreading::HandheldReference> handheld);
    const std::optional<busreading::HandheldReference>& handheld() const { return m_handheld; }
    bool isFiltering() const {
        return m_protocol || m_handheld || !m_command.isEmpty() || m_locId || !m_text.isEmpty();
    }
    // Rows are still being tested after a filter changed; scanPercent() says how far it has come.
    bool isScanning() const;
    int scanPercent() const;

    // Reads a Loc-ID as a user writes it: "0xC003", "49155" or a protocol and address ("dcc 3", "mfx 5",
    // "mm2 80"); nullopt when the text is none of these.
    static std::optional<std::uint32_t> parseLocId(const QString& text);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QModelIndex mapToSource(const QModelIndex& proxyIndex) const override;
    QModelIndex mapFromSource(const QModelIndex& sourceIndex) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

signals:
    // While rows are tested after a filter changed, and once more when all are.
    void scanProgress(int percent);

private:
    // Takes the criteria; returns whether any changed.
    bool take(const QString& command, std::optional<std::uint32_t> locId, const QString& text);
    bool accepts(int sourceRow) const;
    void restart();
    void scanSome();
    void sourceAboutToRemove(const QModelIndex& parent, int first, int last);
    void sourceRemoved();
    void sourceAboutToInsert(const QModelIndex& parent, int first, int last);
    void sourceInserted();
    void sourceAboutToReset();
    void sourceReset();
    std::uint64_t sourceEnd() const;

    BusMonitorModel* m_source = nullptr;
    QTimer* m_scanTimer = nullptr;
    std::optional<busreading::Protocol> m_protocol;
    std::optional<busreading::HandheldReference> m_handheld;
    QString m_command;
    std::string m_commandName;
    std::optional<std::uint32_t> m_locId;
    QString m_text;
    std::string m_lowerText;
    bool m_passThrough = true;        // no filter: every source row, one to one
    std::deque<std::uint64_t> m_rows; // source row numbers (BusMonitorModel::firstSequence() based)
    std::uint64_t m_scanned = 0;      // rows below this number were tested
    std::uint64_t m_scanStart = 0;    // where the current scan began, for its progress
    std::size_t m_removing = 0;       // rows between about-to-be-removed and removed
    bool m_inserting = false;
};

} // namespace stellwerk::ui
