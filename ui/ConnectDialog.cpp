#include "ConnectDialog.h"

#include "StationUrlSettings.h"
#include "can/TransportAddress.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace stellwerk::ui {

ConnectDialog::ConnectDialog(const QString& url, QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("connectDialog"));
    createWidgets();
    m_url->setText(url);
    m_simulated->setChecked(url.trimmed().isEmpty());
    retranslate();
    check();
}

void ConnectDialog::createWidgets() {
    m_simulated = new QCheckBox(this);
    m_simulated->setObjectName(QStringLiteral("useSimulatedStation"));
    m_urlLabel = new QLabel(this);
    m_url = new QLineEdit(this);
    m_url->setObjectName(QStringLiteral("stationUrl"));
    m_url->setPlaceholderText(QStringLiteral("udp://192.168.2.5"));
    m_url->setMinimumWidth(m_url->fontMetrics().averageCharWidth() * 40);
    m_urlLabel->setBuddy(m_url);
    m_examples = new QLabel(this);
    m_examples->setObjectName(QStringLiteral("urlExamples"));
    m_examples->setTextFormat(Qt::PlainText);
    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("urlError"));
    m_error->setStyleSheet(QStringLiteral("color: #c82c2c"));
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_connect = m_buttons->addButton(QString(), QDialogButtonBox::AcceptRole);
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_connect->setDefault(true);

    auto* form = new QFormLayout;
    form->addRow(m_urlLabel, m_url);
    form->addRow(QString(), m_examples);
    form->addRow(QString(), m_error);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_simulated);
    layout->addWidget(m_buttons);

    connect(m_url, &QLineEdit::textChanged, this, &ConnectDialog::check);
    connect(m_simulated, &QCheckBox::toggled, this, &ConnectDialog::check);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);
}

QString ConnectDialog::url() const {
    return m_simulated->isChecked() ? QString() : m_url->text().trimmed();
}

void ConnectDialog::accept() {
    check();
    if (!m_connect->isEnabled())
        return;
    StationUrlSettings::save(url());
    QDialog::accept();
}

void ConnectDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ConnectDialog::retranslate() {
    setWindowTitle(tr("Connect to a station"));
    m_urlLabel->setText(tr("Station &address:"));
    m_examples->setText(tr("Examples:\n"
                           "udp://192.168.2.5 — a CS2 with its CAN-UDP gateway switched on\n"
                           "tcp://192.168.2.5 — a CS3, or a CS2 over TCP\n"
                           "can://socketcan/can0 — a Gleisbox through a CAN adapter"));
    m_simulated->setText(tr("&Use the simulated station (demo layout)"));
    m_connect->setText(tr("&Connect"));
    check();
}

// The address must be readable unless the simulated station is chosen; the reason is shown at once.
void ConnectDialog::check() {
    const bool simulated = m_simulated->isChecked();
    m_url->setEnabled(!simulated);
    QString error;
    if (!simulated) {
        const QString text = m_url->text().trimmed();
        if (text.isEmpty())
            error = tr("Enter the station's address, or use the simulated station.");
        else if (const auto parsed = can::parseTransportUrl(text); !parsed)
            error = tr("This address cannot be used: %1").arg(parsed.error());
    }
    m_error->setText(error);
    m_error->setVisible(!error.isEmpty());
    m_connect->setEnabled(error.isEmpty());
}

} // namespace stellwerk::ui
