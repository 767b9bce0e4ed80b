#pragma once

#include <QFileDialog>

namespace stellwerk::ui {

// The folder dialog of the layout's file commands, which Qt's folder chooser alone cannot be: "Open
// layout…" takes a configuration folder or a single .cs2 page file, and "Export layout…" takes a folder
// typed in that does not exist yet and makes it (Qt refuses such a name with "Directory not found").
class LayoutFileDialog final : public QFileDialog {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LayoutFileDialog)

public:
    enum class Purpose { Open, Export };

    LayoutFileDialog(Purpose purpose, const QString& start, QWidget* parent = nullptr);

    // The folder or file chosen (after exec() returned Accepted).
    QString chosen() const { return m_chosen; }

public slots:
    void accept() override;

private:
    bool makeFolder(const QString& folder);

    Purpose m_purpose;
    QString m_chosen;
};

} // namespace stellwerk::ui
