#pragma once

#include "cs2config/LocomotiveEditor.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;

namespace stellwerk::ui {

// The fields of one locomotive on the Locomotives page: name, decoder, address (with the range the
// decoder allows) and every function key's icon number and trigger. It only edits values; checking
// and applying them is the editor's job.
class LocomotivePictureBook;

class LocomotiveForm final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LocomotiveForm)

public:
    explicit LocomotiveForm(QWidget* parent = nullptr);

    void setSettings(const cs2config::LocomotiveSettings& settings);
    // The locomotive's picture (its `.icon`; empty for none) and where pictures come from.
    void setIcon(const QString& icon);
    void setPictures(LocomotivePictureBook* pictures);
    QLabel* picture() const { return m_picture; }
    QLabel* pictureName() const { return m_pictureName; }
    // What the fields hold now; every function key F0..F31 is listed.
    cs2config::LocomotiveSettings settings() const;

    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* decoderBox() const { return m_decoder; }
    QSpinBox* addressBox() const { return m_address; }
    QTableWidget* functionTable() const { return m_functions; }
    // The function key's icon, trigger and time fields (row = function number).
    QSpinBox* iconBox(int function) const;
    // What function `function`'s icon number shows, in words ("Horn"), and whether a drawing goes with it.
    QString pictureText(int function) const;
    bool showsPicture(int function) const;
    QComboBox* triggerBox(int function) const;
    QSpinBox* durationBox(int function) const;
    void retranslate();

signals:
    void edited();

private:
    void buildFunctionRows();
    void showAddressRange();
    void updateDuration(int function);
    void showPicture(int function);
    void showLocomotivePicture();

    QFormLayout* m_form;
    QLineEdit* m_name;
    QComboBox* m_decoder;
    QSpinBox* m_address;
    QLabel* m_addressRange;
    QLabel* m_nameLabel;
    QLabel* m_decoderLabel;
    QLabel* m_addressLabel;
    QLabel* m_picture;
    QLabel* m_pictureName;
    QPointer<LocomotivePictureBook> m_pictures;
    QString m_icon;
    QTableWidget* m_functions;
};

} // namespace stellwerk::ui
