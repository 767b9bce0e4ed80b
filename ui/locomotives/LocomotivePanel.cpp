#include "locomotives/LocomotivePanel.h"

#include "common/SideBySide.h"
#include "locomotives/LocomotiveFileModel.h"
#include "locomotives/LocomotiveForm.h"
#include "model/Railway.h"

#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace stellwerk::ui {

namespace {

using Kind = cs2config::EditProblem::Kind;

QPushButton* button(QWidget* parent, const char* objectName) {
    auto* created = new QPushButton(parent);
    created->setObjectName(QLatin1String(objectName));
    return created;
}

} // namespace

LocomotivePanel::LocomotivePanel(QWidget* parent)
    : QWidget(parent), m_model(new LocomotiveFileModel(this)), m_table(new QTableView(this)),
      m_form(new LocomotiveForm(this)), m_title(new QLabel(this)), m_message(new QLabel(this)),
      m_emptyText(new QLabel(this)), m_add(button(this, "newLocomotive")),
      m_remove(button(this, "deleteLocomotive")), m_apply(button(this, "applyLocomotive")),
      m_revert(button(this, "revertLocomotive")), m_save(button(this, "saveLocomotives")) {
    setObjectName(QStringLiteral("locomotivePanel"));
    m_message->setObjectName(QStringLiteral("locomotiveMessage"));
    m_message->setWordWrap(true);
    // "12 locomotives, changed and not saved" wraps rather than widening the panel beyond its dock.
    m_title->setObjectName(QStringLiteral("locomotiveTitle"));
    m_title->setWordWrap(true);
    m_emptyText->setAlignment(Qt::AlignCenter);
    m_emptyText->setEnabled(false);
    setUpTable();
    auto* tools = new QHBoxLayout;
    tools->addWidget(m_title, 1);
    tools->addWidget(m_add);
    tools->addWidget(m_remove);
    tools->addWidget(m_save);
    auto* split = new QSplitter(this);
    split->setObjectName(QStringLiteral("locomotiveSplit"));
    split->setChildrenCollapsible(false);
    split->addWidget(m_table);
    split->addWidget(editorSide());
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    // The list beside the editor where the panel is wide, above it in a side panel's width.
    SideBySide::arrange(this, split, 780);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(tools);
    layout->addWidget(m_emptyText);
    layout->addWidget(split, 1);
    connectActions();
    retranslate();
    load();
}

// A list that is read, not edited: one locomotive selected at a time, the name takes the spare width.
void LocomotivePanel::setUpTable() {
    m_table->setObjectName(QStringLiteral("locomotiveList"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    // Only the Z21 address of an MM or mfx locomotive is editable (LocomotiveFileModel::flags).
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_table->setColumnHidden(LocomotiveFileModel::Z21Address, true);
    m_table->setDragEnabled(true); // a locomotive dragged onto a block of the plan is placed there
    m_table->setDragDropMode(QAbstractItemView::DragOnly);
    m_table->setAlternatingRowColors(true);
    m_table->setShowGrid(false);
    m_table->verticalHeader()->hide();
    // Every column as wide as its contents, the name first and whole; in a narrow dock the list scrolls
    // sideways rather than cutting the names short, and in a wide one the last column takes the rest.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
}

QWidget* LocomotivePanel::editorSide() {
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_revert);
    buttons->addWidget(m_apply);
    auto* side = new QWidget(this);
    auto* layout = new QVBoxLayout(side);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_form, 1);
    layout->addWidget(m_message);
    layout->addLayout(buttons);
    return side;
}

// Buttons, and their keys: Enter in the name applies, Ctrl+S saves, Delete in the list deletes.
void LocomotivePanel::connectActions() {
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &LocomotivePanel::selectionChanged);
    connect(m_form, &LocomotiveForm::edited, this, &LocomotivePanel::edited);
    connect(m_form->nameEdit(), &QLineEdit::returnPressed, this, &LocomotivePanel::applyForm);
    connect(m_apply, &QPushButton::clicked, this, &LocomotivePanel::applyForm);
    connect(m_revert, &QPushButton::clicked, this, &LocomotivePanel::showSelected);
    connect(m_add, &QPushButton::clicked, this, &LocomotivePanel::startNewLocomotive);
    connect(m_remove, &QPushButton::clicked, this, &LocomotivePanel::askAndRemove);
    connect(m_save, &QPushButton::clicked, this, &LocomotivePanel::chooseFolderAndSave);
    auto* save = new QShortcut(QKeySequence::Save, this, this, &LocomotivePanel::chooseFolderAndSave);
    save->setContext(Qt::WidgetWithChildrenShortcut);
    auto* remove = new QShortcut(QKeySequence::Delete, m_table, this, &LocomotivePanel::askAndRemove);
    remove->setContext(Qt::WidgetShortcut);
    // F2 in the list edits the selected locomotive's Z21 address, whichever cell is current.
    auto* editZ21 = new QShortcut(QKeySequence(Qt::Key_F2), m_table, this, [this] {
        const QModelIndexList rows = m_table->selectionModel()->selectedRows();
        if (!rows.isEmpty())
            m_table->edit(m_model->index(rows.first().row(), LocomotiveFileModel::Z21Address));
    });
    editZ21->setContext(Qt::WidgetShortcut);
    connect(m_model, &LocomotiveFileModel::z21AddressChanged, this, [this](const QString& sentence) {
        if (m_saveZ21)
            m_saveZ21();
        showMessage(sentence, false);
    });
    connect(m_model, &LocomotiveFileModel::z21AddressRefused, this,
            [this](const QString& sentence) { showMessage(sentence, true); });
    connect(m_model, &LocomotiveFileModel::z21AddressesCovered, this, [this] {
        if (m_saveZ21)
            m_saveZ21();
    });
}

void LocomotivePanel::setZ21Addresses(model::Z21Addresses* book, std::function<void()> save) {
    m_saveZ21 = std::move(save);
    m_model->setZ21Addresses(book);
    m_table->setColumnHidden(LocomotiveFileModel::Z21Address, book == nullptr);
}

void LocomotivePanel::setRailway(model::Railway* railway) {
    if (m_railway)
        disconnect(m_railway, nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway) {
        connect(m_railway, &model::Railway::loaded, this, &LocomotivePanel::railwayLoaded);
        connect(m_railway, &QObject::destroyed, this, [this] { setRailway(nullptr); });
    }
    load();
}

// A new configuration from the station replaces the editor's file, unless it is our own edit or there are
// unsaved edits (the start-up runs again after the station was silent): those stay, and the railway follows
// them again.
void LocomotivePanel::railwayLoaded() {
    if (m_replacing)
        return;
    if (!m_editor.modified() || !m_railway || !m_railway->locomotiveFile()) {
        load();
        return;
    }
    m_stationFile = *m_railway->locomotiveFile();
    m_replacing = true;
    m_railway->replaceLocomotiveFile(m_editor.file());
    m_replacing = false;
    showMessage(tr("The station sent its locomotive list again; your unsaved changes are kept."), false);
}

// Back to the list the station sent, in the editor and in the railway.
void LocomotivePanel::discardEdits() {
    if (m_railway && m_stationFile) {
        m_replacing = true;
        m_railway->replaceLocomotiveFile(*m_stationFile);
        m_replacing = false;
    }
    load();
}

bool LocomotivePanel::hasUnsavedEdits() const {
    return m_editor.modified() || m_apply->isEnabled();
}

bool LocomotivePanel::settleUnsavedEdits(const QString& what) {
    if (!hasUnsavedEdits())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Unsaved locomotive changes"),
                    tr("The locomotive list has changes that are not saved. Save them before %1?").arg(what),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("unsavedLocomotivesBox"));
    box.setDefaultButton(QMessageBox::Cancel);
    box.setEscapeButton(QMessageBox::Cancel);
    switch (box.exec()) {
    case QMessageBox::Save:
        return (!m_apply->isEnabled() || applyForm()) && chooseFolderAndSave();
    case QMessageBox::Discard:
        discardEdits();
        return true;
    default:
        return false;
    }
}

void LocomotivePanel::load() {
    const cs2config::LocomotiveFile* file = m_railway ? m_railway->locomotiveFile() : nullptr;
    m_editor = file ? cs2config::LocomotiveEditor(*file) : cs2config::LocomotiveEditor();
    m_stationFile = file ? std::optional(*file) : std::nullopt;
    m_adding = false;
    m_model->show(file ? &m_editor : nullptr);
    showEmptyText();
    m_message->clear();
    if (m_model->rowCount() > 0)
        m_table->selectRow(0);
    showSelected();
}

std::optional<std::size_t> LocomotivePanel::selectedIndex() const {
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    if (rows.isEmpty())
        return std::nullopt;
    return m_model->fileIndex(rows.first().row());
}

bool LocomotivePanel::selectLocomotive(const QString& name) {
    for (int row = 0; row < m_model->rowCount(); ++row)
        if (m_model->index(row, LocomotiveFileModel::Name).data().toString() == name) {
            m_table->selectRow(row);
            return true;
        }
    return false;
}

void LocomotivePanel::setPictures(LocomotivePictureBook* pictures) {
    m_model->setPictures(pictures);
    m_form->setPictures(pictures);
}

void LocomotivePanel::selectionChanged() {
    m_adding = false;
    showSelected();
}

// The form shows the selected locomotive as the file holds it (Revert does the same).
void LocomotivePanel::showSelected() {
    const std::optional<std::size_t> index = selectedIndex();
    if (index && !m_adding) {
        m_form->setSettings(cs2config::LocomotiveSettings::of(m_editor.locomotives()[*index]));
        m_form->setIcon(QString::fromStdString(m_editor.locomotives()[*index].icon));
    }
    if (!m_adding)
        m_message->clear();
    m_apply->setEnabled(false);
    m_revert->setEnabled(false);
    updateButtons();
}

void LocomotivePanel::edited() {
    m_apply->setEnabled(true);
    m_revert->setEnabled(!m_adding);
}

void LocomotivePanel::startNewLocomotive() {
    m_table->clearSelection();
    m_adding = true;
    cs2config::LocomotiveSettings settings;
    settings.name = tr("New locomotive").toStdString();
    settings.decoder = cs2config::LocomotiveDecoder::Dcc;
    settings.functions = {{0, 1, cs2config::FunctionTrigger::Latching, 0}};
    m_form->setSettings(settings);
    m_form->setIcon({});
    showMessage(tr("Enter the new locomotive and press Add."), false);
    m_apply->setEnabled(true);
    updateButtons();
    m_form->nameEdit()->setFocus();
    m_form->nameEdit()->selectAll();
}

bool LocomotivePanel::applyForm() {
    if (!m_railway || !m_railway->locomotiveFile())
        return false;
    const cs2config::LocomotiveSettings settings = m_form->settings();
    std::size_t index = 0;
    std::optional<cs2config::EditProblem> problem;
    if (m_adding)
        problem = m_editor.add(settings, &index);
    else if (const auto selected = selectedIndex())
        problem = m_editor.apply(index = *selected, settings);
    else
        return false;
    if (problem) {
        showMessage(problemText(*problem), true);
        return false;
    }
    changed(index);
    showMessage(tr("Changed. Save to write lokomotive.cs2."), false);
    return true;
}

bool LocomotivePanel::removeSelected() {
    const std::optional<std::size_t> index = selectedIndex();
    if (!index || !m_editor.remove(*index))
        return false;
    changed(std::nullopt);
    showMessage(tr("Deleted. Save to write lokomotive.cs2."), false);
    return true;
}

void LocomotivePanel::askAndRemove() {
    const std::optional<std::size_t> index = selectedIndex();
    if (!index)
        return;
    const QString name = QString::fromStdString(m_editor.locomotives()[*index].name);
    if (QMessageBox::question(this, tr("Delete locomotive"),
                              tr("Delete '%1' from the locomotive list?").arg(name)) == QMessageBox::Yes)
        removeSelected();
}

void LocomotivePanel::addBoundDecoder(quint32 mfxUid, quint16 sid) {
    if (!m_railway || !m_railway->locomotiveFile())
        return;
    const std::size_t index = m_editor.addBoundDecoder(mfxUid, sid);
    changed(index);
    showMessage(tr("The new mfx decoder is in the list as '%1'. Save to write lokomotive.cs2.")
                    .arg(QString::fromStdString(m_editor.locomotives()[index].name)),
                false);
}

// The file changed: the railway follows it, the list shows it, `select` is selected again.
void LocomotivePanel::changed(std::optional<std::size_t> select) {
    m_adding = false;
    m_replacing = true;
    if (m_railway)
        m_railway->replaceLocomotiveFile(m_editor.file());
    m_replacing = false;
    m_model->show(&m_editor);
    if (const auto row = select ? m_model->rowOf(*select) : std::nullopt)
        m_table->selectRow(*row);
    showSelected();
}

bool LocomotivePanel::chooseFolderAndSave() {
    if (!m_save->isEnabled())
        return false;
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Save lokomotive.cs2 into a CS2 configuration folder"), m_lastFolder);
    return !folder.isEmpty() && saveTo(folder);
}

bool LocomotivePanel::saveTo(const QString& folder) {
    const std::optional<std::string> error = m_editor.save(folder.toStdString());
    if (error) {
        showMessage(tr("Not saved: %1. The edits are kept.").arg(QString::fromStdString(*error)), true);
        return false;
    }
    m_lastFolder = folder;
    showMessage(
        tr("Saved to %1.")
            .arg(QDir::toNativeSeparators(QDir(folder).filePath(QStringLiteral("config/lokomotive.cs2")))),
        false);
    updateButtons();
    return true;
}

QString LocomotivePanel::messageText() const {
    return m_message->text();
}

void LocomotivePanel::showMessage(const QString& text, bool problem) {
    m_message->setText(text);
    m_message->setStyleSheet(problem ? QStringLiteral("QLabel { color: #c82c2c; font-weight: bold; }")
                                     : QString());
}

void LocomotivePanel::updateButtons() {
    const bool file = m_railway && m_railway->locomotiveFile();
    m_add->setEnabled(file);
    m_remove->setEnabled(file && selectedIndex().has_value());
    m_save->setEnabled(file);
    m_form->setEnabled(file && (m_adding || selectedIndex().has_value()));
    m_apply->setText(m_adding ? tr("Add") : tr("Apply"));
    const int count = m_model->rowCount();
    m_title->setText(!file ? tr("Locomotives")
                           : (m_editor.modified()
                                  ? tr("%n locomotive(s), changed and not saved", nullptr, count)
                                  : tr("%n locomotive(s)", nullptr, count)));
}

QString LocomotivePanel::problemText(const cs2config::EditProblem& problem) const {
    switch (problem.kind) {
    case Kind::EmptyName:
        return tr("Give the locomotive a name.");
    case Kind::NameHasBreak:
        return tr("The name must be on one line.");
    case Kind::NameInUse:
        return tr("Another locomotive is already called '%1'.").arg(QString::fromStdString(problem.other));
    case Kind::NoDecoder:
        return tr("Choose the decoder type.");
    case Kind::AddressOutOfRange:
        return tr("The address must be between %1 and %2 for this decoder.")
            .arg(problem.minimum)
            .arg(problem.maximum);
    case Kind::AddressInUse:
        return tr("'%1' already uses this address.").arg(QString::fromStdString(problem.other));
    case Kind::FunctionNumber:
        return tr("F%1 is not a function key (F0 to F31).").arg(problem.function);
    case Kind::IconOutOfRange:
        return tr("The icon of F%1 must be between %2 and %3.")
            .arg(problem.function)
            .arg(problem.minimum)
            .arg(problem.maximum);
    case Kind::DurationOutOfRange:
        return tr("The time of F%1 must be between %2 and %3.")
            .arg(problem.function)
            .arg(problem.minimum)
            .arg(problem.maximum);
    case Kind::NoSuchLocomotive:
        break;
    }
    return tr("Select a locomotive first.");
}

void LocomotivePanel::showEmptyText() {
    const bool file = m_railway && m_railway->locomotiveFile();
    m_emptyText->setText(!m_railway ? tr("No station connected.")
                                    : tr("The station has not sent its locomotive list (lokomotive.cs2)."));
    m_emptyText->setVisible(!file);
}

void LocomotivePanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void LocomotivePanel::retranslate() {
    m_add->setText(tr("New"));
    m_remove->setText(tr("Delete"));
    m_save->setText(tr("Save to folder…"));
    m_save->setToolTip(tr("Writes config/lokomotive.cs2 into the folder you choose"));
    m_revert->setText(tr("Revert"));
    m_model->retranslate();
    m_form->retranslate();
    showEmptyText();
    updateButtons();
}

} // namespace stellwerk::ui
