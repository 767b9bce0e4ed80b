#pragma once

#include <QString>
#include <cstdint>
#include <optional>

namespace stellwerk::ui::hexText {

// How the Devices page writes CAN ids, UIDs and register addresses: "0x01FE0001" (digits: at least).
inline QString of(std::uint32_t value, int digits = 1) {
    return QStringLiteral("0x") + QStringLiteral("%1").arg(value, digits, 16, QLatin1Char('0')).toUpper();
}

// A hexadecimal number as a person types it ("0x1FE0001", "1fe0001"); nullopt when it is none.
inline std::optional<std::uint32_t> read(QString text) {
    text = text.trimmed();
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        text = text.mid(2);
    bool ok = false;
    const std::uint32_t value = text.toUInt(&ok, 16);
    return ok && !text.isEmpty() ? std::optional(value) : std::nullopt;
}

} // namespace stellwerk::ui::hexText
