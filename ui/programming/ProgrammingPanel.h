#pragma once

#include "model/Programmer.h"

#include <QPointer>
#include <QWidget>
#include <cstdint>
#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The Programming page: search the track for new mfx decoders (with the station's search steps as
// progress), register a found one on a free SID (bind, then verify), and read or write a decoder's CVs
// on the programming or main track, showing the value or why there is none. One command at a time, as
// the station takes them.
class FoundDecoders;

class ProgrammingPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ProgrammingPanel)

public:
    explicit ProgrammingPanel(QWidget* parent = nullptr);

    // The railway whose station is programmed (null: none).
    void setRailway(model::Railway* railway);

    QPushButton* searchButton() const { return m_search; }
    QProgressBar* searchProgress() const { return m_progress; }
    QTableWidget* decoderTable() const;
    QSpinBox* sidBox() const { return m_sid; }
    QPushButton* registerButton() const { return m_register; }
    QComboBox* locomotiveBox() const { return m_locomotive; }
    QComboBox* protocolBox() const { return m_protocol; }
    QSpinBox* addressBox() const { return m_address; }
    QSpinBox* cvBox() const { return m_cv; }
    QSpinBox* indexBox() const { return m_index; }
    QSpinBox* valueBox() const { return m_value; }
    QComboBox* trackBox() const { return m_track; }
    QComboBox* modeBox() const { return m_mode; }
    QPushButton* readButton() const { return m_read; }
    QPushButton* writeButton() const { return m_write; }
    QString searchText() const;
    QString resultText() const;
    // Chooses the locomotive with this name for CV programming; false when there is none.
    bool chooseLocomotive(const QString& name);

signals:
    // A decoder the search found was bound to `sid` and answered under it.
    void decoderBound(quint32 mfxUid, quint16 sid);

protected:
    void changeEvent(QEvent* event) override;

private:
    QGroupBox* buildRegistration();
    QGroupBox* buildCvProgramming();
    void createCvFields();
    QGridLayout* cvGrid();
    void fillLocomotives();
    void locomotiveChosen();
    void protocolChosen();
    void search();
    void registerDecoder();
    void readCv();
    void writeCv();
    void progressed(int range, quint32 uidSoFar);
    void finished(const model::ProgrammingResult& result);
    void discoveryFinished(const model::ProgrammingResult& result);
    void bindFinished(const model::ProgrammingResult& result);
    void verifyFinished(const model::ProgrammingResult& result);
    void instruct(std::function<QString()> text);
    void showResult(std::function<QString()> text, bool problem);
    std::optional<model::CvTarget> target() const;
    std::uint16_t suggestedSid() const;
    void updateEnabled();
    void retranslate();

    QPointer<model::Railway> m_railway;
    QGroupBox* m_registration = nullptr;
    QGroupBox* m_programming = nullptr;
    QPushButton* m_search = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_searchText = nullptr;
    std::function<QString()> m_instruction;
    FoundDecoders* m_decoders = nullptr;
    QLabel* m_sidLabel = nullptr;
    QSpinBox* m_sid = nullptr;
    QPushButton* m_register = nullptr;
    QComboBox* m_locomotive = nullptr;
    QComboBox* m_protocol = nullptr;
    QSpinBox* m_address = nullptr;
    QSpinBox* m_cv = nullptr;
    QSpinBox* m_index = nullptr;
    QSpinBox* m_value = nullptr;
    QComboBox* m_track = nullptr;
    QComboBox* m_mode = nullptr;
    QSpinBox* m_bit = nullptr;
    QCheckBox* m_bitOn = nullptr;
    QLabel* m_protocolNote = nullptr;
    QPushButton* m_read = nullptr;
    QPushButton* m_write = nullptr;
    QLabel* m_result = nullptr;
    std::function<QString()> m_resultSaid;
    QList<QLabel*> m_labels; // the form's labels, named in retranslate()
    std::uint16_t m_lastBoundSid = 0;
    bool m_searchFailed = false;
};

} // namespace stellwerk::ui
