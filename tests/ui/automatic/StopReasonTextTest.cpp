// Why the automation stopped a train, in the window's language: in English every reason reads exactly as the
// core's sentence the command line prints, and in German none is left in English.

#include "automatic/StopReasonText.h"

#include "shell/Translations.h"

#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::ui::test {
namespace {

using automation::StopReason;
using Why = StopReason::Why;

std::vector<StopReason> everyReason() {
    return {
        StopReason::noLongerSeen("BR 218 Ost"),
        StopReason::otherEnteredItsWay("BR 218 Ost", "ICE 3 Velaro", "Gleis 2"),
        StopReason::ranIntoUnreserved("BR 218 Ost", "Block 1"),
        StopReason::unknownOccupantAhead("BR 218 Ost", "Block 3"),
        StopReason::didNotArrive("BR 218 Ost", "Block 1"),
        StopReason::turnoutNotConfirmed("BR 218 Ost", 2, 1, 3),
        StopReason::turnoutSwitchedUnder("BR 218 Ost", 2, 0),
    };
}

TEST(StopReasonText, InEnglishEveryReasonIsTheCoresSentence) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    for (const StopReason& reason : everyReason())
        EXPECT_EQ(StopReasonText::of(reason).toStdString(), automation::describe(reason));
    EXPECT_EQ(StopReasonText::of(StopReason{}), QString());
}

TEST(StopReasonText, InGermanEveryReasonIsGerman) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::German));
    for (const StopReason& reason : everyReason()) {
        const QString text = StopReasonText::of(reason);
        EXPECT_NE(text.toStdString(), automation::describe(reason)) << "left in English";
        EXPECT_TRUE(text.contains(QStringLiteral("BR 218 Ost"))) << text.toStdString();
    }
    EXPECT_EQ(
        StopReasonText::of(everyReason()[5]),
        QStringLiteral("Weiche 2 wurde nach 3 Versuchen nicht in Stellung 1 bestätigt: BR 218 Ost fährt "
                       "nicht ab, der Fahrweg wird freigegeben"));
    ASSERT_TRUE(translations.select(Language::English));
}

} // namespace
} // namespace stellwerk::ui::test
