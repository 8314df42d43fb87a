#pragma once
// Crew messages panel: the history of messages both ways, a recipient picker (all machines or
// one), a text entry that sends on Enter. Sending goes through the command gate (audited); the history shows
// what went on the wire (the gate's result per target), received messages show their sender.
#include "models/CrewMessaging.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace ocu {

class CommandGate;
class FleetBridge;
class OnScreenWatcher;
struct CommandResult;
struct FleetEvent;

class CrewMessagesPanel : public QWidget {
    Q_OBJECT
public:
    explicit CrewMessagesPanel(QWidget* parent = nullptr);

    // The gate that sends; the bridge whose crews are messaged (its received texts are shown). Not owned.
    void setCommandGate(CommandGate* gate);
    void setBridge(FleetBridge* bridge, CrewMessaging* crew);

    QStringList history() const; // oldest first, as shown
    // Messages from the machines that arrived while the panel was not in front of the operator; cleared
    // when it comes in front.
    int unreadCount() const { return m_unread; }
    QComboBox* recipientPicker() const { return m_to; }
    QLineEdit* entry() const { return m_entry; }

public slots:
    void refreshRecipients();
    void send();

signals:
    // The unread count changed (a message arrived unseen, or the panel came in front).
    void unreadChanged(int unread);

private:
    void onEvent(const FleetEvent& e);
    void append(const QString& text, const QString& tooltip = {});
    QString protocolName() const;

    QPointer<CommandGate> m_gate;
    QPointer<FleetBridge> m_bridge;
    CrewMessaging* m_crew = nullptr;
    QListWidget* m_history;
    QComboBox* m_to;
    QLineEdit* m_entry;
    QPushButton* m_send;
    QLabel* m_bytes;
    OnScreenWatcher* m_onScreen;
    int m_unread = 0;
};

} // namespace ocu
