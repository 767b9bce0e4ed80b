// Every text on the desk follows a switch of the language while it runs, dynamic ones included: after
// View > Language > Deutsch no visible text is still an English text the German translation has words for,
// and back the same.

#include "shell/Workspace.h"
#include "support/TrustTestSupport.h"
#include "throttle/ThrottlePanel.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QRegularExpression>
#include <QSet>
#include <QTabBar>
#include <QXmlStreamReader>
#include <map>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr quint32 SwitchedBr218 = 0x4001; // a locomotive of the demo layout

// The German translation file: each English source with its German translation where they differ, and
// every text of either language (a word may be both: "Register").
struct TranslationFile {
    std::map<QString, QString> germanOf;
    QSet<QString> english;
    QSet<QString> german;
};

TranslationFile germanTranslations() {
    TranslationFile file;
    QFile ts(QStringLiteral(STELLWERK_TRANSLATIONS_DIR "/stellwerk_de.ts"));
    if (!ts.open(QIODevice::ReadOnly))
        return file;
    QXmlStreamReader xml(&ts);
    QString source;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("source")) {
            source = xml.readElementText().remove(QLatin1Char('&'));
            file.english.insert(source);
        } else if (xml.isStartElement() && xml.name() == QLatin1String("translation")) {
            const QString german =
                xml.readElementText(QXmlStreamReader::IncludeChildElements).remove(QLatin1Char('&'));
            file.german.insert(german);
            if (!german.isEmpty() && german != source)
                file.germanOf[source] = german;
        }
    }
    return file;
}

// A source with placeholders ("Speed %1 %") as a pattern for the texts made from it; none when it has too
// few words of its own to tell it from any other text.
std::optional<QRegularExpression> patternOf(const QString& source) {
    QString literal = source;
    literal.remove(QRegularExpression(QStringLiteral("%[0-9Ln]+")));
    if (!source.contains(QLatin1Char('%')) ||
        literal.count(QRegularExpression(QStringLiteral("[A-Za-z]"))) < 8)
        return std::nullopt;
    QString pattern = QRegularExpression::escape(source);
    pattern.replace(QRegularExpression(QStringLiteral("%[0-9Ln]+")), QStringLiteral(".*"));
    return QRegularExpression(QStringLiteral("^") + pattern + QStringLiteral("$"),
                              QRegularExpression::DotMatchesEverythingOption);
}

bool isOnScreen(const QWidget* widget) {
    return widget->isVisible() && !widget->visibleRegion().isEmpty();
}

// The texts a person sees in the widget (and its tooltip): its own, or a view's headers and first rows.
QStringList textsOf(const QWidget* widget) {
    QStringList texts{widget->toolTip(), widget->accessibleName()};
    if (const auto* label = qobject_cast<const QLabel*>(widget))
        texts << label->text();
    else if (const auto* button = qobject_cast<const QAbstractButton*>(widget))
        texts << button->text().remove(QLatin1Char('&'));
    else if (const auto* box = qobject_cast<const QGroupBox*>(widget))
        texts << box->title();
    else if (const auto* tabs = qobject_cast<const QTabBar*>(widget))
        for (int i = 0; i < tabs->count(); ++i)
            texts << tabs->tabText(i).remove(QLatin1Char('&'));
    else if (const auto* view = qobject_cast<const QAbstractItemView*>(widget); view && view->model()) {
        const QAbstractItemModel* model = view->model();
        for (int column = 0; column < model->columnCount(); ++column) {
            texts << model->headerData(column, Qt::Horizontal).toString();
            for (int row = 0; row < std::min(model->rowCount(), 12); ++row)
                texts << model->data(model->index(row, column)).toString();
        }
    }
    return texts;
}

class LanguageSwitchTest : public test::DeskOnTestStation {
protected:
    QStringList textsLeftBehind(const std::map<QString, QString>& left, const QSet<QString>& now);

    // Every text on every panel, each panel brought to the front in turn, with where it stands.
    std::vector<std::pair<QString, QString>> deskTexts() {
        std::vector<std::pair<QString, QString>> texts;
        for (QDockWidget* dock : window->workspace()->docks()) {
            QWidget* panel = Workspace::panelOf(dock);
            window->workspace()->showPanel(panel);
            QTest::qWait(40);
            texts.emplace_back(dock->windowTitle(),
                               QStringLiteral("the title of %1").arg(panel->objectName()));
            for (const QWidget* widget : panel->findChildren<QWidget*>())
                if (isOnScreen(widget))
                    for (const QString& text : textsOf(widget))
                        texts.emplace_back(text.trimmed(),
                                           QStringLiteral("%1 %2 in %3")
                                               .arg(QString::fromLatin1(widget->metaObject()->className()),
                                                    widget->objectName(), panel->objectName()));
        }
        for (const QWidget* widget : window->findChildren<QWidget*>()) // the tool bars and the status bar
            if (isOnScreen(widget) && !insideDock(widget))
                for (const QString& text : textsOf(widget))
                    texts.emplace_back(text.trimmed(),
                                       QStringLiteral("%1 %2 in the window")
                                           .arg(QString::fromLatin1(widget->metaObject()->className()),
                                                widget->objectName()));
        return texts;
    }

    static bool insideDock(const QWidget* widget) {
        for (const QWidget* w = widget; w; w = w->parentWidget())
            if (qobject_cast<const QDockWidget*>(w))
                return true;
        return false;
    }
};

// The same desk, started in German.
class LanguageSwitchFromGermanTest : public LanguageSwitchTest {
protected:
    Language deskLanguage() const override { return Language::German; }
};

} // namespace

// The desk's texts still in the language left behind: `left` maps each text of that language to the
// one of the language now chosen, where they differ.
QStringList LanguageSwitchTest::textsLeftBehind(const std::map<QString, QString>& left,
                                                const QSet<QString>& now) {
    std::vector<std::pair<QRegularExpression, QRegularExpression>> patterns; // left behind, now
    for (const auto& [old, now] : left)
        if (const auto oldPattern = patternOf(old))
            if (const auto nowPattern = patternOf(now))
                patterns.emplace_back(*oldPattern, *nowPattern);
    QStringList found;
    for (const auto& [text, where] : deskTexts()) {
        if (text.isEmpty() || now.contains(text))
            continue; // a text of the language chosen (which may be a word of both)
        if (left.contains(text)) {
            found << QStringLiteral("\"%1\" (%2)").arg(text, where);
            continue;
        }
        for (const auto& [oldPattern, nowPattern] : patterns)
            if (oldPattern.match(text).hasMatch() && !nowPattern.match(text).hasMatch()) {
                found << QStringLiteral("\"%1\" (%2, from \"%3\")").arg(text, where, oldPattern.pattern());
                break;
            }
    }
    found.removeDuplicates();
    return found;
}

TEST_F(LanguageSwitchTest, EveryTextOnTheDeskFollowsASwitchToGerman) {
    const TranslationFile file = germanTranslations();
    ASSERT_GT(file.germanOf.size(), 300u) << "the German translation file is read";
    ASSERT_NE(window->throttlePanel()->addThrottle(SwitchedBr218), nullptr);
    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QTest::qWait(100);
    const QStringList english = textsLeftBehind(file.germanOf, file.german);
    EXPECT_TRUE(english.isEmpty()) << "still English after the switch:\n"
                                   << english.join(QLatin1Char('\n')).toStdString();
}

TEST_F(LanguageSwitchFromGermanTest, EveryTextOnTheDeskFollowsASwitchToEnglish) {
    const TranslationFile file = germanTranslations();
    std::map<QString, QString> fromGerman;
    for (const auto& [english, german] : file.germanOf)
        fromGerman[german] = english;
    ASSERT_NE(window->throttlePanel()->addThrottle(SwitchedBr218), nullptr);
    ASSERT_TRUE(translations.select(Language::English));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QTest::qWait(100);
    const QStringList german = textsLeftBehind(fromGerman, file.english);
    EXPECT_TRUE(german.isEmpty()) << "still German after the switch:\n"
                                  << german.join(QLatin1Char('\n')).toStdString();
}
