#pragma once
// Teleop panel for the selected vehicle this console controls: on-screen stick, keyboard
// (W/A/S/D or arrows with the dead-man key), SDL2 joysticks; wrench effort or velocity as the platform
// offers; a speed limit within the platform specifications; zero on release, focus loss and joystick
// loss; a large E-STOP (Space, Esc) and clear-emergency only by holding a confirm button.
// The vehicle's video above the controls, or in a panel of its own (detachVideo; TeleopVideoPane: cameras,
// overlays, full-screen window),
// the video watchdog (driving is held while the video is lost or too old, and resumes only by the
// operator's Resume once it is back), and the camera's pan-tilt from J/L/I/K, the stick's camera mode and
// a joystick hat.
#include "models/jaus/JausVehicle.h"
#include "widgets/teleop/InputDevice.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QLabel;
class QComboBox;
class QSlider;
class QPushButton;
class QBoxLayout;

namespace ocu {

class OnScreenWatcher;

class JausVehicleBridge;
class CommandGate;
class FleetSelection;
class TeleopController;
class VirtualStick;
class AxisDisplay;
class HoldToConfirmButton;
class InputDevice;
class PanTiltController;
class TeleopVideoPane;
class MissionTakeover;

class TeleopPanel : public QWidget {
    Q_OBJECT
public:
    // device: the joystick source (SDL2 in the app, a fake in tests); may be null.
    // Stop and clear go through the command gate (audited; clear with its confirmation token).
    TeleopPanel(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection, InputDevice* device,
                QWidget* parent = nullptr);
    ~TeleopPanel() override;

    std::uint16_t vehicle() const { return m_subsystem; }
    void setVehicle(std::uint16_t subsystem);
    TeleopController* controller() const { return m_controller; }
    VirtualStick* stick() const { return m_stick; }
    QPushButton* emergencyButton() const { return m_estop; }
    HoldToConfirmButton* clearEmergencyButton() const { return m_clear; }
    // Why driving does not reach the vehicle right now (a session the gate could not start, a demand
    // refused, a stream message the socket did not take); empty while all is well. Shown in red.
    QString driveProblem() const;
    // True while a drive session is open (started through the command gate and not ended).
    bool sessionOpen() const { return m_session == Session::Open; }
    // Taking the stick over a running mission (its question while it is open).
    MissionTakeover* missionTakeover() const { return m_takeover; }
    // The JAUS drive command for a normalised demand, with the current mode and platform limits.
    JausDrive toDriveCommand(DriveAxes axes) const;
    bool velocityMode() const;
    // Opens the joystick mapping dialog (non-blocking). Nothing drives while it is open; OK applies the
    // mapping to the device and saves it for that device name.
    void openJoystickMapping();
    QPushButton* joystickMappingButton() const { return m_mapButton; }

    // Pan-tilt rate (rad/s) at full stick deflection (AEP-4818 §9.3.3 rates; the unit clamps to its own).
    static constexpr double kPanTiltFullRate = 1.0;
    // The video pane, the pan-tilt stream, cameras configured for vehicles that announce none.
    TeleopVideoPane* video() const;
    // Takes the video out of this panel for a panel of its own (the UGV workspace gives it the largest area);
    // the caller reparents it, created after this panel so that this one goes first. Driving then needs
    // both in the operator's sight: the video leaving the screen releases the controls too.
    TeleopVideoPane* detachVideo();
    PanTiltController* panTilt() const { return m_panTilt; }
    // The on-screen stick drives the camera's pan-tilt instead of the vehicle while checked.
    QPushButton* stickCameraButton() const { return m_stickCamera; }
    void setConfiguredCameras(quint16 subsystem, const QVector<JausVideoEndpoint>& cameras);
    // Why the video watchdog holds driving (empty when it does not).
    QString videoHold() const;

signals:
    // A pan-tilt rate demand for the shown camera (rates -1..1 of the sensor's), sent to the vehicle.
    void panTiltCommand(quint16 subsystem, quint16 sensorId, double panRate, double tiltRate);

protected:
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;
    void focusOutEvent(QFocusEvent* e) override;
    void showEvent(QShowEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // Construction, in the order the panel is laid out.
    void buildVideoAndLabels();
    void buildStopButtons();
    QBoxLayout* buildInputs();
    void buildLayout(QBoxLayout* inputs);
    void connectStickAndVideo();
    void connectInputDevice(InputDevice* device);
    void refresh();
    void emergencyStop();
    void onCommand(DriveAxes axes);
    // Drive sessions go through the command gate: start at the first demand, end on release,
    // focus loss, joystick loss, vehicle change, a refused demand; one audit line each.
    void startSession();
    // The vehicle runs a mission: ask, pause it through the gate, then drive (MissionTakeover).
    void takeOverMission();
    void endSession(const QString& reason);
    void showDriveProblem(const QString& text);
    void onWatchdog();
    void onPanTilt(double pan, double tilt);
    void releaseAll(const QString& reason);
    // The controls and the video are in front of the operator (or the full-screen video window is open).
    bool inSight() const;

    JausVehicleBridge* m_bridge;
    QPointer<CommandGate> m_gate;
    FleetSelection* m_selection;
    std::uint16_t m_subsystem = 0;
    TeleopController* m_controller;
    VirtualStick* m_stick;
    AxisDisplay* m_axes;
    QLabel* m_title;
    QLabel* m_state;
    QLabel* m_live;
    QLabel* m_device;
    InputDevice* m_inputDevice = nullptr;
    QPushButton* m_mapButton = nullptr;
    QComboBox* m_mode;
    QSlider* m_limit;
    QLabel* m_limitLabel;
    QPushButton* m_estop;
    HoldToConfirmButton* m_clear;
    enum class Session { Closed, Opening, Open };
    Session m_session = Session::Closed;
    // After a session failed or was ended by a refusal, a new one starts only once the input was released
    // (no new session, and audit line, per 20 Hz demand while the operator still holds the stick).
    bool m_waitForRelease = false;
    QLabel* m_problem;
    QLabel* m_keysHint = nullptr;
    QPointer<TeleopVideoPane> m_video; // in another dock once detached: may go first
    PanTiltController* m_panTilt = nullptr;
    QPushButton* m_stickCamera = nullptr;
    QLabel* m_videoHold = nullptr;
    QHash<quint16, QVector<JausVideoEndpoint>> m_configuredCameras;
    bool m_autoSelect = true; // until a vehicle is set (selection or setVehicle)
    // Narrow docks (a 1366 px laptop's side column): the stick above its settings and the stop buttons
    // stacked, instead of side by side, so the panel fits the width it has (the video takes that width).
    void fitToWidth();
    QBoxLayout* m_inputs = nullptr;
    QBoxLayout* m_inputsRight = nullptr;
    QBoxLayout* m_stops = nullptr;
    QPointer<QWidget> m_widthSource; // whose width is available (the scroll area's viewport, or the panel)
    OnScreenWatcher* m_onScreen = nullptr;      // in front of the operator (not a dock tab behind another)
    OnScreenWatcher* m_videoOnScreen = nullptr; // the video's, once it is in a panel of its own
    MissionTakeover* m_takeover = nullptr;
};

} // namespace ocu
