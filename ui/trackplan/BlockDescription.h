#pragma once

#include "trackgraph/TrackGraph.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>

namespace stellwerk::ui {

// Says in words what the track graph knows of one block, for the block popup: its name and length, its
// contacts and signals, and from each end every way to the next block, with the turnouts and the positions
// they must have and the crossings passed.
class BlockDescription final {
    Q_DECLARE_TR_FUNCTIONS(BlockDescription)

public:
    // The name of an accessory (keyboard number) or a route (id) in the files; empty when it has none.
    using NameOf = std::function<QString(std::int64_t)>;
    struct Names {
        NameOf accessory;
        NameOf route;
    };

    BlockDescription(const trackgraph::TrackGraph& graph, Names names);

    // "Block 4 'Gleis 1'".
    QString title(int block) const;
    // "7 tiles, 1260 mm".
    QString length(int block) const;
    // "Contact 1 'Gleis 1'", in order from end a.
    QStringList contacts(int block) const;
    // "Signal 'P1', for trains towards end b", in order from end a.
    QStringList signalsAlong(int block) const;
    // "From end a (page 'Bahnhof', column 5, row 5):".
    QString endHeading(const trackgraph::BlockEnd& end) const;
    // Every way from the end, one line each ("to block 3 'Einfahrt West', end a, over turnout 1 'W1'
    // straight"), or what ends the track there when there is none.
    QStringList ways(const trackgraph::BlockEnd& end) const;
    // All of it, as rich text for a label.
    QString html(int block) const;

private:
    QString way(const trackgraph::Connection& connection) const;
    QString turnouts(const trackgraph::Connection& connection) const;
    QString crossings(const trackgraph::Connection& connection) const;
    QString routes(const trackgraph::Connection& connection) const;
    QString beyond(const trackgraph::BlockEnd& end) const;
    QString place(trackgraph::TileId tile) const;
    static QString positionName(trackgraph::TurnoutKind kind, int position);

    const trackgraph::TrackGraph& m_graph;
    Names m_names;
};

} // namespace stellwerk::ui
