#include "trackplan/BlockDescription.h"

#include "trackplan/GraphProblemText.h"

#include <utility>

namespace stellwerk::ui {
namespace {

QString quoted(const std::string& text) {
    return QString::fromStdString(text);
}

// Lines with a bullet each, wrapped under their first word (a list's indent would take a fifth of the popup).
QString listItems(const QStringList& lines) {
    QString rows;
    for (const QString& line : lines)
        rows += QStringLiteral("<tr><td width=\"14\" valign=\"top\">\u2022</td><td>%1</td></tr>")
                    .arg(line.toHtmlEscaped());
    return QStringLiteral("<table cellspacing=\"0\" cellpadding=\"1\" style=\"margin-left:6px; "
                          "margin-bottom:4px\">%1</table>")
        .arg(rows);
}

} // namespace

BlockDescription::BlockDescription(const trackgraph::TrackGraph& graph, Names names)
    : m_graph(graph), m_names(std::move(names)) {}

QString BlockDescription::title(int block) const {
    return tr("Block %1 '%2'").arg(block).arg(quoted(m_graph.block(block).name));
}

QString BlockDescription::length(int block) const {
    const trackgraph::Block& b = m_graph.block(block);
    return tr("%n tile(s), %1 mm", "", b.lengthTiles()).arg(b.lengthMm);
}

QStringList BlockDescription::contacts(int block) const {
    QStringList lines;
    for (const trackgraph::ContactOnBlock& contact : m_graph.block(block).contacts) {
        QString line = contact.label.empty()
                           ? tr("Contact %1").arg(contact.contact.number)
                           : tr("Contact %1 '%2'").arg(contact.contact.number).arg(quoted(contact.label));
        if (contact.contact.device != 0)
            line = tr("%1 of feedback device %2").arg(line).arg(contact.contact.device);
        lines << line;
    }
    return lines;
}

QStringList BlockDescription::signalsAlong(int block) const {
    QStringList lines;
    for (const trackgraph::SignalOnTrack& signal : m_graph.block(block).signalsAlong) {
        const QString name = !signal.name.empty() ? tr("Signal '%1'").arg(quoted(signal.name))
                             : signal.article     ? tr("Signal %1").arg(*signal.article)
                                                  : tr("A signal");
        lines << tr("%1, for trains towards end %2")
                     .arg(name, QString::fromLatin1(trackgraph::endName(signal.towards)));
    }
    return lines;
}

QString BlockDescription::endHeading(const trackgraph::BlockEnd& end) const {
    const trackgraph::BlockEndInfo& info = m_graph.block(end.block).end(end.end);
    return tr("From end %1 (%2):").arg(QString::fromLatin1(trackgraph::endName(end.end)), place(info.tile));
}

QStringList BlockDescription::ways(const trackgraph::BlockEnd& end) const {
    QStringList lines;
    for (const int id : m_graph.connectionsFrom(end))
        lines << way(m_graph.connection(id));
    if (lines.isEmpty())
        lines << beyond(end);
    return lines;
}

QString BlockDescription::way(const trackgraph::Connection& connection) const {
    const trackgraph::Block& to = m_graph.block(connection.to.block);
    QStringList parts{tr("to block %1 '%2', end %3")
                          .arg(to.id)
                          .arg(quoted(to.name), QString::fromLatin1(trackgraph::endName(connection.to.end)))};
    if (!connection.turnouts.empty())
        parts << turnouts(connection);
    else if (connection.path.empty())
        parts << tr("directly");
    else
        parts << tr("over %n tile(s) of track without a contact", "", int(connection.path.size()));
    if (!connection.crossings.empty())
        parts << crossings(connection);
    if (!connection.routes.empty())
        parts << routes(connection);
    return parts.join(QStringLiteral(", "));
}

QString BlockDescription::turnouts(const trackgraph::Connection& connection) const {
    QStringList names;
    for (const trackgraph::TurnoutOnWay& turnout : connection.turnouts) {
        const QString position = positionName(turnout.kind, turnout.position);
        if (!turnout.article) {
            names << tr("the turnout at %1 %2").arg(place(turnout.tile), position);
            continue;
        }
        const QString name = m_names.accessory ? m_names.accessory(*turnout.article) : QString();
        names << (name.isEmpty() ? tr("turnout %1 %2").arg(*turnout.article).arg(position)
                                 : tr("turnout %1 '%2' %3").arg(*turnout.article).arg(name, position));
    }
    return tr("over %1").arg(names.join(QStringLiteral(", ")));
}

QString BlockDescription::crossings(const trackgraph::Connection& connection) const {
    QStringList places;
    for (const trackgraph::TileId tile : connection.crossings)
        places << place(tile);
    return tr("across the crossing(s) at %1", "", int(places.size())).arg(places.join(QStringLiteral("; ")));
}

QString BlockDescription::routes(const trackgraph::Connection& connection) const {
    QStringList names;
    for (const std::int64_t route : connection.routes) {
        const QString name = m_names.route ? m_names.route(route) : QString();
        names << (name.isEmpty() ? QString::number(route) : tr("'%1'").arg(name));
    }
    return tr("set by route(s) %1", "", int(names.size())).arg(names.join(QStringLiteral(", ")));
}

// What ends the track at a block end that leads to no other block.
QString BlockDescription::beyond(const trackgraph::BlockEnd& end) const {
    switch (m_graph.block(end.block).end(end.end).beyond) {
    case trackgraph::EndKind::BufferStop:
        return tr("The track ends at a buffer stop.");
    case trackgraph::EndKind::Turntable:
        return tr("The track ends at a turntable.");
    case trackgraph::EndKind::OpenEnd:
        return tr("The track ends without a buffer stop.");
    case trackgraph::EndKind::Junction:
    case trackgraph::EndKind::Block:
        break;
    }
    return tr("No way leads from here to another block.");
}

QString BlockDescription::place(trackgraph::TileId tile) const {
    const trackgraph::Tile& t = m_graph.tile(tile);
    return tr("page %1, column %2, row %3")
        .arg(GraphProblemText::pageName(m_graph, t.page))
        .arg(t.place.column)
        .arg(t.place.row);
}

QString BlockDescription::positionName(trackgraph::TurnoutKind kind, int position) {
    static const std::pair<std::string_view, const char*> words[] = {
        {"straight", QT_TR_NOOP("straight")},
        {"diverging", QT_TR_NOOP("diverging")},
        {"left", QT_TR_NOOP("left")},
        {"right", QT_TR_NOOP("right")},
        {"straight-diverging", QT_TR_NOOP("straight and diverging")},
        {"diverging-straight", QT_TR_NOOP("diverging and straight")},
        {"crossing", QT_TR_NOOP("across")},
    };
    const std::string_view word = trackgraph::positionName(kind, position);
    for (const auto& [english, text] : words)
        if (word == english)
            return tr(text);
    return QString::fromLatin1(word.data(), qsizetype(word.size()));
}

QString BlockDescription::html(int block) const {
    QString text = QStringLiteral("<p style=\"margin:0\"><b>%1</b><br>%2</p>")
                       .arg(title(block).toHtmlEscaped(), length(block).toHtmlEscaped());
    const QStringList contactLines = contacts(block);
    text += QStringLiteral("<p style=\"margin:6px 0 0 0\">%1</p>").arg(tr("Contacts:").toHtmlEscaped()) +
            listItems(contactLines);
    if (const QStringList signalLines = signalsAlong(block); !signalLines.isEmpty())
        text += QStringLiteral("<p style=\"margin:0\">%1</p>").arg(tr("Signals:").toHtmlEscaped()) +
                listItems(signalLines);
    for (const trackgraph::End end : {trackgraph::End::A, trackgraph::End::B}) {
        const trackgraph::BlockEnd at{block, end};
        text += QStringLiteral("<p style=\"margin:0\">%1</p>").arg(endHeading(at).toHtmlEscaped()) +
                listItems(ways(at));
    }
    return text;
}

} // namespace stellwerk::ui
