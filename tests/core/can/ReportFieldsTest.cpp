// The shared report writer of the M-CAN and OpenRailCAN frame reports: its text starts with the frame as
// formatDocument writes it, its JSON holds the frame as formatCandump writes it, whatever the frame.

#include "can/ReportFields.h"

#include "can/FrameText.h"

#include <gtest/gtest.h>

namespace stellwerk::can::test {
namespace {

std::vector<Field> everyFormat() {
    FieldList fields;
    fields.number("speed", 511).hex("uid", 0x4711, 8).flag("go", true).text("name", "Gleis \"1\" \\ a");
    fields.text("bare", "BR01").hex("wide", 0x123456789ABCDEF0ull, 2).flag("off", false).number("zero", 0);
    return fields.list;
}

std::vector<CanFrame> frames() {
    const std::uint8_t bytes[] = {0x00, 0x0F, 0xA0, 0xFF, 0x01, 0x02, 0x03, 0x04};
    CanFrame tooLong = CanFrame::extendedFrame(0x1FFFFFFF, bytes);
    tooLong.dlc = 15; // a broken sender: eight data bytes are kept
    CanFrame wideStandard = CanFrame::standard(0x7FF, std::span(bytes, 2));
    wideStandard.id = 0xABCDE; // more than 11 bits: written with every digit
    return {CanFrame::extendedFrame(0, {}), CanFrame::standard(0x7, std::span(bytes, 1)), tooLong,
            wideStandard};
}

TEST(ReportFields, TextIsTheDocumentNotationThenNameThenFields) {
    const auto fields = everyFormat();
    for (const CanFrame& frame : frames())
        EXPECT_EQ(reportText(frame, "orc.test", fields),
                  formatDocument(frame) + "  orc.test  " + fieldsText(fields));
    EXPECT_EQ(fieldsText(fields),
              "speed=511 uid=0x00004711 go=true name=\"Gleis \\\"1\\\" \\\\ a\" bare=BR01 "
              "wide=0x123456789ABCDEF0 off=false zero=0");
}

TEST(ReportFields, JsonHoldsTheCandumpNotationAndEveryField) {
    const auto fields = everyFormat();
    for (const CanFrame& frame : frames()) {
        const std::string candump = formatCandump(frame);
        const std::size_t hash = candump.find('#');
        const std::string json = reportJson(frame, "mcan.test", fields);
        EXPECT_EQ(json.substr(0, json.find(",\"fields\"")),
                  "{\"id\":\"" + candump.substr(0, hash) + "\",\"dlc\":" + std::to_string(frame.dlc) +
                      ",\"data\":\"" + candump.substr(hash + 1) + "\",\"name\":\"mcan.test\"");
        EXPECT_EQ(
            json.substr(json.find(",\"fields\"")),
            ",\"fields\":{\"speed\":511,\"uid\":\"0x00004711\",\"go\":true,\"name\":\"Gleis \\\"1\\\" \\\\ "
            "a\",\"bare\":\"BR01\",\"wide\":\"0x123456789ABCDEF0\",\"off\":false,\"zero\":0}}");
    }
}

TEST(ReportFields, HexDigitsPadsToTheWidthAndNeverCuts) {
    EXPECT_EQ(hexDigits(0, 1), "0");
    EXPECT_EQ(hexDigits(0, 4), "0000");
    EXPECT_EQ(hexDigits(0xABC, 2), "ABC");
    EXPECT_EQ(hexDigits(~0ull, 0), "FFFFFFFFFFFFFFFF");
    EXPECT_EQ(hexDigits(0x1F, 20), "0000000000000000001F");
}

} // namespace
} // namespace stellwerk::can::test
