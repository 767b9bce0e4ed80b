// Building messages from key=value text: the vocabulary of `stellwerk-cli encode`.

#include "cs2/Fields.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2;

namespace {

CanFrame build(std::string_view name, std::vector<KeyValue> arguments) {
    const auto message = buildMessage(name, arguments);
    EXPECT_TRUE(message.hasValue()) << name << ": " << (message ? "" : message.error());
    return message ? encode(*message) : CanFrame{};
}

std::string buildError(std::string_view name, std::vector<KeyValue> arguments) {
    const auto message = buildMessage(name, arguments);
    EXPECT_FALSE(message.hasValue()) << name;
    return message ? std::string() : message.error();
}

const Field* findField(const std::vector<Field>& fields, std::string_view key) {
    for (const auto& f : fields)
        if (f.key == key)
            return &f;
    return nullptr;
}

} // namespace

TEST(Fields, EveryNameOfTheVocabularyExists) {
    const auto names = messageNames();
    for (std::string_view name : {"system.stop",
                                  "system.go",
                                  "system.halt",
                                  "system.loco-emergency-stop",
                                  "system.loco-cycle-end",
                                  "system.loco-protocol",
                                  "system.accessory-switch-time",
                                  "system.mfx-fast-read",
                                  "system.track-protocols",
                                  "system.mfx-registration-counter",
                                  "system.overload",
                                  "system.status",
                                  "system.device-id",
                                  "system.reset",
                                  "system.mfx-seek",
                                  "loco.discovery",
                                  "mfx.bind",
                                  "mfx.verify",
                                  "loco.speed",
                                  "loco.direction",
                                  "loco.function",
                                  "config.read",
                                  "config.write",
                                  "accessory.switch",
                                  "accessory.config",
                                  "feedback.s88-poll",
                                  "feedback.s88-event",
                                  "feedback.sx1-event",
                                  "ping",
                                  "update.offer",
                                  "update.read-config-data",
                                  "bootloader.can",
                                  "bootloader.track",
                                  "statusdata.config",
                                  "configdata.request",
                                  "configdata.stream",
                                  "connect6021.stream",
                                  "automation.switch",
                                  "unknown"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_EQ(names.size(), 39u);
}

TEST(Fields, LocoSpeedFromProtocolAndAddress) {
    EXPECT_EQ(
        formatDocument(build("loco.speed",
                             {{"protocol", "dcc"}, {"address", "3"}, {"speed", "288"}, {"hash", "0x4711"}})),
        "00084711 6 00 00 C0 03 01 20");
}

TEST(Fields, LocoSpeedFromLocIdWithoutSpeedIsAQuery) {
    EXPECT_EQ(formatDocument(build("loco.speed", {{"locId", "0x4005"}, {"hash", "0x4711"}})),
              "00084711 4 00 00 40 05");
}

TEST(Fields, EnvelopeKeysSetPrioResponseAndHash) {
    const CanFrame frame = build("system.go", {{"prio", "1"}, {"response", "true"}, {"hash", "0x0301"}});
    EXPECT_EQ(stellwerk::cs2::prio(frame), 1);
    EXPECT_TRUE(stellwerk::cs2::isResponse(frame));
    EXPECT_EQ(stellwerk::cs2::hash(frame), 0x0301);
}

TEST(Fields, PacketNumberBecomesTheHash) {
    const CanFrame frame =
        build("statusdata.config",
              {{"response", "true"}, {"form", "packet"}, {"packet", "129"}, {"bytes", "0102"}});
    EXPECT_EQ(stellwerk::cs2::hash(frame), 0x0701);
    EXPECT_EQ(frame.dlc, 2);
}

TEST(Fields, NamedValuesAndScaledTimes) {
    EXPECT_EQ(formatDocument(
                  build("loco.direction", {{"locId", "0xc003"}, {"direction", "toggle"}, {"hash", "0"}})),
              "000A0000 5 00 00 C0 03 03");
    EXPECT_EQ(formatDocument(build("accessory.switch", {{"protocol", "mm2-accessory"},
                                                        {"address", "1"},
                                                        {"position", "1"},
                                                        {"current", "1"},
                                                        {"switchTimeMs", "250"},
                                                        {"hash", "0"}})),
              "00160000 8 00 00 30 00 01 01 00 19");
    EXPECT_EQ(formatDocument(build("config.write", {{"protocol", "dcc"},
                                                    {"address", "3"},
                                                    {"cvNumber", "29"},
                                                    {"value", "6"},
                                                    {"track", "main"},
                                                    {"mode", "bit"},
                                                    {"hash", "0"}})),
              "00100000 8 00 00 C0 03 00 1D 06 A0");
}

TEST(Fields, FileNamesAndVersions) {
    EXPECT_EQ(formatDocument(build("configdata.request", {{"filename", "lokstat"}, {"hash", "0"}})),
              "00400000 8 6C 6F 6B 73 74 61 74 00");
    EXPECT_EQ(formatDocument(build("ping", {{"response", "1"},
                                            {"uid", "0x4743F5DA"},
                                            {"version", "1.62"},
                                            {"deviceType", "0x0010"},
                                            {"hash", "0"}})),
              "00310000 8 47 43 F5 DA 01 3E 00 10");
}

TEST(Fields, ErrorsNameTheKeyAndTheRule) {
    EXPECT_EQ(buildError("loco.drive", {}), "unknown message name 'loco.drive'");
    EXPECT_EQ(buildError("loco.speed", {{"speed", "10"}}),
              "loco.speed: needs locId=<Loc-ID> or protocol=<name> address=<number>");
    EXPECT_EQ(buildError("loco.speed", {{"locId", "0xc003"}, {"speed", "70000"}}),
              "loco.speed: speed=70000 is out of range (0..65535)");
    EXPECT_EQ(buildError("loco.speed", {{"locId", "0xc003"}, {"colour", "red"}}),
              "loco.speed has no field 'colour'");
    EXPECT_EQ(buildError("loco.direction", {{"locId", "1"}, {"direction", "sideways"}}),
              "loco.direction: direction=sideways is not a valid value (one of keep forward backward toggle, "
              "or a number)");
    EXPECT_EQ(buildError("system.stop", {{"subcommand", "1"}}),
              "system.stop: subcommand is derived from the other fields and cannot be set");
    EXPECT_EQ(buildError("accessory.switch", {{"protocol", "dcc-accessory"}, {"address", "0"}}),
              "accessory.switch: address=0 does not exist for protocol dcc-accessory");
    EXPECT_EQ(buildError("accessory.switch", {{"locId", "0x3000"}, {"switchTimeMs", "15"}}),
              "accessory.switch: switchTimeMs=15 must be a multiple of 10");
    EXPECT_EQ(buildError("configdata.request", {{"filename", "verylongname"}}),
              "configdata.request: filename=verylongname is longer than 8 characters");
    EXPECT_EQ(buildError("system.go", {{"prio", "16"}}), "prio=16 is out of range (0..15)");
}

TEST(Fields, DescribeMarksShownOnlyFieldsAsDerived) {
    const auto message = decode(test::frame("00004711 5 00 00 C0 03 03"));
    ASSERT_TRUE(message.hasValue());
    const auto fields = describe(*message);
    ASSERT_NE(findField(fields, "locId"), nullptr);
    EXPECT_FALSE(findField(fields, "locId")->derived);
    EXPECT_TRUE(findField(fields, "protocol")->derived);
    EXPECT_TRUE(findField(fields, "address")->derived);
    EXPECT_TRUE(findField(fields, "subcommand")->derived);
    EXPECT_EQ(findField(fields, "address")->number, 3u);
}
