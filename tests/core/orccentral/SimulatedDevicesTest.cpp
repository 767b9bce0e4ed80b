// The simulated OpenRailCAN devices on their own: what each answers to a frame, as the document's tables say
// (001 §Befehlssatz) and the notes decide where it is silent.

#include "OrcRig.h"
#include "orc/Codec.h"

#include <QSignalSpy>

namespace stellwerk::orccentral::test {
namespace {

// Everything a device emits, in document notation.
template <typename Device>
std::vector<std::string> answers(Device& device, std::string_view frame) {
    std::vector<std::string> out;
    QObject::connect(&device, &Device::framesEmitted, &device,
                     [&out](const std::vector<can::CanFrame>& frames) {
                         for (const can::CanFrame& f : frames)
                             out.push_back(can::formatDocument(f));
                     });
    device.receive(can::parseFrame(frame)->frame);
    QObject::disconnect(&device, &Device::framesEmitted, &device, nullptr);
    return out;
}

// Lok Speed (0x81/0x01): the booster holds the loco's state and answers for it (notes O24) with D=1, from
// its own bus id; the derived vector V7 has the same bytes.
TEST(LokSpeed, BoosterAnswersForTheLocoItDrives) {
    sim::SimulatedOrcBooster booster(BoosterUid);
    booster.plugIn();
    EXPECT_TRUE(answers(booster, "11020000 5 01 00 48 01 F4").empty()) << "a set has no answer";
    EXPECT_EQ(booster.speed(0x0048), 500);
    EXPECT_EQ(answers(booster, "11020000 3 01 00 48"), std::vector<std::string>{"11030042 5 01 00 48 01 F4"});
    answers(booster, "09020000 1 00"); // Lok(s) Nothalt
    EXPECT_TRUE(booster.emergencyStopped());
    EXPECT_EQ(booster.speed(0x0048), 0);
}

// Alle dekoder aus (0x88/0x00): the decoder switches nothing until Alle dekoder EIN.
TEST(AlleDekoderAus, DecoderIgnoresSwitchesWhileOff) {
    sim::SimulatedOrcDecoder decoder(DecoderUid);
    decoder.plugIn();
    answers(decoder, "11100000 1 00");
    EXPECT_TRUE(answers(decoder, "11100000 4 03 2E 01 01").empty());
    EXPECT_EQ(decoder.switchCount(), 0);
    answers(decoder, "11100000 1 01");
    EXPECT_EQ(answers(decoder, "11100000 4 03 2E 01 01"), std::vector<std::string>{"15112E01 4 03 2E 01 01"});
    EXPECT_EQ(decoder.outputs(), 1);
}

// enkoder Abfrage with the printed DLC 1 (notes O18: every encoder) is answered with D=1 and 32 inputs.
TEST(EnkoderAbfrage, Dlc1IsAnsweredByEveryEncoder) {
    sim::SimulatedOrcEncoder encoder(EncoderUid);
    encoder.plugIn();
    encoder.setInput(0, true);
    EXPECT_EQ(answers(encoder, "11120000 1 10"), std::vector<std::string>{"17132E10 7 10 2E 10 01 00 00 00"});
    EXPECT_TRUE(answers(encoder, "11120000 3 10 2E 11").empty()) << "another encoder's query";
}

// Ping for another UID, and anything while unplugged: no answer.
TEST(Ping, OnlyTheDeviceWithTheUidAnswersAndOnlyWhenPluggedIn) {
    sim::SimulatedOrcDecoder decoder(DecoderUid);
    EXPECT_TRUE(answers(decoder, "19200000 5 00 3A 2E 2E 01").empty()) << "unplugged";
    decoder.plugIn();
    EXPECT_TRUE(answers(decoder, "19200000 5 00 12 34 56 78").empty());
    EXPECT_EQ(answers(decoder, "19200000 5 00 3A 2E 2E 01"),
              std::vector<std::string>{"1D212E01 7 00 3A 2E 2E 01 01 02"}); // the derived vector V10
}

} // namespace
} // namespace stellwerk::orccentral::test
