#pragma once

// Frames written as the protocol document writes them, and a table cell as text, for the bus monitor tests.

#include "can/FrameText.h"

#include <QAbstractItemModel>
#include <QString>
#include <gtest/gtest.h>

namespace stellwerk::ui::test {

inline can::CanFrame frame(const char* text) {
    const auto parsed = can::parseFrame(text);
    EXPECT_TRUE(parsed.hasValue()) << text;
    return parsed.hasValue() ? parsed.value().frame : can::CanFrame{};
}

// "System stop" (CS2 on a station's bus, foreign on a module bus).
inline can::CanFrame systemStop() {
    return frame("00004711 5 00 00 00 00 00");
}

inline QString cell(const QAbstractItemModel& model, int row, int column, int role = Qt::DisplayRole) {
    return model.index(row, column).data(role).toString();
}

} // namespace stellwerk::ui::test
