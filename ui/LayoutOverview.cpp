#include "LayoutOverview.h"

#include "ContactTableModel.h"
#include "LocomotiveTableModel.h"
#include "StatusDot.h"
#include "model/Railway.h"

#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace stellwerk::ui {

namespace {

constexpr int LampSize = 14;

QColor powerColour(std::optional<station::PowerState> power) {
    if (!power)
        return StatusDot::Unknown;
    switch (*power) {
    case station::PowerState::Running:
        return StatusDot::Running;
    case station::PowerState::Halted:
        return StatusDot::Halted;
    case station::PowerState::Stopped:
        break;
    }
    return StatusDot::Stopped;
}

} // namespace

LayoutOverview::LayoutOverview(QWidget* parent)
    : QWidget(parent), locomotives_(new LocomotiveTableModel(this)), contacts_(new ContactTableModel(this)),
      powerLamp_(new QLabel(this)), power_(new QLabel(this)),
      locomotiveView_(tableView(QStringLiteral("locomotiveTable"))),
      contactView_(tableView(QStringLiteral("contactTable"))) {
    setObjectName(QStringLiteral("layoutOverview"));
    power_->setObjectName(QStringLiteral("trackPower"));
    locomotiveView_->setModel(locomotives_);
    contactView_->setModel(contacts_);
    auto* powerLine = new QHBoxLayout;
    powerLine->addWidget(powerLamp_);
    powerLine->addWidget(power_, 1);
    auto* tables = new QSplitter(Qt::Horizontal, this);
    locomotiveBox_ = tableBox(locomotiveView_, QStringLiteral("locomotiveBox"));
    contactBox_ = tableBox(contactView_, QStringLiteral("contactBox"));
    tables->addWidget(locomotiveBox_);
    tables->addWidget(contactBox_);
    tables->setStretchFactor(0, 3);
    tables->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(powerLine);
    layout->addWidget(tables, 1);
    retranslate();
    showPower();
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
    view->horizontalHeader()->setStretchLastSection(true);
    view->horizontalHeader()->setHighlightSections(false);
    return view;
}

QGroupBox* LayoutOverview::tableBox(QTableView* view, const QString& objectName) {
    auto* box = new QGroupBox(this);
    box->setObjectName(objectName);
    auto* layout = new QVBoxLayout(box);
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
        connect(railway_, &model::Railway::powerChanged, this, &LayoutOverview::showPower);
        connect(railway_, &model::Railway::loaded, this, [this] {
            locomotiveView_->resizeColumnsToContents();
            contactView_->resizeColumnsToContents();
            showPower();
        });
        connect(railway_, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    showPower();
}

QString LayoutOverview::powerText() const {
    if (!railway_)
        return tr("No station connected");
    const std::optional<station::PowerState> power = railway_->power();
    if (!power)
        return tr("Track power: not reported yet");
    switch (*power) {
    case station::PowerState::Running:
        return tr("Track power: on, trains may run");
    case station::PowerState::Halted:
        return tr("Track power: on, every train halted");
    case station::PowerState::Stopped:
        break;
    }
    return tr("Track power: off (stop)");
}

void LayoutOverview::showPower() {
    powerLamp_->setPixmap(StatusDot::icon(powerColour(railway_ ? railway_->power() : std::nullopt), LampSize)
                              .pixmap(LampSize, LampSize));
    power_->setText(powerText());
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
    showPower();
}

} // namespace stellwerk::ui
