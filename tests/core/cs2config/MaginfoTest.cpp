// The MS2's maginfo stream (document 8.6): the same "artikel" records cut down, read as accessories and
// written the way the document's example shows.

#include "AccessoryFileTestSupport.h"
#include "ConfigTestSupport.h"
#include "cs2config/AccessoryFile.h"

namespace stellwerk::cs2config::test {
namespace {

using namespace accessoryfile;

TEST(AccessoryFile, MaginfoExampleIsReadAsAccessories) {
    Read read = readText(documentMaginfo);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    EXPECT_EQ(read.file.versionMinor, std::nullopt);
    ASSERT_EQ(read.file.accessories.size(), 2u);
    EXPECT_EQ(read.file.accessories[0].id, 3);
    EXPECT_EQ(read.file.accessories[0].name, "1.3");
    EXPECT_EQ(read.file.accessories[0].type, "rechtsweiche");
    EXPECT_EQ(read.file.accessories[1].type, "entkupplungsgleis");
    EXPECT_EQ(read.file.accessories[1].switchTimeMs, 200);
    EXPECT_EQ(read.file.accessories[1].protocol, "mm2");
    EXPECT_EQ(read.file.document.style().indent, "  ");
    EXPECT_EQ(read.file.write().serialize(), documentMaginfo);
}

// MS2 text streams pad their lines with spaces; the words the format defines are read without them.
TEST(AccessoryFile, MaginfoWithPaddedLinesIsRead) {
    const std::string padded = "[magnetartikel]\nartikel\n  .id=3  \n  .name=1.3 \n  .typ=rechtsweiche    \n"
                               "  .schaltzeit=200 \n  .dectyp=mm2     \n";
    Read read = readText(padded);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const Accessory& turnout = read.file.accessories.at(0);
    EXPECT_EQ(turnout.id, 3);
    EXPECT_EQ(turnout.name, "1.3 ");
    EXPECT_EQ(turnout.type, "rechtsweiche");
    EXPECT_EQ(turnout.switchTimeMs, 200);
    EXPECT_EQ(turnout.protocol, "mm2");
    EXPECT_EQ(read.file.write().serialize(), padded);
}

TEST(AccessoryFile, MaginfoIsWrittenLikeTheDocumentsExample) {
    Read read = readText(documentMaginfo);
    EXPECT_EQ(writeAccessoryInfo(read.file.accessories).serialize(), documentMaginfo);
}

TEST(AccessoryFile, MaginfoLeavesOutWhatTheMs2DoesNotGet) {
    const AccessoryFile file = readCorpusFile(corpus::magnetartikelGbert).file;
    const std::vector<Accessory> firstTwo(file.accessories.begin(), file.accessories.begin() + 2);
    EXPECT_EQ(writeAccessoryInfo(firstTwo).serialize(),
              "[magnetartikel]\nartikel\n  .id=1\n  .name=23\n  .typ=rechtsweiche\n  .schaltzeit=200\n  "
              ".dectyp=mm2\n"
              "artikel\n  .id=2\n  .name=13\n  .typ=linksweiche\n  .schaltzeit=200\n  .dectyp=mm2\n");
}

} // namespace
} // namespace stellwerk::cs2config::test
