#include "shell/Language.h"

#include "shell/LanguageSettings.h"

#include <QSettings>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

const QString languageKey = QStringLiteral("ui/language");

// Starts every test with no stored choice, as on a first run.
class LanguageSettingsTest : public ::testing::Test {
protected:
    void SetUp() override { QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear(); }
    void TearDown() override { SetUp(); }

    static QString storedCode() {
        return QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"))
            .value(languageKey)
            .toString();
    }
    static void storeCode(const QString& code) {
        QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).setValue(languageKey, code);
    }
};

} // namespace

TEST(Language, CodesRoundTrip) {
    EXPECT_EQ(languageCode(Language::English), QStringLiteral("en"));
    EXPECT_EQ(languageCode(Language::German), QStringLiteral("de"));
    EXPECT_EQ(languageFromCode(u"en"), Language::English);
    EXPECT_EQ(languageFromCode(u"de"), Language::German);
    EXPECT_EQ(languageFromCode(u"fr"), std::nullopt);
    EXPECT_EQ(languageFromCode(u""), std::nullopt);
}

TEST(Language, DefaultIsGermanOnGermanSystems) {
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::German, QLocale::Germany)), Language::German);
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::German, QLocale::Switzerland)), Language::German);
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::German, QLocale::Austria)), Language::German);
}

TEST(Language, DefaultIsEnglishElsewhere) {
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::English, QLocale::UnitedKingdom)), Language::English);
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::French, QLocale::France)), Language::English);
    EXPECT_EQ(defaultLanguage(QLocale(QLocale::Dutch, QLocale::Netherlands)), Language::English);
}

TEST_F(LanguageSettingsTest, FirstRunFollowsTheSystemLocale) {
    EXPECT_EQ(LanguageSettings::load(), defaultLanguage(QLocale::system()));
}

TEST_F(LanguageSettingsTest, SavedChoiceIsLoadedAgain) {
    LanguageSettings::save(Language::German);
    EXPECT_EQ(LanguageSettings::load(), Language::German);
    LanguageSettings::save(Language::English);
    EXPECT_EQ(LanguageSettings::load(), Language::English);
}

TEST_F(LanguageSettingsTest, IsStoredAsCodeUnderStellwerkStellwerk) {
    LanguageSettings::save(Language::German);
    EXPECT_EQ(storedCode(), QStringLiteral("de"));
}

TEST_F(LanguageSettingsTest, UnknownStoredCodeFallsBackToTheSystemLocale) {
    storeCode(QStringLiteral("tlh"));
    EXPECT_EQ(LanguageSettings::load(), defaultLanguage(QLocale::system()));
}
