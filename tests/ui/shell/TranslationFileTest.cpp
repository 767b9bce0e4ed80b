// The .ts files in translations/ are complete: every text of the user interface has a German translation,
// and the English file lists the same texts (both are refreshed together by lupdate).

#include <QFile>
#include <QSet>
#include <QXmlStreamReader>
#include <gtest/gtest.h>

namespace {

struct Message {
    QString context;
    QString source;
    QString translation;
    bool finished = true;
};

QString tsPath(const char* language) {
    return QStringLiteral(STELLWERK_TRANSLATIONS_DIR "/stellwerk_%1.ts").arg(QLatin1String(language));
}

// Reads the messages of a .ts file; entries lupdate marked vanished or obsolete are left out.
QList<Message> readMessages(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        ADD_FAILURE() << "cannot open " << path.toStdString();
        return {};
    }
    QList<Message> messages;
    QString context;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) {
            continue;
        }
        const auto name = xml.name();
        if (name == u"name") {
            context = xml.readElementText();
        } else if (name == u"message") {
            messages.append(Message{context, {}, {}, true});
        } else if (name == u"source" && !messages.isEmpty()) {
            messages.last().source = xml.readElementText();
        } else if (name == u"translation" && !messages.isEmpty()) {
            const QString type = xml.attributes().value(QStringLiteral("type")).toString();
            messages.last().finished = type != u"unfinished";
            // Plural texts keep their forms in <numerusform> children; they count as one translation.
            messages.last().translation = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (type == u"vanished" || type == u"obsolete") {
                messages.removeLast();
            }
        }
    }
    EXPECT_FALSE(xml.hasError()) << path.toStdString() << ": " << xml.errorString().toStdString();
    return messages;
}

QSet<QString> keys(const QList<Message>& messages) {
    QSet<QString> result;
    for (const Message& message : messages) {
        result.insert(message.context + QStringLiteral(" | ") + message.source);
    }
    return result;
}

} // namespace

TEST(TranslationFiles, GermanHasAFinishedTranslationForEveryText) {
    const QList<Message> messages = readMessages(tsPath("de"));
    ASSERT_FALSE(messages.isEmpty());
    for (const Message& message : messages) {
        EXPECT_TRUE(message.finished && !message.translation.isEmpty())
            << "stellwerk_de.ts, context " << message.context.toStdString() << ": \""
            << message.source.toStdString() << "\" is not translated yet";
    }
}

TEST(TranslationFiles, EnglishListsTheSameTextsAsGerman) {
    EXPECT_EQ(keys(readMessages(tsPath("en"))), keys(readMessages(tsPath("de"))));
}
