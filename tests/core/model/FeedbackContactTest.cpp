// Document 5.2: S88 events from the bus show up on the contact and on its tile.

#include "ModelBench.h"

namespace stellwerk::model::test {
namespace {

TEST(FeedbackContacts, AnS88EventShowsOnTheContactAndItsTile) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy contacts(&bench.railway, &Railway::contactsChanged);
    QSignalSpy tiles(&bench.railway, &Railway::tilesChanged);
    const QDateTime before = QDateTime::currentDateTime();
    bench.station.setContact(0, 7, true);
    ASSERT_TRUE(waitFor([&] { return contacts.count() == 1; }));
    EXPECT_EQ(contacts.first().at(0).value<QList<quint32>>(), QList<quint32>{contactKey(0, 7)});
    const FeedbackContact* contact = bench.railway.contact(contactKey(0, 7));
    EXPECT_TRUE(contact->occupied());
    EXPECT_GE(contact->lastChange(), before);
    ASSERT_EQ(tiles.count(), 1);
    EXPECT_EQ(tiles.first().at(0).value<QList<TileRef>>(), (QList<TileRef>{{0, 0}}));

    bench.station.setContact(0, 7, false);
    ASSERT_TRUE(waitFor([&] { return !bench.railway.contact(contactKey(0, 7))->occupied(); }));
}

// Contacts that no page shows (a Link S88 bus, contact 1005) are kept as the bus reports them.
TEST(FeedbackContacts, AContactNoPageShowsIsAddedWhenTheBusReportsIt) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    bench.station.setContact(0x53, 1005, true);
    ASSERT_TRUE(waitFor([&] { return bench.railway.contact(contactKey(0x53, 1005)) != nullptr; }));
    EXPECT_TRUE(bench.railway.contact(contactKey(0x53, 1005))->occupied());
    EXPECT_EQ(bench.railway.contact(contactKey(0x53, 1005))->device(), 0x53);
}

} // namespace
} // namespace stellwerk::model::test
