#include "widgets/osyris/CrewMessagesPanel.h"

#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "widgets/CommandPermissionHint.h"
#include "widgets/OnScreenWatcher.h"

#include <QApplication>
#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace ocu {

CrewMessagesPanel::CrewMessagesPanel(QWidget* parent)
    : QWidget(parent), m_history(new QListWidget(this)), m_to(new QComboBox(this)),
      m_entry(new QLineEdit(this)), m_send(new QPushButton(tr("Send"), this)), m_bytes(new QLabel(this)),
      m_onScreen(new OnScreenWatcher(this)) {
    m_send->setObjectName(QStringLiteral("crew-send"));
    connect(m_onScreen, &OnScreenWatcher::changed, this, [this](bool onScreen) {
        if (onScreen && m_unread > 0) {
            m_unread = 0;
            emit unreadChanged(0);
        }
    });
    m_history->setWordWrap(true);
    m_history->setAlternatingRowColors(true);
    m_entry->setPlaceholderText(tr("Message to the crew (Enter sends)"));
    m_to->setToolTip(tr("Recipient"));
    auto* row = new QHBoxLayout;
    row->addWidget(m_to);
    row->addWidget(m_entry, 1);
    row->addWidget(m_bytes);
    row->addWidget(m_send);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_history, 1);
    lay->addLayout(row);
    connect(m_entry, &QLineEdit::returnPressed, this, &CrewMessagesPanel::send);
    connect(m_send, &QPushButton::clicked, this, &CrewMessagesPanel::send);
    connect(m_entry, &QLineEdit::textChanged, this, [this](const QString& t) {
        const int max = m_crew ? m_crew->crewMessageMaxBytes() : 79;
        const int n = int(t.toUtf8().size());
        m_bytes->setText(QStringLiteral("%1/%2").arg(n).arg(max));
        m_send->setEnabled(permittedShowingWhy(m_send, m_gate, QStringLiteral("send_text")) && n > 0 &&
                           n <= max && m_gate && m_bridge);
    });
    refreshRecipients();
    m_entry->textChanged(QString());
}

void CrewMessagesPanel::setCommandGate(CommandGate* gate) {
    if (m_gate)
        disconnect(m_gate, nullptr, this, nullptr);
    m_gate = gate;
    if (gate)
        connect(gate, &CommandGate::permissionsChanged, this,
                [this] { m_entry->textChanged(m_entry->text()); });
    m_entry->textChanged(m_entry->text());
}

void CrewMessagesPanel::setBridge(FleetBridge* bridge, CrewMessaging* crew) {
    if (m_bridge)
        disconnect(m_bridge, nullptr, this, nullptr);
    m_bridge = bridge;
    m_crew = crew;
    if (bridge)
        connect(bridge, &FleetBridge::eventRaised, this, &CrewMessagesPanel::onEvent);
    refreshRecipients();
    m_entry->textChanged(m_entry->text());
}

QString CrewMessagesPanel::protocolName() const {
    return m_bridge ? toText(m_bridge->protocol()) : QString();
}

void CrewMessagesPanel::refreshRecipients() {
    const QString current = m_to->currentData().toString();
    m_to->clear();
    m_to->addItem(tr("All machines"), QString());
    if (m_crew)
        for (const CrewRecipient& r : m_crew->crewRecipients())
            m_to->addItem(r.name, r.id);
    const int i = m_to->findData(current);
    m_to->setCurrentIndex(i < 0 ? 0 : i);
}

void CrewMessagesPanel::append(const QString& text, const QString& tooltip) {
    auto* item = new QListWidgetItem(text, m_history);
    item->setToolTip(tooltip);
    m_history->scrollToBottom();
}

void CrewMessagesPanel::onEvent(const FleetEvent& e) {
    if (e.kind != EventKind::TextMessage)
        return;
    append(QStringLiteral("%1  ← %2")
               .arg(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")), e.text),
           e.machineId);
    if (!e.machineId.isEmpty() && m_to->findData(e.machineId) < 0)
        refreshRecipients();
    if (!m_onScreen->onScreen()) {
        ++m_unread;
        emit unreadChanged(m_unread);
        // The desktop's notification sound, where it has one: a message is not an alarm, but the crew
        // expects it to be read.
        QApplication::beep();
    }
}

void CrewMessagesPanel::send() {
    const QString text = m_entry->text().trimmed();
    if (text.isEmpty() || !m_gate || !m_bridge || !m_send->isEnabled())
        return;
    const QString to = m_to->currentData().toString();
    const QString toName = m_to->currentText();
    const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
    auto* item = new QListWidgetItem(tr("%1  → %2: %3 (sending…)").arg(stamp, toName, text), m_history);
    m_history->scrollToBottom();
    m_entry->clear();
    QPointer<QListWidget> list = m_history;
    m_gate->command(
        SendText{to, text}, QStringLiteral("gui"), [list, item, stamp, toName, text](const CommandResult& r) {
            if (!list)
                return;
            // What went on the wire, per target (the gate's truthful result).
            item->setText(r.ok ? tr("%1  → %2: %3 (sent)").arg(stamp, toName, text)
                               : tr("%1  → %2: %3 (NOT sent: %4)").arg(stamp, toName, text, r.message));
            item->setToolTip(r.message);
        });
}

QStringList CrewMessagesPanel::history() const {
    QStringList out;
    for (int i = 0; i < m_history->count(); ++i)
        out << m_history->item(i)->text();
    return out;
}

} // namespace ocu
