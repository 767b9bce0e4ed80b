#include "layout/LayoutOverview.h"

#include "common/LocomotiveTableModel.h"
#include "common/PowerStatus.h"
#include "layout/ContactTableModel.h"
#include "model/Railway.h"

#include <QEvent>
#include <QGroupBox>
#include <QHeaderView>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

namespace stellwerk::ui {

LayoutOverview::LayoutOverview(QWidget* parent)
    : QWidget(parent), locomotives_(new LocomotiveTableModel(this)), contacts_(new ContactTableModel(this)),
      power_(new PowerStatus(this)), locomotiveView_(tableView(QStringLiteral("locomotiveTable"))),
      contactView_(tableView(QStringLiteral("contactTable"))) {
    setObjectName(QStringLiteral("layoutOverview"));
    locomotiveView_->setModel(locomotives_);
    contactView_->setModel(contacts_);
    // A longer name or speed text may need the room of another column (one refit per batch of changes).
    for (QAbstractItemModel* model :
         {static_cast<QAbstractItemModel*>(locomotives_), static_cast<QAbstractItemModel*>(contacts_)}) {
        connect(model, &QAbstractItemModel::dataChanged, this, &LayoutOverview::fitColumns);
        connect(model, &QAbstractItemModel::rowsInserted, this, &LayoutOverview::fitColumns);
    }
    auto* tables = new QSplitter(Qt::Horizontal, this);
    locomotiveBox_ = tableBox(locomotiveView_, QStringLiteral("locomotiveBox"));
    contactBox_ = tableBox(contactView_, QStringLiteral("contactBox"));
    tables->addWidget(locomotiveBox_);
    tables->addWidget(contactBox_);
    // Half each: the contacts' five columns need as much room as the locomotives' (whose functions column
    // has room to spare); at 1366 px the contacts would scroll sideways with less.
    tables->setStretchFactor(0, 1);
    tables->setStretchFactor(1, 1);
    // Below the plan the height is short: little chrome, so that the tables show several rows.
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);
    layout->addWidget(power_);
    layout->addWidget(tables, 1);
    retranslate();
}

// A table that is read, not edited: whole rows, no row numbers, columns as wide as their contents.
QTableView* LayoutOverview::tableView(const QString& objectName) {
    auto* view = new QTableView(this);
    view->setObjectName(objectName);
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setAlternatingRowColors(true);
    view->setShowGrid(false);
    view->setWordWrap(false);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 6);
    view->horizontalHeader()->setStretchLastSection(true);
    view->horizontalHeader()->setHighlightSections(false);
    return view;
}

QGroupBox* LayoutOverview::tableBox(QTableView* view, const QString& objectName) {
    auto* box = new QGroupBox(this);
    box->setObjectName(objectName);
    box->setFlat(true);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 2, 0, 0);
    layout->addWidget(view);
    return box;
}

void LayoutOverview::setRailway(const model::Railway* railway) {
    if (railway_)
        disconnect(railway_, nullptr, this, nullptr);
    railway_ = railway;
    locomotives_->setRailway(railway);
    contacts_->setRailway(railway);
    if (railway_) {
        connect(railway_, &model::Railway::loaded, this, &LayoutOverview::fitColumns);
        // "(not reported)" comes and goes
        connect(railway_, &model::Railway::stateReportedChanged, this, &LayoutOverview::fitColumns);
        connect(railway_, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    power_->setRailway(railway);
}

QString LayoutOverview::powerText() const {
    return power_->text();
}

void LayoutOverview::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void LayoutOverview::retranslate() {
    locomotiveBox_->setTitle(tr("Locomotives"));
    contactBox_->setTitle(tr("Feedback contacts"));
    locomotives_->retranslate();
    contacts_->retranslate();
    fitColumns(); // headers and texts of another language have other widths
}

void LayoutOverview::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitColumns();
}

// Every column but the last, which stretches over the rest.
void LayoutOverview::fitColumns() {
    for (QTableView* view : {locomotiveView_, contactView_})
        fitColumnsOf(*view);
}

// Columns as wide as their contents; where the table is narrower than that (a laptop's dock, the longer
// "(not reported)" texts), the widest columns give way and shorten their texts with "…" rather than
// the table scrolling sideways. None gets narrower than its header.
void LayoutOverview::fitColumnsOf(QTableView& view) {
    const int columns = view.model()->columnCount();
    const QAbstractItemView& cells = view; // where the contents' width is public
    QList<int> wanted;
    int total = 0;
    for (int column = 0; column < columns; ++column) {
        wanted << std::max(cells.sizeHintForColumn(column), view.horizontalHeader()->sectionSizeHint(column));
        total += wanted.last();
    }
    // The stretched last column is never narrower than the header's default section.
    total += std::max(0, view.horizontalHeader()->defaultSectionSize() - wanted.last());
    wanted.last() = std::max(wanted.last(), view.horizontalHeader()->defaultSectionSize());
    const int room = view.viewport()->width();
    int widest = total > room ? widestAllowed(wanted, room) : std::numeric_limits<int>::max();
    for (int column = 0; column + 1 < columns; ++column)
        view.setColumnWidth(column, std::max(std::min(wanted[column], widest),
                                             view.horizontalHeader()->sectionSizeHint(column)));
}

// The width at which capping every column of `wanted` makes them fit `room` together.
int LayoutOverview::widestAllowed(QList<int> wanted, int room) {
    std::sort(wanted.begin(), wanted.end());
    int below = 0; // the columns narrower than the cap keep their widths
    for (qsizetype i = 0; i < wanted.size(); ++i) {
        const int cap = (room - below) / int(wanted.size() - i);
        if (cap <= wanted[i])
            return std::max(cap, 0);
        below += wanted[i];
    }
    return wanted.isEmpty() ? room : wanted.last();
}

} // namespace stellwerk::ui
