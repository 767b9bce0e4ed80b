#pragma once

#include <QString>
#include <cstdint>
#include <optional>

class QMimeData;

namespace stellwerk::ui {

// A locomotive dragged from one panel to another (from the Locomotives list onto a block of the plan): its
// Loc-ID under a type of Stellwerk's own, and its name as plain text for anything else it is dropped on.
class LocomotiveMime final {
public:
    static inline const QString Type = QStringLiteral("application/x-stellwerk-locomotive");

    // The caller owns the data (a drag or a model hands it on).
    static QMimeData* make(std::uint32_t locId, const QString& name);
    // The Loc-ID carried; nullopt when the data is no locomotive.
    static std::optional<std::uint32_t> locId(const QMimeData* data);
};

} // namespace stellwerk::ui
