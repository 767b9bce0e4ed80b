// `stellwerk --help` and `--version` work without a display, and the help lists every option of the
// program that the README mentions.

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <gtest/gtest.h>

namespace {

// Runs the built program with neither a display nor a Qt platform chosen, as on a server over ssh.
QString runWithoutDisplay(const QStringList& arguments, int* exitCode) {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        environment.remove(QString::fromLatin1(name));
    QProcess program;
    program.setProcessEnvironment(environment);
    program.start(QStringLiteral(STELLWERK_GUI_BINARY), arguments);
    if (!program.waitForFinished(20000))
        return QStringLiteral("(did not finish)");
    *exitCode = program.exitStatus() == QProcess::NormalExit ? program.exitCode() : -1;
    return QString::fromLocal8Bit(program.readAllStandardOutput() + program.readAllStandardError());
}

// The options the README gives to `stellwerk` itself (not stellwerk-cli or stellwerk-sim).
QSet<QString> readmeOptions() {
    QFile readme(QStringLiteral(STELLWERK_README));
    if (!readme.open(QIODevice::ReadOnly))
        return {};
    QSet<QString> options;
    static const QRegularExpression call(
        QStringLiteral("(?:^|[\\s`/])stellwerk((?: --?[a-z][a-z0-9-]*(?: [^\\s`-][^\\s`]*)?)+)"));
    static const QRegularExpression option(QStringLiteral("--[a-z][a-z0-9-]*"));
    for (auto calls = call.globalMatch(QString::fromUtf8(readme.readAll())); calls.hasNext();)
        for (auto found = option.globalMatch(calls.next().captured(1)); found.hasNext();)
            options.insert(found.next().captured());
    return options;
}

} // namespace

TEST(CommandLine, HelpWorksWithoutADisplayAndListsEveryOptionTheReadmeMentions) {
    int exitCode = -2;
    const QString help = runWithoutDisplay({QStringLiteral("--help")}, &exitCode);
    EXPECT_EQ(exitCode, 0) << help.toStdString();
    QSet<QString> options = readmeOptions();
    EXPECT_TRUE(options.contains(QStringLiteral("--station"))) << "the README scan found the calls";
    options += {QStringLiteral("--screenshot"), QStringLiteral("--panel"),     QStringLiteral("--size"),
                QStringLiteral("--decode"),     QStringLiteral("--simulated"), QStringLiteral("--version")};
    for (const QString& name : options)
        EXPECT_TRUE(help.contains(name + QLatin1Char(' ')) || help.contains(name + QLatin1Char('\n')) ||
                    help.contains(name + QLatin1Char('=')) || help.contains(name + QLatin1Char('<')))
            << name.toStdString() << " is missing from:\n"
            << help.toStdString();
}

TEST(CommandLine, VersionWorksWithoutADisplay) {
    int exitCode = -2;
    const QString version = runWithoutDisplay({QStringLiteral("--version")}, &exitCode);
    EXPECT_EQ(exitCode, 0);
    EXPECT_TRUE(version.startsWith(QStringLiteral("Stellwerk "))) << version.toStdString();
}
