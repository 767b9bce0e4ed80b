#include "trackplan/TileMenu.h"

#include "model/Railway.h"
#include "model/TrackLayout.h"
#include "trackplan/TrackTileInfo.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QPointer>
#include <algorithm>
#include <vector>

namespace stellwerk::ui {
namespace {

// A checkable entry of an exclusive group that calls `choose` on the railway while it still exists.
template <class Choose>
void addChoice(QMenu& menu, QActionGroup& group, const QString& text, bool checked, model::Railway& railway,
               Choose choose) {
    QAction* action = menu.addAction(text);
    action->setCheckable(true);
    action->setChecked(checked);
    group.addAction(action);
    QObject::connect(action, &QAction::triggered, &railway,
                     [railway = QPointer<model::Railway>(&railway), choose] {
                         if (railway)
                             choose(*railway);
                     });
}

// An entry that calls `run` on the railway while it still exists.
template <class Run>
QAction* addAction(QMenu& menu, const QString& text, model::Railway& railway, Run run) {
    QAction* action = menu.addAction(text);
    QObject::connect(action, &QAction::triggered, &railway,
                     [railway = QPointer<model::Railway>(&railway), run] {
                         if (railway)
                             run(*railway);
                     });
    return action;
}

} // namespace

bool TileMenu::fill(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway) {
    menu.setObjectName(QStringLiteral("trackTileMenu"));
    if (tile.accessory)
        return fillPositions(menu, tile, railway);
    if (tile.route)
        return fillRoute(menu, tile, railway);
    if (tile.contact)
        return fillOccupants(menu, tile, railway);
    return false;
}

bool TileMenu::fillPositions(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway) {
    const model::Accessory* accessory = railway.accessory(*tile.accessory);
    if (!accessory)
        return false;
    auto* group = new QActionGroup(&menu);
    const std::int64_t id = accessory->id();
    for (int position = 0; position < accessory->positionCount(); ++position)
        addChoice(menu, *group, TrackTileInfo::positionName(tile.type, tile.category, position),
                  position == accessory->position(), railway,
                  [id, position](model::Railway& r) { r.switchAccessory(id, position); });
    return true;
}

// A route runs from Stellwerk (each accessory switched in turn) or, where it has a memory slot, from the
// station's memory, which other programs on the station see as running and active.
bool TileMenu::fillRoute(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway) {
    const model::Route* route = railway.route(*tile.route);
    if (!route)
        return false;
    const std::int64_t id = route->id();
    const QString slot = model::BlockStates::memorySlotOfRoute(id);
    addAction(menu, tr("Run from Stellwerk"), railway, [id](model::Railway& r) { r.runRoute(id); });
    if (slot.isEmpty())
        return true;
    QAction* ask = addAction(menu, tr("Run from the station's memory (%1)").arg(slot), railway,
                             [id](model::Railway& r) { r.blockStates().requestRoute(id); });
    ask->setObjectName(QStringLiteral("memoryEntry"));
    return true;
}

bool TileMenu::fillOccupants(QMenu& menu, const model::LayoutTile& tile, model::Railway& railway) {
    const model::FeedbackContact* contact = railway.contact(*tile.contact);
    if (!contact || !contact->occupied())
        return false; // a free contact has nobody on it to name
    menu.addSection(tr("Locomotive on this contact"));
    auto* group = new QActionGroup(&menu);
    const model::ContactKey key = contact->key();
    addChoice(menu, *group, tr("Not known"), contact->occupant() == 0, railway,
              [key](model::Railway& r) { r.reportOccupant(key, 0); });
    std::vector<const model::Locomotive*> locomotives;
    for (const model::Locomotive& locomotive : railway.state().locomotives().items())
        locomotives.push_back(&locomotive);
    std::sort(locomotives.begin(), locomotives.end(), [](const auto* a, const auto* b) {
        return QString::localeAwareCompare(a->displayName(), b->displayName()) < 0;
    });
    for (const model::Locomotive* locomotive : locomotives) {
        const std::uint32_t locId = locomotive->id().value();
        addChoice(menu, *group, locomotive->displayName(), contact->occupant() == locId, railway,
                  [key, locId](model::Railway& r) { r.reportOccupant(key, locId); });
    }
    return true;
}

} // namespace stellwerk::ui
