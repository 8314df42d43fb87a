#pragma once
// Stop controls (issue 6 §6):
//  * createStopAllAction(): the STOP ALL action for the toolbar and a global shortcut (F12 and Ctrl+Space,
//    application-wide). Never asks.
//  * StopAllButton: the large always-visible red button.
//  * MachineStopControls: stop / hold-to-release for the current machine of the shared selection, showing
//    the stop state the machine reports.
#include <QAction>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QWidget>

namespace ocu {

class FleetModel;
class FleetSelection;
class HoldToConfirmButton;
class CommandGate;

QAction* createStopAllAction(CommandGate* stop, QObject* parent);

class StopAllButton : public QPushButton {
    Q_OBJECT
public:
    explicit StopAllButton(CommandGate* stop, QWidget* parent = nullptr);
};

class MachineStopControls : public QWidget {
    Q_OBJECT
public:
    MachineStopControls(FleetModel* fleet, FleetSelection* selection, CommandGate* stop,
                        QWidget* parent = nullptr);

    QPushButton* stopButton() const { return m_stopButton; }
    HoldToConfirmButton* releaseButton() const { return m_release; }
    QLabel* stateLabel() const { return m_state; }

private:
    void refresh();

    QPointer<FleetModel> m_fleet;
    QPointer<FleetSelection> m_selection;
    QPointer<CommandGate> m_gate;
    QLabel* m_state;
    QPushButton* m_stopButton;
    HoldToConfirmButton* m_release;
};

} // namespace ocu
