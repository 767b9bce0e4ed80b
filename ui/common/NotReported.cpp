#include "common/NotReported.h"

#include "model/Railway.h"

namespace stellwerk::ui {

bool NotReported::applies(const model::Railway* railway) {
    return railway && !railway->isStateReported();
}

QString NotReported::word() {
    return tr("not reported");
}

QString NotReported::reason() {
    return tr("Not reported: the station is silent or being reconnected. This is the last state it "
              "reported; it may no longer be true.");
}

} // namespace stellwerk::ui
