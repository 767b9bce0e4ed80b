// Decoder programming (document 3.1-3.3, 3.7, 3.8) through the station session against the simulated CS2:
// an mfx search with its steps, bind and verify, CV read and write per protocol, and what the document
// rules out refused before anything is sent.

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

using Outcome = ProgrammingResult::Outcome;
using Problem = ProgrammingResult::Problem;
using Task = ProgrammingResult::Task;

constexpr std::uint32_t NewDecoder = 0x7A3C1E10;
constexpr std::uint32_t Mm2Loco = 0x0018; // MM2 address 24

sim::SimulatedStation::Options withNewDecoder() {
    sim::SimulatedStation::Options options = stationOptions();
    options.newMfxDecoders = {NewDecoder};
    return options;
}

// The bench with a new mfx decoder on the track and the programmer's results collected.
class ProgrammerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.start());
        QObject::connect(&programmer(), &Programmer::finished, &programmer(),
                         [this](const ProgrammingResult& result) { results.push_back(result); });
    }
    Programmer& programmer() { return bench.railway.programmer(); }
    // Waits for the next result.
    ProgrammingResult next() {
        const std::size_t before = consumed;
        EXPECT_TRUE(waitFor([&] { return results.size() > before; }));
        return results.size() > before ? results[consumed++] : ProgrammingResult{};
    }

    ModelBench bench{inlineLayout(), withNewDecoder()};
    std::vector<ProgrammingResult> results;
    std::size_t consumed = 0;
};

TEST_F(ProgrammerTest, DiscoveryReportsItsStepsAndFindsTheNewDecoder) {
    QSignalSpy progress(&programmer(), &Programmer::discoveryProgress);
    ASSERT_TRUE(programmer().discover());
    EXPECT_TRUE(programmer().busy());
    const ProgrammingResult found = next();
    EXPECT_EQ(found.task, Task::Discovery);
    EXPECT_EQ(found.outcome, Outcome::Done);
    EXPECT_EQ(found.mfxUid, NewDecoder);
    EXPECT_EQ(found.ask, std::optional<std::uint8_t>(0xD1));
    ASSERT_EQ(progress.count(), Programmer::DiscoverySteps);
    EXPECT_EQ(progress.first().at(0).toInt(), 1);
    EXPECT_EQ(progress.last().at(0).toInt(), Programmer::DiscoverySteps);
    EXPECT_FALSE(programmer().busy());
}

TEST_F(ProgrammerTest, BindThenVerifyThenTheNextSearchFindsNothing) {
    ASSERT_TRUE(programmer().bind(NewDecoder, 9));
    const ProgrammingResult bound = next();
    EXPECT_EQ(bound.task, Task::Bind);
    EXPECT_EQ(bound.outcome, Outcome::Done);
    ASSERT_TRUE(programmer().verify(NewDecoder, 9));
    const ProgrammingResult verified = next();
    EXPECT_EQ(verified.outcome, Outcome::Done);
    EXPECT_EQ(verified.ask, std::optional<std::uint8_t>(0xD1));
    ASSERT_TRUE(programmer().verify(NewDecoder, 10));
    EXPECT_EQ(next().outcome, Outcome::Refused) << "3.3: the negative answer carries SID 0";
    ASSERT_TRUE(programmer().discover());
    EXPECT_EQ(next().outcome, Outcome::NotFound) << "3.1: a bound decoder takes no part in the search";
}

TEST_F(ProgrammerTest, OneCommandAtATime) {
    ASSERT_TRUE(programmer().discover());
    EXPECT_FALSE(programmer().readCv({cs2::LocId(V100), 1, 0}));
    const ProgrammingResult busy = next();
    EXPECT_EQ(busy.task, Task::ReadCv);
    EXPECT_EQ(busy.outcome, Outcome::Busy);
    EXPECT_EQ(next().task, Task::Discovery);
}

TEST_F(ProgrammerTest, DccWriteThenReadGivesTheWrittenValueVerified) {
    CvWrite write;
    write.target = {cs2::LocId(V100), 3, 0};
    write.value = 42;
    ASSERT_TRUE(programmer().writeCv(write));
    const ProgrammingResult written = next();
    EXPECT_EQ(written.outcome, Outcome::Done);
    EXPECT_TRUE(written.verified);
    ASSERT_TRUE(programmer().readCv({cs2::LocId(V100), 3, 0}));
    const ProgrammingResult read = next();
    EXPECT_EQ(read.outcome, Outcome::Done);
    EXPECT_EQ(read.value, std::optional<std::uint8_t>(42));
}

TEST_F(ProgrammerTest, MfxCvsAreAddressedWithAnIndex) {
    ASSERT_TRUE(programmer().bind(NewDecoder, 9));
    next();
    const cs2::LocId sid9(0x4009);
    CvWrite write;
    write.target = {sid9, 5, 3};
    write.value = 0x77;
    write.track = ProgrammingTrack::Main;
    ASSERT_TRUE(programmer().writeCv(write));
    EXPECT_EQ(next().outcome, Outcome::Done);
    ASSERT_TRUE(programmer().readCv({sid9, 5, 3}));
    EXPECT_EQ(next().value, std::optional<std::uint8_t>(0x77));
    ASSERT_TRUE(programmer().readCv({sid9, 5, 4}));
    EXPECT_NE(next().value, std::optional<std::uint8_t>(0x77)) << "another index is another byte";
}

TEST_F(ProgrammerTest, Mm2ReadIsRefusedBeforeSendingAndMm2WriteIsNotVerified) {
    EXPECT_FALSE(programmer().readCv({cs2::LocId(Mm2Loco), 1, 0}));
    const ProgrammingResult read = next();
    EXPECT_EQ(read.outcome, Outcome::Invalid);
    EXPECT_EQ(read.problem, Problem::Mm2CannotBeRead);
    EXPECT_FALSE(programmer().busy());
    CvWrite write;
    write.target = {cs2::LocId(Mm2Loco), 1, 0};
    write.value = 30;
    ASSERT_TRUE(programmer().writeCv(write));
    const ProgrammingResult written = next();
    EXPECT_EQ(written.outcome, Outcome::Done);
    EXPECT_FALSE(written.verified) << "an MM2 decoder cannot be read back";
}

TEST_F(ProgrammerTest, ReadingAnUnboundMfxSidIsRefusedByTheStation) {
    ASSERT_TRUE(programmer().readCv({cs2::LocId(0x4030), 1, 0}));
    EXPECT_EQ(next().outcome, Outcome::Refused) << "3.7: DLC 6 answer without a value";
}

TEST(ProgrammerRules, TheDocumentsRangesPerProtocol) {
    const auto problemOf = [](const std::optional<ProgrammingResult>& result) {
        return result ? result->problem : Problem::None;
    };
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0xC003), 1023, 0})), Problem::None);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0xC003), 0, 0})), Problem::CvOutOfRange);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0xC003), 1, 2})), Problem::IndexNotMfx);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0x4001), 1, 63})), Problem::None);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0x4001), 1, 64})), Problem::IndexOutOfRange);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0x0801), 6, 0})), Problem::CvOutOfRange);
    EXPECT_EQ(problemOf(Programmer::checkRead({cs2::LocId(0x3000), 1, 0})), Problem::NotProgrammable);

    CvWrite write;
    write.target = {cs2::LocId(0x0018), 257, 0};
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::CvOutOfRange) << "MM2: CV 1-256";
    write.target = {cs2::LocId(0x0801), 1, 0};
    write.track = ProgrammingTrack::Main;
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::ProgrammingTrackOnly) << "SX1";
    write.target = {cs2::LocId(0x4001), 1, 0};
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::IndexOutOfRange) << "mfx write index 1-63";
    write.target = {cs2::LocId(0x0018), 1, 0};
    write.track = ProgrammingTrack::Programming;
    write.mode = cs2::DccProgrammingMode::Register;
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::ModeNotDcc);
    write.target = {cs2::LocId(0xC003), 29, 0};
    write.mode = cs2::DccProgrammingMode::Bit;
    write.value = 5;
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::BitValueForm);
    write.value = CvWrite::bitValue(5, true);
    EXPECT_EQ(write.value, 0xFD);
    EXPECT_EQ(problemOf(Programmer::checkWrite(write)), Problem::None);
}

} // namespace
// The limits the Programming page takes from the programmer fit the Loc-ID ranges (issue 12).
TEST(ProgrammerLimits, FitTheLocIdRanges) {
    EXPECT_TRUE(cs2::LocId::fromAddress(cs2::Protocol::Dcc, Programmer::MaxAddress));
    EXPECT_TRUE(cs2::LocId::fromAddress(cs2::Protocol::Mfx, Programmer::MaxAddress));
    EXPECT_FALSE(cs2::LocId::fromAddress(cs2::Protocol::Dcc, Programmer::MaxAddress + 1));
    EXPECT_FALSE(cs2::LocId::fromAddress(cs2::Protocol::Mfx, Programmer::MaxSid + 1));
    EXPECT_EQ(Programmer::MaxCv, 1023);  // 10 bits
    EXPECT_EQ(Programmer::MaxIndex, 63); // 6 bits
}

} // namespace stellwerk::model::test
