#include "trackplan/LayoutFileDialog.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>

namespace stellwerk::ui {

LayoutFileDialog::LayoutFileDialog(Purpose purpose, const QString& start, QWidget* parent)
    : QFileDialog(parent), m_purpose(purpose) {
    setObjectName(QStringLiteral("layoutFileDialog"));
    // Qt's own dialog: a desktop's native one would not ask accept() below.
    setOption(QFileDialog::DontUseNativeDialog);
    setFileMode(QFileDialog::Directory);
    setDirectory(start);
    if (purpose == Purpose::Open) {
        setWindowTitle(tr("Open a CS2 layout folder or track plan page"));
        setNameFilter(tr("CS2 track plan files (*.cs2)")); // folders, and the page files in them
    } else {
        setWindowTitle(tr("Export the layout into a folder"));
        setOption(QFileDialog::ShowDirsOnly);
    }
}

void LayoutFileDialog::accept() {
    const QString selected = selectedFiles().value(0);
    const QFileInfo info(selected);
    if (m_purpose == Purpose::Open && info.isFile()) { // a page file: Qt's chooser of folders refuses it
        m_chosen = info.absoluteFilePath();
        QDialog::accept();
        return;
    }
    if (m_purpose == Purpose::Export && !selected.isEmpty() && !info.exists() && !makeFolder(selected))
        return;
    m_chosen = selected;
    QFileDialog::accept();
}

bool LayoutFileDialog::makeFolder(const QString& folder) {
    if (QDir().mkpath(folder))
        return true;
    QMessageBox::warning(
        this, windowTitle(),
        tr("The folder %1 cannot be made here. Choose another place.").arg(QDir::toNativeSeparators(folder)));
    return false;
}

} // namespace stellwerk::ui
