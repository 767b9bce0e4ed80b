#pragma once

#include <QString>

class QFontMetrics;

namespace stellwerk::ui {

// Shortens a name to a width so that what tells it from its siblings survives: names on a plan differ
// at their end ("Block 1" … "Block 4", "Einfahrt 1" and "Einfahrt 2"), so the last word stays with the
// character before it and the start gives way: "Bl…k 1", "E…t 1" instead of "Blo…", "Ein…" for all. Where
// not even the last word fits, a number keeps its end ("…1") and a word both ends of the name ("E…t").
class NameElision final {
public:
    static QString shorten(const QString& name, const QFontMetrics& metrics, int width);

private:
    // How many characters at the end are kept: the last word, its space and the character before it;
    // the trailing digits of a name without spaces; none where nothing at the end tells names apart.
    static qsizetype tailLength(const QString& name);
};

} // namespace stellwerk::ui
