#include "common/LocomotiveMime.h"

#include <QMimeData>

namespace stellwerk::ui {

QMimeData* LocomotiveMime::make(std::uint32_t locId, const QString& name) {
    auto* data = new QMimeData;
    data->setData(Type, QByteArray::number(locId));
    data->setText(name);
    return data;
}

std::optional<std::uint32_t> LocomotiveMime::locId(const QMimeData* data) {
    if (!data || !data->hasFormat(Type))
        return std::nullopt;
    bool ok = false;
    const std::uint32_t id = data->data(Type).toUInt(&ok);
    return ok && id != 0 ? std::optional<std::uint32_t>(id) : std::nullopt;
}

} // namespace stellwerk::ui
