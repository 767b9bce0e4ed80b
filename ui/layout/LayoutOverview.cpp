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

namespace stellwerk::ui {

LayoutOverview::LayoutOverview(QWidget* parent)
    : QWidget(parent), locomotives_(new LocomotiveTableModel(this)), contacts_(new ContactTableModel(this)),
      power_(new PowerStatus(this)), locomotiveView_(tableView(QStringLiteral("locomotiveTable"))),
      contactView_(tableView(QStringLiteral("contactTable"))) {
    setObjectName(QStringLiteral("layoutOverview"));
    locomotiveView_->setModel(locomotives_);
    contactView_->setModel(contacts_);
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

// Every column but the last, which stretches over the rest.
void LayoutOverview::fitColumns() {
    for (QTableView* view : {locomotiveView_, contactView_})
        for (int column = 0; column + 1 < view->model()->columnCount(); ++column)
            view->resizeColumnToContents(column);
}

} // namespace stellwerk::ui
