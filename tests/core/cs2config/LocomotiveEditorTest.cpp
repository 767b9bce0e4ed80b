// The locomotive editor against real lokomotive.cs2 files (read in place from the corpus): a change
// rewrites only its own lines, untouched records come back byte for byte, bad values are refused.

#include "cs2config/LocomotiveEditor.h"

#include "ConfigTestSupport.h"

#include <QTemporaryDir>

namespace stellwerk::cs2config::test {
namespace {

using Kind = EditProblem::Kind;

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// The lines that differ between two texts of the same line count (the test fails otherwise).
std::vector<std::string> editedLines(const std::string& before, const std::string& after) {
    const std::vector<std::string> a = linesOf(before), b = linesOf(after);
    EXPECT_EQ(a.size(), b.size());
    std::vector<std::string> changed;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] != b[i])
            changed.push_back(b[i]);
    return changed;
}

struct Corpus {
    explicit Corpus(std::string_view file) : bytes(readCorpus(file)) {
        Diagnostics diagnostics;
        editor = LocomotiveEditor(LocomotiveFile::read(Document::parse(bytes, diagnostics), diagnostics));
    }
    std::size_t indexOf(std::string_view name) const {
        for (std::size_t i = 0; i < editor.locomotives().size(); ++i)
            if (editor.locomotives()[i].name == name)
                return i;
        ADD_FAILURE() << "no locomotive " << name;
        return 0;
    }
    LocomotiveSettings settingsOf(std::string_view name) const {
        return LocomotiveSettings::of(editor.locomotives()[indexOf(name)]);
    }

    std::string bytes;
    LocomotiveEditor editor;
};

TEST(LocomotiveEditor, UntouchedFilesComeBackByteForByte) {
    for (const std::string_view file :
         {corpus::lokomotiveTrainControl, corpus::lokomotiveGbert, corpus::lokomotiveSrseii}) {
        const Corpus loaded(file);
        EXPECT_EQ(loaded.editor.bytes(), loaded.bytes) << file;
        EXPECT_FALSE(loaded.editor.modified());
    }
}

TEST(LocomotiveEditor, ARenameChangesOnlyTheNameLine) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    LocomotiveSettings settings = loaded.settingsOf("VT 11.5 TEE");
    settings.name = "VT 11.5 Helvetia";
    ASSERT_EQ(loaded.editor.apply(loaded.indexOf("VT 11.5 TEE"), settings), std::nullopt);
    EXPECT_TRUE(loaded.editor.modified());
    EXPECT_EQ(editedLines(loaded.bytes, loaded.editor.bytes()),
              std::vector<std::string>{" .name=VT 11.5 Helvetia"});
}

TEST(LocomotiveEditor, RecordsBeforeAndAfterTheEditedOneStayByteIdentical) {
    Corpus loaded(corpus::lokomotiveGbert);
    LocomotiveSettings settings = loaded.settingsOf("111 043-6");
    settings.address = 0x2A;
    settings.functions = {{1, 23, FunctionTrigger::Timed, 5}};
    ASSERT_EQ(loaded.editor.apply(loaded.indexOf("111 043-6"), settings), std::nullopt);
    const std::string after = loaded.editor.bytes();
    // The address is written as the file writes it (hex), the uid follows it, F1 gets its icon and time.
    EXPECT_EQ(editedLines(loaded.bytes, after),
              (std::vector<std::string>{" .uid=0x2a", " .adresse=0x2a", " ..typ=23", " ..dauer=5"}));
    const std::size_t firstChange = loaded.bytes.find(" .uid=0xb\n .name=111 043-6");
    EXPECT_EQ(after.substr(0, firstChange), loaded.bytes.substr(0, firstChange));
    const std::size_t next = loaded.bytes.find(" .name=140 239-5");
    EXPECT_EQ(after.substr(after.find(" .name=140 239-5")), loaded.bytes.substr(next));
}

TEST(LocomotiveEditor, AddressesOutsideTheDecodersRangeAreRefused) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    LocomotiveSettings settings = loaded.settingsOf("MZ");
    settings.decoder = LocomotiveDecoder::Dcc;
    settings.address = 10240;
    const auto problem = loaded.editor.apply(loaded.indexOf("MZ"), settings);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->kind, Kind::AddressOutOfRange);
    EXPECT_EQ(problem->minimum, 1);
    EXPECT_EQ(problem->maximum, 10239);
    EXPECT_EQ(problem->describe(), "the address must be 1-10239");
    settings.decoder = LocomotiveDecoder::Mm2Dil8;
    settings.address = 81;
    EXPECT_EQ(loaded.editor.check(settings, loaded.indexOf("MZ"))->maximum, 80);
    settings.decoder = LocomotiveDecoder::Mm2Prg;
    settings.address = 0;
    EXPECT_EQ(loaded.editor.check(settings, loaded.indexOf("MZ"))->kind, Kind::AddressOutOfRange);
    EXPECT_FALSE(loaded.editor.modified());
    EXPECT_EQ(loaded.editor.bytes(), loaded.bytes) << "a refused change loses nothing and changes nothing";
}

TEST(LocomotiveEditor, AnAddressOrNameInUseIsRefusedWithTheOtherLocomotive) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    LocomotiveSettings settings = loaded.settingsOf("MZ");
    settings.address = 5;
    settings.decoder = LocomotiveDecoder::Mm2Dil8;
    const auto inUse = loaded.editor.check(settings, loaded.indexOf("MZ"));
    ASSERT_TRUE(inUse.has_value());
    EXPECT_EQ(inUse->kind, Kind::AddressInUse);
    EXPECT_EQ(inUse->other, "BR 85 006 Gl.");
    settings = loaded.settingsOf("MZ");
    settings.name = "MY 1112";
    EXPECT_EQ(loaded.editor.check(settings, loaded.indexOf("MZ"))->kind, Kind::NameInUse);
    settings.name = "  ";
    EXPECT_EQ(loaded.editor.check(settings, loaded.indexOf("MZ"))->kind, Kind::EmptyName);
}

TEST(LocomotiveEditor, FunctionIconsAndTimesAreChecked) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    LocomotiveSettings settings = loaded.settingsOf("MZ");
    const std::size_t mz = loaded.indexOf("MZ");
    settings.functions = {{3, 600, FunctionTrigger::Latching, 0}};
    EXPECT_EQ(loaded.editor.check(settings, mz)->kind, Kind::IconOutOfRange);
    settings.functions = {{3, 5, FunctionTrigger::Timed, 0}};
    EXPECT_EQ(loaded.editor.check(settings, mz)->kind, Kind::DurationOutOfRange);
    settings.functions = {{32, 5, FunctionTrigger::Latching, 0}};
    EXPECT_EQ(loaded.editor.check(settings, mz)->kind, Kind::FunctionNumber);
}

TEST(LocomotiveEditor, ANewLocomotiveIsAppendedAndTheRestStays) {
    Corpus loaded(corpus::lokomotiveSrseii);
    LocomotiveSettings settings;
    settings.name = "BR 50 Kabinentender";
    settings.decoder = LocomotiveDecoder::Dcc;
    settings.address = 50;
    settings.functions = {{0, 1, FunctionTrigger::Latching, 0}, {2, 10, FunctionTrigger::Momentary, 0}};
    std::size_t index = 0;
    ASSERT_EQ(loaded.editor.add(settings, &index), std::nullopt);
    const std::string after = loaded.editor.bytes();
    EXPECT_EQ(after.substr(0, loaded.bytes.size()), loaded.bytes);
    Diagnostics diagnostics;
    const LocomotiveFile reread = LocomotiveFile::read(Document::parse(after, diagnostics), diagnostics);
    ASSERT_EQ(reread.locomotives.size(), loaded.editor.locomotives().size());
    const Locomotive& added = reread.locomotives.back();
    EXPECT_EQ(added.name, "BR 50 Kabinentender");
    EXPECT_EQ(added.uid, 0xC032u);
    EXPECT_EQ(added.decoder, LocomotiveDecoder::Dcc);
    ASSERT_EQ(added.functions.size(), 2u);
    EXPECT_EQ(added.functions[1].trigger(), FunctionTrigger::Momentary);
    EXPECT_EQ(added.functions[1].icon, 10);
}

TEST(LocomotiveEditor, ARemovedLocomotiveIsGoneAndTheOthersStay) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    const std::size_t count = loaded.editor.locomotives().size();
    ASSERT_TRUE(loaded.editor.remove(loaded.indexOf("F7 endevogn")));
    const std::string after = loaded.editor.bytes();
    EXPECT_EQ(after.find("F7 endevogn"), std::string::npos);
    Diagnostics diagnostics;
    EXPECT_EQ(LocomotiveFile::read(Document::parse(after, diagnostics), diagnostics).locomotives.size(),
              count - 1);
    EXPECT_NE(after.find(" .name=BR220 007-9 Ole"), std::string::npos);
}

TEST(LocomotiveEditor, ABoundMfxDecoderBecomesALocomotiveOnTheNextFreeSid) {
    Corpus loaded(corpus::lokomotiveSrseii);
    const std::uint16_t sid = loaded.editor.nextFreeSid();
    const std::size_t index = loaded.editor.addBoundDecoder(0x7A3C1E10, sid);
    const Locomotive& added = loaded.editor.locomotives()[index];
    EXPECT_EQ(added.name, "mfx 7a3c1e10");
    EXPECT_EQ(added.uid, 0x4000u + sid);
    EXPECT_EQ(added.mfxUid, 0x7A3C1E10u);
    EXPECT_GT(sid, 0);
    EXPECT_EQ(loaded.editor.addBoundDecoder(0x7A3C1E10, sid + 1), index)
        << "a known decoder is not added twice";
}

TEST(LocomotiveEditor, SaveWritesConfigLokomotiveCs2AndLeavesNoTemporaryFile) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    LocomotiveSettings settings = loaded.settingsOf("MZ");
    settings.name = "MZ 1401";
    ASSERT_EQ(loaded.editor.apply(loaded.indexOf("MZ"), settings), std::nullopt);
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    const std::filesystem::path root(folder.path().toStdString());
    ASSERT_EQ(loaded.editor.save(root), std::nullopt);
    EXPECT_FALSE(loaded.editor.modified());
    std::ifstream in(root / "config" / "lokomotive.cs2", std::ios::binary);
    std::ostringstream saved;
    saved << in.rdbuf();
    EXPECT_EQ(saved.str(), loaded.editor.bytes());
    EXPECT_FALSE(std::filesystem::exists(root / "config" / "lokomotive.cs2.new"));
}

TEST(LocomotiveEditor, SavingIntoAFileInsteadOfAFolderFailsWithAReason) {
    Corpus loaded(corpus::lokomotiveTrainControl);
    QTemporaryDir folder;
    const std::filesystem::path blocker = std::filesystem::path(folder.path().toStdString()) / "plain";
    std::ofstream(blocker) << "x";
    const auto error = loaded.editor.save(blocker);
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("cannot create"), std::string::npos) << *error;
}

} // namespace
// The editor's widest address is the highest any decoder type allows (issue 12: the form takes it from here).
TEST(LocomotiveEditor, MaxAddressIsTheWidestDecoderRange) {
    std::uint32_t widest = 0;
    for (const LocomotiveDecoder decoder :
         {LocomotiveDecoder::Mm2Prg, LocomotiveDecoder::Mm2Dil8, LocomotiveDecoder::MmPrg,
          LocomotiveDecoder::Mmm2Lok, LocomotiveDecoder::Dcc, LocomotiveDecoder::Mfx, LocomotiveDecoder::Sx1})
        widest = std::max(widest, addressRange(decoder)->maximum);
    EXPECT_EQ(LocomotiveEditor::MaxAddress, widest);
}

} // namespace stellwerk::cs2config::test
