#pragma once
// Hand-off of control between consoles in the JAUS panel (AEP-4818 §6.3), a banner above the vehicle table,
// never a modal dialog (the operator may be driving):
//  * another console asks for a vehicle this console holds: who asks (its JAUS ID, authority) and why,
//  Accept,
//    Deny and Wait (the request stays, its decision time starts again), and the seconds left before the
//    vehicle's decision timeout answers it TIMEOUT;
//  * the selected vehicle is held by another console: a reason and "Ask for hand-off" (for a vehicle without
//    Enhanced Access Control the banner says that the ordinary pre-emption rules apply instead);
//  * this console's own request: where it stands (waiting, granted, denied, timed out...) with Withdraw while
//    it waits and OK to put away the outcome.
// Answers and requests go through the command gate (audited, with their per-target results). Every button is
// in the panel's Tab chain.
#include "models/jaus/JausVehicle.h"

#include <QFrame>
#include <QHash>
#include <QMap>
#include <QPointer>

#include <memory>

class QLabel;
class QLineEdit;
class QPushButton;
class QTimer;

namespace ocu {

class CommandGate;
class ControlRoomModel;
class FleetSelection;
class JausVehicleBridge;
class ModelClock;

class HandoffBanner : public QFrame {
    Q_OBJECT
public:
    HandoffBanner(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection,
                  QWidget* parent = nullptr);
    // The countdown's clock (null: the models' system clock).
    void setClock(std::shared_ptr<const ModelClock> clock);
    // Who is where across the control room: a requester or holder that is a console of the room is named
    // by its operator and console, the JAUS ID beside them (null: JAUS IDs only).
    void setControlRoom(ControlRoomModel* room);

    // For keyboard users' tests and the screenshots.
    QPushButton* acceptButton() const { return m_accept; }
    QPushButton* denyButton() const { return m_deny; }
    QPushButton* waitButton() const { return m_wait; }
    QPushButton* askButton() const { return m_ask; }
    QPushButton* withdrawButton() const { return m_withdraw; }
    QPushButton* dismissButton() const { return m_dismiss; }
    QLineEdit* reasonEdit() const { return m_reason; }
    // Its focusable widgets in Tab order (the panel puts them between "Release all" and the vehicle table).
    QList<QWidget*> tabChain() const;
    QString promptText() const;
    QString statusText() const;
    bool promptShown() const;

private:
    // "bob at dispatch-desk (console 201.1.1)" for a console of the room, empty for another.
    QString personAt(const QString& jausId) const;
    // What the banner needs of a vehicle, kept from its updates (which come at the pose rate): the banner
    // redraws only when this changes.
    struct Seen {
        quint16 subsystem = 0;
        QString callSign;
        JausAddress controller;
        int controllerAuthority = 0;
        bool controlledByUs = false;
        JausLink link = JausLink::Down;
        JausHandoff handoff;
        bool operator==(const Seen&) const = default;
    };
    void onVehicle(const JausVehicle& v);
    void refresh();
    void showPrompt(const Seen* holder);
    void showAsk(const Seen* selected);
    void showStatus(const Seen* own);
    void updateCountdown();
    void answer(bool accept, bool wait = false);
    static QString nameOf(const Seen& v);

    JausVehicleBridge* m_bridge;
    QPointer<CommandGate> m_gate;
    QPointer<ControlRoomModel> m_room;
    FleetSelection* m_selection;
    std::shared_ptr<const ModelClock> m_clock;
    QFrame* m_promptBox;
    QLabel* m_promptLabel;
    QLabel* m_countdown;
    QPushButton* m_accept;
    QPushButton* m_deny;
    QPushButton* m_wait;
    QFrame* m_askBox;
    QLabel* m_askLabel;
    QLineEdit* m_reason;
    QPushButton* m_ask;
    QFrame* m_statusBox;
    QLabel* m_statusLabel;
    QPushButton* m_withdraw;
    QPushButton* m_dismiss;
    QTimer* m_tick;
    // The prompt shown: vehicle and the vehicle's queue ID of the request.
    quint16 m_promptVehicle = 0;
    JausHandoffPrompt m_prompt;
    quint16 m_askVehicle = 0, m_statusVehicle = 0;
    QMap<quint16, Seen> m_seen;
    // Outcomes put away with OK, per vehicle (a new outcome shows again).
    QHash<quint16, QString> m_dismissed;
};

} // namespace ocu
