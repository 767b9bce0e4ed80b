// Document 5.2: S88 events from the bus show up on the contact and on its tile; which locomotive is on it
// comes from the simulator or the user.

#include "ModelBench.h"
#include "model/OccupantBook.h"

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

// Which locomotive is on a contact comes from outside the station (the simulator or the user): it is kept
// while the contact is occupied and forgotten once the bus reports it free.
TEST(FeedbackContacts, AnOccupantIsKeptWhileTheContactIsOccupiedAndForgottenWhenItIsFree) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    QSignalSpy contacts(&bench.railway, &Railway::contactsChanged);
    QSignalSpy tiles(&bench.railway, &Railway::tilesChanged);
    bench.railway.reportOccupant(contactKey(0, 7), Br86);
    ASSERT_EQ(contacts.count(), 1) << "told at once: the simulator's report needs no bus";
    EXPECT_EQ(contacts.first().at(0).value<QList<quint32>>(), QList<quint32>{contactKey(0, 7)});
    EXPECT_EQ(tiles.first().at(0).value<QList<TileRef>>(), (QList<TileRef>{{0, 0}}))
        << "its tile is drawn anew";
    EXPECT_EQ(bench.railway.contact(contactKey(0, 7))->occupant(), Br86);
    bench.railway.reportOccupant(contactKey(0, 7), Br86);
    EXPECT_EQ(contacts.count(), 1) << "the same occupant again changes nothing";

    bench.station.setContact(0, 7, true);
    ASSERT_TRUE(waitFor([&] { return bench.railway.contact(contactKey(0, 7))->occupied(); }));
    EXPECT_EQ(bench.railway.contact(contactKey(0, 7))->occupant(), Br86)
        << "the train arrived: it stays named";
    bench.station.setContact(0, 7, false);
    ASSERT_TRUE(waitFor([&] { return !bench.railway.contact(contactKey(0, 7))->occupied(); }));
    EXPECT_EQ(bench.railway.contact(contactKey(0, 7))->occupant(), 0u) << "the train left";
}

TEST(FeedbackContacts, AnOccupantOfAContactNotReportedYetIsKept) {
    ModelBench bench;
    ASSERT_TRUE(bench.start());
    bench.railway.reportOccupant(contactKey(0x53, 1005), V100);
    ASSERT_NE(bench.railway.contact(contactKey(0x53, 1005)), nullptr);
    EXPECT_EQ(bench.railway.contact(contactKey(0x53, 1005))->occupant(), V100);
    EXPECT_FALSE(bench.railway.contact(contactKey(0x53, 1005))->known()) << "the bus has not said a word yet";
    bench.station.setContact(0x53, 1005, true);
    ASSERT_TRUE(waitFor([&] { return bench.railway.contact(contactKey(0x53, 1005))->occupied(); }));
    EXPECT_EQ(bench.railway.contact(contactKey(0x53, 1005))->occupant(), V100);
}

// The book outlives sessions: a railway made after a reconnection learns every occupant known so far, and
// one that is gone is not told.
TEST(OccupantBook, HandsItsOccupantsToEachNewRailway) {
    OccupantBook book;
    book.report(contactKey(0, 1), Br86);
    book.report(contactKey(0, 2), V100);
    book.report(contactKey(0, 2), 0); // V 100 left
    EXPECT_EQ(book.occupantOf(contactKey(0, 1)), Br86);
    EXPECT_EQ(book.occupantOf(contactKey(0, 2)), 0u);
    {
        ModelBench bench;
        ASSERT_TRUE(bench.start());
        book.setRailway(&bench.railway);
        EXPECT_EQ(bench.railway.contact(contactKey(0, 1))->occupant(), Br86);
        EXPECT_TRUE(!bench.railway.contact(contactKey(0, 2)) ||
                    bench.railway.contact(contactKey(0, 2))->occupant() == 0);
        book.report(contactKey(0, 3), V100);
        EXPECT_EQ(bench.railway.contact(contactKey(0, 3))->occupant(), V100) << "told while it is shown";
        book.clear();
        EXPECT_EQ(bench.railway.contact(contactKey(0, 1))->occupant(), 0u)
            << "a new simulation: nobody known";
        book.report(contactKey(0, 1), Br86);
    }
    book.report(contactKey(0, 4), V100); // the railway is gone: nothing to tell, nothing to crash on
    ModelBench next;
    ASSERT_TRUE(next.start());
    book.setRailway(&next.railway);
    EXPECT_EQ(next.railway.contact(contactKey(0, 1))->occupant(), Br86);
    EXPECT_EQ(next.railway.contact(contactKey(0, 4))->occupant(), V100);
}

} // namespace
} // namespace stellwerk::model::test
