#pragma once
// Taking the stick over a running mission (AEP-4818 §8.2: a list driver keeps driving the vehicle until it
// leaves Ready): the teleop panel asks the operator first, then pauses the mission through the command gate
// (audited like any mission_pause), and opens the drive session only once the gate confirms the pause from
// the vehicle's own report (CommandGate::commandConfirmed). A refused or unconfirmed pause, or a "no", leaves
// the vehicle to its mission and says why.
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

class QMessageBox;
class QWidget;

namespace ocu {

class CommandGate;
class JausVehicleBridge;

class MissionTakeover : public QObject {
    Q_OBJECT
public:
    // `dialogParent` shows the question (not modal: STOP ALL stays at hand).
    MissionTakeover(JausVehicleBridge* bridge, CommandGate* gate, QWidget* dialogParent);

    // Whether `subsystem` runs a mission as the vehicle reports it (a drive session must then wait).
    bool runsMission(quint16 subsystem) const;
    // Asks, pauses and waits as above: `proceed` once the pause is confirmed, `refused(why)` otherwise (the
    // operator said no, the gate refused the pause, or the vehicle did not report it in time). One at a time:
    // a second call while one is pending is refused at once.
    void pauseThen(quint16 subsystem, std::function<void()> proceed, std::function<void(QString)> refused);
    // Drops a pending takeover without calling back (the panel changed vehicle or closed the session).
    void cancel();
    bool pending() const { return m_subsystem != 0; }
    // The question while it is open (tests answer it), else nullptr.
    QMessageBox* question() const { return m_question; }

private:
    void answered(bool yes);
    void finish(bool ok, const QString& why);

    QPointer<JausVehicleBridge> m_bridge;
    QPointer<CommandGate> m_gate;
    QPointer<QWidget> m_parent;
    QPointer<QMessageBox> m_question;
    quint16 m_subsystem = 0;
    std::function<void()> m_proceed;
    std::function<void(QString)> m_refused;
    bool m_paused = false; // the pause went out; waiting for the gate's confirmation
};

} // namespace ocu
