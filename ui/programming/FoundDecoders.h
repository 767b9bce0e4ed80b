#pragma once

#include <QHash>
#include <QTableWidget>
#include <cstdint>
#include <functional>
#include <optional>

namespace stellwerk::ui {

// The mfx decoders a search found, each with what happened to it ("found", "registered on SID 6"); the
// states are kept as how to say them, so that they follow a language switch.
class FoundDecoders final : public QTableWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(FoundDecoders)

public:
    using Say = std::function<QString()>;

    explicit FoundDecoders(QWidget* parent = nullptr);

    // The decoder's row (added and selected if it is new) says `state`.
    void show(std::uint32_t mfxUid, Say state);
    std::optional<std::uint32_t> selectedUid() const;
    void clearDecoders();
    // "0x7a3c1e10".
    static QString uidText(std::uint32_t uid);

protected:
    void changeEvent(QEvent* event) override;

private:
    int rowOf(std::uint32_t mfxUid);
    void retranslate();

    QHash<std::uint32_t, Say> m_states;
};

} // namespace stellwerk::ui
