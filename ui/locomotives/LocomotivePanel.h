#pragma once

#include "cs2config/LocomotiveEditor.h"

#include <QPointer>
#include <QWidget>
#include <functional>
#include <optional>

class QLabel;
class QPushButton;
class QTableView;

namespace stellwerk::model {
class Railway;
class Z21Addresses;
} // namespace stellwerk::model

namespace stellwerk::ui {

class LocomotiveFileModel;
class LocomotiveForm;
class LocomotivePictureBook;

// The Locomotives page: the station's locomotives from lokomotive.cs2 in a list, an editor for the
// selected one (name, decoder, address, function keys) that refuses bad values with a reason, new and
// delete, and saving the edited file into a CS2 configuration folder (config/lokomotive.cs2). The
// railway's locomotives follow every applied edit; nothing is sent to the station. With the phone servers'
// book, the list shows each locomotive's Z21 address and an MM or mfx one's is changed in place (saved at
// once, a taken or impossible one refused with a reason).
class LocomotivePanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotivePanel)

public:
    explicit LocomotivePanel(QWidget* parent = nullptr);

    // The railway whose lokomotive.cs2 the page edits (null: none).
    void setRailway(model::Railway* railway);
    // The book of Z21 addresses the list shows and edits, and what saves it after each change (null: the
    // column is hidden).
    void setZ21Addresses(model::Z21Addresses* book, std::function<void()> save);
    // The locomotives' pictures for the list and the form.
    void setPictures(LocomotivePictureBook* pictures);

    const cs2config::LocomotiveEditor& editor() const { return m_editor; }
    LocomotiveFileModel* model() const { return m_model; }
    LocomotiveForm* form() const { return m_form; }
    QTableView* table() const { return m_table; }
    // Selects the locomotive with this name; false when there is none.
    bool selectLocomotive(const QString& name);
    // Applies the form to the selected (or new) locomotive; false (and the reason shown) when refused.
    bool applyForm();
    // Starts a new locomotive in the form; Apply adds it.
    void startNewLocomotive();
    // Removes the selected locomotive from the file (without asking).
    bool removeSelected();
    // Writes <folder>/config/lokomotive.cs2; false (and the reason shown) when that failed.
    bool saveTo(const QString& folder);
    // Adds an mfx decoder just bound to `sid` (from the Programming page) as a locomotive.
    void addBoundDecoder(quint32 mfxUid, quint16 sid);
    // True while there are edits that are not in a saved lokomotive.cs2: applied ones, or a form being
    // edited and not applied yet.
    bool hasUnsavedEdits() const;
    // Before something that would lose unsaved edits (quitting, connecting again, opening another layout):
    // asks "Save / Discard / Cancel" when there are any. True when it may go on (nothing unsaved, saved,
    // or discarded); false on Cancel or when saving failed, and then everything stays as it was.
    bool settleUnsavedEdits(const QString& what);
    // The last message: why a change was refused, or what was saved.
    QString messageText() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void setUpTable();
    QWidget* editorSide();
    void connectActions();
    void load();
    void railwayLoaded();
    void selectionChanged();
    void showSelected();
    void edited();
    void changed(std::optional<std::size_t> select);
    bool chooseFolderAndSave();
    void discardEdits();
    void askAndRemove();
    void showMessage(const QString& text, bool problem);
    void updateButtons();
    void showEmptyText();
    void retranslate();
    QString problemText(const cs2config::EditProblem& problem) const;
    std::optional<std::size_t> selectedIndex() const;

    QPointer<model::Railway> m_railway;
    cs2config::LocomotiveEditor m_editor;
    std::optional<cs2config::LocomotiveFile> m_stationFile; // as the station sent it, for Discard
    LocomotiveFileModel* m_model;
    QTableView* m_table;
    LocomotiveForm* m_form;
    QLabel* m_title;
    QLabel* m_message;
    QLabel* m_emptyText;
    QPushButton* m_add;
    QPushButton* m_remove;
    QPushButton* m_apply;
    QPushButton* m_revert;
    QPushButton* m_save;
    std::function<void()> m_saveZ21;
    bool m_adding = false;
    bool m_replacing = false; // our own edit makes the railway reload: keep the editor as it is
    QString m_lastFolder;
};

} // namespace stellwerk::ui
