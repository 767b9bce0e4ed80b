#include "trackplan/GraphProblemText.h"

#include "trackgraph/TrackGraph.h"
#include "trackplan/TrackTileInfo.h"

#include <QStringList>

namespace stellwerk::ui {

using trackgraph::ProblemKind;

QString GraphProblemText::of(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem) {
    const trackgraph::Tile& tile = graph.tile(problem.tile);
    return tr("Page %1, column %2, row %3: %4")
        .arg(pageName(graph, tile.page))
        .arg(tile.place.column)
        .arg(tile.place.row)
        .arg(sentence(graph, problem));
}

QString GraphProblemText::sentence(const trackgraph::TrackGraph& graph, const trackgraph::Problem& problem) {
    const trackgraph::Tile& tile = graph.tile(problem.tile);
    switch (problem.kind) {
    case ProblemKind::OpenEnd:
        return tr("The track ends here without a buffer stop, or does not meet the track of the tile beside "
                  "it; add the missing track or a buffer stop, or turn a tile.");
    case ProblemKind::JoinsNothing:
        return tr("This tile (%1) joins no other track; move it onto the track or remove it.")
            .arg(typeName(tile));
    case ProblemKind::TurnoutLegNowhere:
        return tr("%1 has a side without track, so the way through it there leads nowhere; add the track or "
                  "a buffer stop.")
            .arg(turnoutName(tile));
    case ProblemKind::NoContact:
        return tr("The track from here to the next turnout or end has no contact, so a train there cannot be "
                  "seen; add a contact where trains may stop.");
    case ProblemKind::PageLinkNoPage:
    case ProblemKind::PageLinkFileMissing:
    case ProblemKind::PageLinkUnpaired:
        return pageLinkSentence(graph, problem);
    case ProblemKind::ContactInTwoBlocks:
    case ProblemKind::DrawingsDisagree:
        return drawingSentence(graph, problem);
    case ProblemKind::RouteNoConnection:
    case ProblemKind::TurnoutClash:
    case ProblemKind::TooManyWays:
        break;
    }
    return waySentence(graph, problem);
}

QString GraphProblemText::pageLinkSentence(const trackgraph::TrackGraph& graph,
                                           const trackgraph::Problem& problem) {
    const QString page = linkedPage(graph, graph.tile(problem.tile));
    if (problem.kind == ProblemKind::PageLinkNoPage)
        return tr("The arrow names page %1, which the track plan does not have; the track ends here.")
            .arg(page);
    if (problem.kind == ProblemKind::PageLinkFileMissing)
        return tr("The arrow leads to page %1, whose file is missing; the track ends here.").arg(page);
    return tr("The arrow to page %1 has no arrow back on that page, so the track ends here; add one where "
              "the "
              "track goes on.")
        .arg(page);
}

QString GraphProblemText::drawingSentence(const trackgraph::TrackGraph& graph,
                                          const trackgraph::Problem& problem) {
    const trackgraph::Tile& tile = graph.tile(problem.tile);
    if (problem.kind == ProblemKind::ContactInTwoBlocks) {
        const std::optional<int> block = tile.contact ? graph.blockWithContact(*tile.contact) : std::nullopt;
        return tr("%1 is drawn twice on this page, on two stretches of track; one contact can watch only one "
                  "block, so both are taken as block '%2'.")
            .arg(contactName(tile), block ? QString::fromStdString(graph.block(*block).name) : QString());
    }
    const QString what = tile.contact ? contactName(tile) : turnoutName(tile);
    return tr("%1 is drawn on another page as well, and the drawings join different track; make the pages "
              "agree.")
        .arg(what);
}

QString GraphProblemText::waySentence(const trackgraph::TrackGraph& graph,
                                      const trackgraph::Problem& problem) {
    const trackgraph::Tile& tile = graph.tile(problem.tile);
    if (problem.kind == ProblemKind::RouteNoConnection) {
        if (tile.role() == trackgraph::TileRole::Turnout)
            return tr("A route sets %1 so that it leads from no block to another as the plan draws it; check "
                      "the route's turnouts against the plan.")
                .arg(turnoutName(tile));
        const QString route =
            tile.text.empty() ? QString::number(tile.article) : QString::fromStdString(tile.text);
        return tr("Route %1 sets turnouts that together lead from no block to another as the plan draws "
                  "them; check the route's turnouts against the plan.")
            .arg(route);
    }
    if (problem.kind == ProblemKind::TurnoutClash)
        return tr("A way over this tile needs %1 in two positions at once (it is drawn more than once, or "
                  "passed twice), so that way is left out; give the drawings their own articles if they are "
                  "separate turnouts.")
            .arg(turnoutName(tile));
    return tr("From this tile the track branches into more ways than are followed; add contacts between the "
              "turnouts so that it splits into blocks.");
}

QString GraphProblemText::list(const trackgraph::TrackGraph& graph) {
    const std::vector<trackgraph::Problem>& problems = graph.problems();
    if (problems.empty())
        return {};
    QStringList lines{tr("The drawing of the track plan has %n problem(s):", "", int(problems.size()))};
    for (const trackgraph::Problem& problem : problems)
        lines << of(graph, problem);
    return lines.join(QLatin1Char('\n'));
}

QString GraphProblemText::pageName(const trackgraph::TrackGraph& graph, std::uint32_t page) {
    const trackgraph::GraphPage& p = graph.pages()[page];
    return p.name.empty() ? QString::number(p.id) : tr("'%1'").arg(QString::fromStdString(p.name));
}

QString GraphProblemText::typeName(const trackgraph::Tile& tile) {
    const cs2config::TrackElementType* type = cs2config::findTrackElementType(tile.type);
    return TrackTileInfo::typeName(QString::fromStdString(tile.type),
                                   type ? type->category : cs2config::TrackCategory::Unknown);
}

QString GraphProblemText::turnoutName(const trackgraph::Tile& tile) {
    if (!tile.accessory)
        return tr("The turnout");
    return tile.text.empty()
               ? tr("Turnout %1").arg(*tile.accessory)
               : tr("Turnout %1 '%2'").arg(*tile.accessory).arg(QString::fromStdString(tile.text));
}

QString GraphProblemText::contactName(const trackgraph::Tile& tile) {
    const qint64 number = tile.contact ? tile.contact->number : tile.article;
    return tile.text.empty() ? tr("Contact %1").arg(number)
                             : tr("Contact %1 '%2'").arg(number).arg(QString::fromStdString(tile.text));
}

// The page an arrow names: by number, else by its text.
QString GraphProblemText::linkedPage(const trackgraph::TrackGraph& graph, const trackgraph::Tile& arrow) {
    if (arrow.article >= 0)
        if (const std::optional<std::uint32_t> page = graph.tiles().pageWithId(arrow.article))
            return pageName(graph, *page);
    if (!arrow.text.empty())
        if (const std::optional<std::uint32_t> page = graph.tiles().pageNamed(arrow.text))
            return pageName(graph, *page);
    return arrow.article >= 0 ? QString::number(arrow.article)
                              : tr("'%1'").arg(QString::fromStdString(arrow.text));
}

} // namespace stellwerk::ui
