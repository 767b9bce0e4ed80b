// The accessory types of magnetartikel.cs2 (AccessoryType): every type the document and the corpus name,
// with its addresses and positions.

#include "cs2config/AccessoryType.h"

#include "AccessoryFileTestSupport.h"
#include "ConfigTestSupport.h"
#include "cs2config/AccessoryFile.h"

#include <string>

namespace stellwerk::cs2config::test {
namespace {

using namespace accessoryfile;

TEST(AccessoryType, EveryDocumentedTypeIsKnown) {
    const std::vector<std::string_view> documented = {
        "std_rot_gruen",
        "std_rot",
        "std_gruen",
        "entkupplungsgleis",
        "entkupplungsgleis_1",
        "rechtsweiche",
        "linksweiche",
        "y_weiche",
        "k84_ausgang",
        "k84_doppelausgang",
        "dreiwegweiche",
        "DKW 2 Antriebe",
        "DKW 1 Antrieb",
        "lichtsignal_HP01",
        "lichtsignal_HP02",
        "lichtsignal_HP012",
        "lichtsignal_HP012_SH01",
        "lichtsignal_SH01",
        "formsignal_HP01",
        "formsignal_HP02",
        "formsignal_HP012",
        "formsignal_HP012_SH01",
        "formsignal_SH01",
        "urc_lichtsignal_HP01",
        "urc_lichtsignal_HP012",
        "urc_lichtsignal_HP012_SH01",
        "urc_lichtsignal_SH01",
        "schiebebuehne",
        "drehscheibe_alt",
        "digitaldrehscheibe",
    };
    ASSERT_EQ(accessoryTypes().size(), documented.size());
    for (std::size_t i = 0; i < documented.size(); ++i)
        EXPECT_EQ(accessoryTypes()[i].key, documented[i]);
    EXPECT_EQ(findAccessoryType("drehscheibe_mfx"), nullptr);
}

TEST(AccessoryType, AddressesAndPositionsOfEachKind) {
    struct Expected {
        std::string_view key;
        int addresses;
        int positions;
    };
    for (const Expected& expected : std::vector<Expected>{{"rechtsweiche", 1, 2},
                                                          {"std_rot_gruen", 1, 2},
                                                          {"lichtsignal_HP01", 1, 2},
                                                          {"std_rot", 1, 1},
                                                          {"entkupplungsgleis", 1, 1},
                                                          {"k84_ausgang", 1, 2},
                                                          {"dreiwegweiche", 2, 3},
                                                          {"formsignal_HP012", 2, 3},
                                                          {"lichtsignal_HP012_SH01", 2, 4},
                                                          {"urc_lichtsignal_HP012_SH01", 2, 4},
                                                          {"DKW 2 Antriebe", 2, 4},
                                                          {"schiebebuehne", 2, 4},
                                                          {"drehscheibe_alt", 2, 4},
                                                          {"digitaldrehscheibe", 16, 32}}) {
        const AccessoryTypeInfo* type = findAccessoryType(expected.key);
        ASSERT_NE(type, nullptr) << expected.key;
        EXPECT_EQ(type->addresses, expected.addresses) << expected.key;
        EXPECT_EQ(type->positions, expected.positions) << expected.key;
    }
    const AccessoryTypeInfo& hp012 = *findAccessoryType("formsignal_HP012");
    EXPECT_TRUE(hp012.acceptsPosition(3));
    EXPECT_FALSE(hp012.acceptsPosition(2));
    EXPECT_TRUE(findAccessoryType("entkupplungsgleis")->singleOutput);
    EXPECT_FALSE(findAccessoryType("rechtsweiche")->singleOutput);
    EXPECT_FALSE(findAccessoryType("rechtsweiche")->acceptsPosition(32));
}

TEST(AccessoryType, EveryCorpusTypeIsKnown) {
    for (std::string_view path : {corpus::magnetartikelTrainControl, corpus::magnetartikelGbert})
        for (const Accessory& accessory : readCorpusFile(path).file.accessories)
            EXPECT_NE(accessory.typeInfo(), nullptr) << path << ": " << accessory.type;
}

} // namespace
} // namespace stellwerk::cs2config::test
