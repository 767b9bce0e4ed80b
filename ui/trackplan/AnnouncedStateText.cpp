#include "trackplan/AnnouncedStateText.h"

namespace stellwerk::ui {

QString AnnouncedStateText::of(model::AnnouncedMeaning meaning) {
    switch (meaning) {
    case model::AnnouncedMeaning::Deactivated:
        return tr("not active");
    case model::AnnouncedMeaning::Activated:
        return tr("active");
    case model::AnnouncedMeaning::Running:
        return tr("running");
    case model::AnnouncedMeaning::Free:
        return tr("free");
    case model::AnnouncedMeaning::Occupied:
        return tr("occupied");
    case model::AnnouncedMeaning::Waiting:
        return tr("waiting");
    case model::AnnouncedMeaning::Reserved:
        return tr("reserved");
    case model::AnnouncedMeaning::Unknown:
        break;
    }
    return tr("unknown");
}

} // namespace stellwerk::ui
