#include "widgets/jaus/TeleopPanel.h"

#include "models/CommandGate.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausSubsystemModel.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/video/VideoPlayer.h"
#include "widgets/CommandPermissionHint.h"
#include "widgets/HoldToConfirmButton.h"
#include "widgets/OnScreenWatcher.h"
#include "widgets/jaus/IlluminationBar.h"
#include "widgets/jaus/MissionTakeover.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/teleop/JoystickMappingDialog.h"
#include "widgets/teleop/PanTiltController.h"
#include "widgets/teleop/SdlJoystickInput.h"
#include "widgets/teleop/TeleopController.h"
#include "widgets/teleop/VirtualStick.h"

#include <QApplication>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSlider>
#include <QVBoxLayout>

#include <cmath>

namespace ocu {

TeleopPanel::TeleopPanel(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection,
                         InputDevice* device, QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_gate(gate), m_selection(selection),
      m_controller(new TeleopController(this)), m_stick(new VirtualStick(this)),
      m_axes(new AxisDisplay(this)), m_title(new QLabel(this)), m_state(new QLabel(this)),
      m_live(new QLabel(this)), m_device(new QLabel(this)), m_mode(new QComboBox(this)),
      m_limit(new QSlider(Qt::Horizontal, this)), m_limitLabel(new QLabel(this)),
      m_estop(new QPushButton(tr("E-STOP"), this)),
      m_clear(new HoldToConfirmButton(tr("Hold to clear emergency"), this)), m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("teleop-panel"));
    setFocusPolicy(Qt::StrongFocus);
    m_controller->setRateHz(bridge->identity().driveRateHz);
    buildVideoAndLabels();
    buildStopButtons();
    connect(m_clear, &HoldToConfirmButton::confirmed, this, [this] {
        // The hold is the deliberate confirmation: it buys the gate's one-time token, and the gate audits.
        if (m_subsystem && m_gate) {
            const QString id = JausVehicleBridge::machineId(m_subsystem);
            m_gate->clearStop(id, m_gate->requestClearToken(id), QStringLiteral("teleop"));
        }
    });

    buildLayout(buildInputs());
    connectStickAndVideo();
    connect(m_controller, &TeleopController::command, this, &TeleopPanel::onCommand);
    connect(m_controller, &TeleopController::command, m_axes, &AxisDisplay::setMapped);
    // Zero on release, focus loss, joystick loss...: the controller sends the zero demand at once, then the
    // session ends through the gate (the stack sends zeros several times).
    connect(m_controller, &TeleopController::stopped, this, [this](const QString& reason) {
        if (m_session != Session::Closed)
            endSession(reason);
    });
    // Out of the operator's sight (a dock tab behind another gets no hide event): nothing drives. The
    // full-screen video window keeps the keys and the stream.
    m_onScreen = new OnScreenWatcher(this);
    connect(m_onScreen, &OnScreenWatcher::changed, this, [this](bool on) {
        if (!on && !m_video->fullScreenWindow())
            releaseAll(tr("teleop panel hidden"));
    });
    connect(bridge, &JausVehicleBridge::driveProblem, this,
            [this](quint16 subsystem, const QString& text, bool failing) {
                if (subsystem != m_subsystem)
                    return;
                if (failing)
                    showDriveProblem(text);
                else
                    showDriveProblem({});
            });
    connectInputDevice(device);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, [this](const JausVehicle& s) {
        // Nothing selected yet: show the first vehicle heard of (its video and state; driving still needs
        // control of it), rather than an empty panel.
        if (!m_subsystem && m_autoSelect)
            setVehicle(s.subsystem);
        if (s.subsystem == m_subsystem)
            refresh();
    });
    if (selection)
        connect(selection, &FleetSelection::currentMachineChanged, this, [this](const QString& id) {
            if (auto sub = JausVehicleBridge::subsystemOf(id))
                setVehicle(*sub);
        });
    // Window focus loss (another application, a dialog): stop driving at once.
    connect(qApp, &QApplication::applicationStateChanged, this, [this](Qt::ApplicationState st) {
        if (st != Qt::ApplicationActive)
            releaseAll(tr("window lost focus"));
    });
    m_stick->installEventFilter(this);
    m_takeover = new MissionTakeover(bridge, gate, this);
    if (gate)
        connect(gate, &CommandGate::permissionsChanged, this, &TeleopPanel::refresh);
    refresh();
}

TeleopPanel::~TeleopPanel() {
    // Closing the window hides the video pane after this object is gone: no more calls into it from there.
    if (m_video)
        disconnect(m_video, nullptr, this, nullptr);
    if (!m_subsystem || m_session == Session::Closed)
        return;
    if (m_gate) // no handler: this panel is going away
        m_gate->command(DriveStop{JausVehicleBridge::machineId(m_subsystem), tr("teleop panel closed")},
                        QStringLiteral("teleop"));
    else
        m_bridge->stopDriving(m_subsystem);
}

TeleopVideoPane* TeleopPanel::video() const {
    return m_video;
}

TeleopVideoPane* TeleopPanel::detachVideo() {
    if (m_videoOnScreen)
        return m_video;
    layout()->removeWidget(m_video);
    m_video->setParent(nullptr);
    static_cast<QBoxLayout*>(layout())->addStretch(1); // the controls together at the top
    m_videoOnScreen = new OnScreenWatcher(m_video);
    connect(m_videoOnScreen, &OnScreenWatcher::changed, this, [this](bool on) {
        if (!on && !m_video->fullScreenWindow())
            releaseAll(tr("teleop video hidden"));
    });
    return m_video;
}

bool TeleopPanel::inSight() const {
    if (m_video->fullScreenWindow())
        return true;
    return m_onScreen->onScreen() && (!m_videoOnScreen || m_videoOnScreen->onScreen());
}

void TeleopPanel::releaseAll(const QString& reason) {
    m_controller->releaseAll(reason);
    m_panTilt->releaseAll(reason);
}

void TeleopPanel::setConfiguredCameras(quint16 subsystem, const QVector<JausVideoEndpoint>& cameras) {
    m_configuredCameras[subsystem] = cameras;
    for (JausVideoEndpoint& c : m_configuredCameras[subsystem])
        c.configured = true;
    refresh();
}

QString TeleopPanel::videoHold() const {
    return m_video->watchdog().allowsDriving() ? QString() : m_video->watchdog().reason();
}

void TeleopPanel::onWatchdog() {
    if (!m_video->watchdog().allowsDriving() && m_subsystem) {
        // The drive stream goes to zero at once; the session ends below (refresh) with the reason.
        const QString why = m_video->watchdog().reason();
        m_controller->releaseAll(why);
    }
    refresh();
}

void TeleopPanel::onPanTilt(double pan, double tilt) {
    const auto cam = m_video->currentCamera();
    if (!m_subsystem || !cam || !cam->panTilt)
        return;
    emit panTiltCommand(m_subsystem, cam->sensorId, pan, tilt);
    // Full deflection (or the hat / keys at their fraction of it) is kPanTiltFullRate rad/s; the unit
    // clamps to its own limit.
    const CommandResult r =
        m_bridge->panTilt(m_subsystem, cam->sensorId, pan * kPanTiltFullRate, tilt * kPanTiltFullRate);
    if (!r.ok && (pan != 0 || tilt != 0))
        showDriveProblem(tr("Camera pan-tilt refused: %1").arg(r.message));
}

void TeleopPanel::setVehicle(std::uint16_t subsystem) {
    m_autoSelect = false;
    if (subsystem == m_subsystem)
        return;
    releaseAll(tr("vehicle changed"));
    m_takeover->cancel();
    if (m_subsystem && m_session != Session::Closed)
        endSession(tr("vehicle changed"));
    m_subsystem = subsystem;
    // Another vehicle: its video watchdog starts afresh (waits for that vehicle's first frame).
    m_video->watchdog().reset();
    showDriveProblem({});
    refresh();
}

QString TeleopPanel::driveProblem() const {
    return m_problem->isVisible() || !m_problem->text().isEmpty() ? m_problem->text() : QString();
}

void TeleopPanel::showDriveProblem(const QString& text) {
    m_problem->setText(text);
    m_problem->setVisible(!text.isEmpty());
}

void TeleopPanel::startSession() {
    if (!m_gate) {
        showDriveProblem(tr("no command gate: driving is not possible"));
        return;
    }
    if (m_takeover->runsMission(m_subsystem)) {
        takeOverMission();
        return;
    }
    m_session = Session::Opening;
    const quint16 sub = m_subsystem;
    QPointer<TeleopPanel> self(this);
    m_gate->command(DriveStart{JausVehicleBridge::machineId(sub), tr("teleop input")},
                    QStringLiteral("teleop"), [self, sub](const CommandResult& r) {
                        if (!self || self->m_subsystem != sub || self->m_session != Session::Opening)
                            return; // ended (and closed through the gate) before the start's result came
                        if (!r.ok) {
                            self->m_session = Session::Closed;
                            self->m_waitForRelease = true;
                            self->showDriveProblem(tr("Drive session NOT started: %1")
                                                       .arg(r.notSent().isEmpty()
                                                                ? r.message
                                                                : r.notSent().join(QStringLiteral("; "))));
                            return;
                        }
                        self->m_session = Session::Open;
                        self->showDriveProblem({});
                        self->onCommand(self->m_controller->demand()); // the demand held meanwhile
                    });
}

void TeleopPanel::takeOverMission() {
    const quint16 sub = m_subsystem;
    QPointer<TeleopPanel> self(this);
    showDriveProblem(tr("The vehicle runs a mission: confirm to pause it before driving"));
    m_takeover->pauseThen(
        sub,
        [self, sub] {
            if (!self || self->m_subsystem != sub)
                return;
            self->showDriveProblem(tr("Mission paused: driving by hand (Resume in the mission panel)"));
            if (!self->m_controller->demand().isZero())
                self->startSession(); // the stick is still held
        },
        [self, sub](const QString& why) {
            if (!self || self->m_subsystem != sub)
                return;
            self->m_waitForRelease = true;
            self->showDriveProblem(tr("Drive session NOT started: %1").arg(why));
        });
}

void TeleopPanel::endSession(const QString& reason) {
    m_session = Session::Closed;
    if (!m_gate) {
        m_bridge->stopDriving(m_subsystem);
        return;
    }
    QPointer<TeleopPanel> self(this);
    const quint16 sub = m_subsystem;
    m_gate->command(DriveStop{JausVehicleBridge::machineId(sub), reason}, QStringLiteral("teleop"),
                    [self, sub](const CommandResult& r) {
                        if (self && !r.ok && self->m_subsystem == sub)
                            self->showDriveProblem(tr("Drive session end: zero commands NOT sent: %1")
                                                       .arg(r.notSent().join(QStringLiteral("; "))));
                    });
}

bool TeleopPanel::velocityMode() const {
    return m_mode->currentData().toString() == QLatin1String("velocity");
}

JausDrive TeleopPanel::toDriveCommand(DriveAxes a) const {
    JausDrive c;
    if (velocityMode()) {
        c.mode = JausDrive::Mode::Velocity;
        double fwd = 1.0, rev = 1.0, rot = 1.0; // conservative defaults until the platform reports its limits
        if (auto s = m_bridge->subsystem(m_subsystem); s && s->platform) {
            fwd = s->platform->maxForwardSpeed.value_or(fwd);
            rev = s->platform->maxReverseSpeed.value_or(rev);
            rot = s->platform->maxRotationalSpeed.value_or(rot);
        }
        c.linear = a.forward >= 0 ? a.forward * fwd : a.forward * rev;
        c.angular = a.turn * rot;
    } else {
        c.mode = JausDrive::Mode::Wrench;
        c.linear = a.forward * 100.0;
        c.angular = a.turn * 100.0;
    }
    return c;
}

void TeleopPanel::onCommand(DriveAxes axes) {
    if (!m_subsystem)
        return;
    switch (m_session) {
    case Session::Closed:
        // Released means the input itself: a zero sent for a focus change (a question opening over the panel)
        // while the joystick is still deflected is not a release.
        if (axes.isZero()) {
            if (m_controller->demand().isZero())
                m_waitForRelease = false;
        } else if (!m_waitForRelease && !m_takeover->pending() && inSight())
            startSession(); // the demand follows once the gate says the session is open
        return;
    case Session::Opening:
        return; // the controller holds the demand; it goes out when the session is open
    case Session::Open:
        break;
    }
    // The stream itself: one message per period, no audit line each; a refusal ends the session loudly.
    const auto r = m_bridge->drive(m_subsystem, toDriveCommand(axes));
    if (!r.ok) {
        showDriveProblem(tr("Driving stopped: %1").arg(r.message));
        m_waitForRelease = true;
        endSession(r.message);
    }
}

void TeleopPanel::emergencyStop() {
    releaseAll(tr("emergency stop"));
    if (m_subsystem && m_gate)
        m_gate->stopMachine(JausVehicleBridge::machineId(m_subsystem), QStringLiteral("teleop"));
}

void TeleopPanel::openJoystickMapping() {
    if (!m_inputDevice || !m_inputDevice->supportsMapping())
        return;
    // Mapping means moving the stick: the device is detached from the controller while the dialog is open.
    m_controller->setDevice(nullptr);
    m_controller->releaseAll(tr("joystick mapping"));
    auto* dlg = new JoystickMappingDialog(m_inputDevice, this);
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    connect(dlg, &QDialog::finished, this, [this, dlg](int result) {
        if (result == QDialog::Accepted) {
            m_inputDevice->setMapping(dlg->mapping());
            saveJoystickMapping(m_inputDevice->name(), dlg->mapping());
        }
        m_controller->setDevice(m_inputDevice);
        refresh();
    });
    dlg->open();
}

void TeleopPanel::refresh() {
    InputDevice* dev = m_inputDevice;
    m_device->setText(dev ? (dev->isConnected() ? dev->name() : tr("none connected")) : tr("none"));
    m_mapButton->setEnabled(dev && dev->supportsMapping());
    auto s = m_subsystem ? m_bridge->subsystem(m_subsystem) : std::nullopt;
    if (!s) {
        m_title->setText(tr("No JAUS vehicle selected"));
        m_state->setText(
            tr("Select a vehicle in the fleet list or the JAUS control panel, then take control."));
        m_live->clear();
        m_video->setCameras({});
        m_video->setOverlay({});
        m_videoHold->hide();
        m_panTilt->setEnabled(false);
        m_controller->setEnabled(false);
        m_estop->setEnabled(false);
        m_clear->setEnabled(false);
        permittedShowingWhy(m_clear, m_gate, QStringLiteral("clear_stop"));
        return;
    }
    m_title->setText(tr("%1 [%2]").arg(s->callSign).arg(s->subsystem));
    const JausConsoleIdentity me = m_bridge->identity();
    const bool may = me.mayControl;
    const bool ours = s->controlledByUs;
    const bool up = s->link == JausLink::Up;
    QVector<JausVideoEndpoint> cameras = s->videoEndpoints;
    for (const JausVideoEndpoint& c : m_configuredCameras.value(s->subsystem)) {
        const bool announced = std::any_of(cameras.begin(), cameras.end(),
                                           [&](const JausVideoEndpoint& a) { return a.url == c.url; });
        if (!announced)
            cameras << c;
    }
    m_video->setCameras(cameras);
    m_video->checkWatchdog();
    const bool videoOk = m_video->watchdog().allowsDriving();
    const QString hold = videoOk ? QString() : m_video->watchdog().reason();
    m_videoHold->setText(hold);
    m_videoHold->setVisible(!hold.isEmpty());
    const bool canDrive = may && ours && up && !s->emergency && videoOk;
    const auto cam = m_video->currentCamera();
    m_panTilt->setEnabled(may && ours && up && !s->emergency && cam && cam->panTilt);
    m_stickCamera->setEnabled(cam && cam->panTilt);
    if (!canDrive && m_session != Session::Closed) {
        // The vehicle's own state ends the session: say why, loudly, and end it through the gate. The
        // vehicle's state first (a lost link or an emergency also loses the video, and is the stronger
        // reason), the video watchdog's reason when the vehicle is fine.
        const QString why =
            !up ? tr("the link to %1 is %2").arg(s->callSign, JausSubsystemModel::linkText(s->link))
            : s->emergency ? tr("%1 is in EMERGENCY").arg(s->callSign)
            : !ours        ? tr("this console no longer controls %1").arg(s->callSign)
            : !videoOk     ? hold
                           : tr("driving is not allowed");
        showDriveProblem(tr("Driving stopped: %1").arg(why));
        m_waitForRelease = true;
        endSession(why);
    }
    m_controller->setEnabled(canDrive);
    m_estop->setEnabled(me.mayStop); // any role may stop (the JAUS stop rule)
    // Only roles with command rights may clear (the JAUS rule and the gate's table, whose role is named).
    m_clear->setEnabled(permittedShowingWhy(m_clear, m_gate, QStringLiteral("clear_stop")) &&
                        me.mayClearStop && s->emergency);
    QStringList state;
    if (!may)
        state << tr("MONITOR role: driving disabled");
    else if (!ours)
        state << tr("not controlled by this console: take control first");
    else
        state << tr("controlled by this console");
    if (s->emergency)
        state << tr("EMERGENCY — hold the clear button to release");
    if (!up)
        state << tr("link %1").arg(JausSubsystemModel::linkText(s->link));
    if (s->management)
        state << tr("state %1").arg(s->managementText);
    state << (s->driving ? tr("drive session open")
                         : tr("drive session closed (vehicle stops after its 1 s drive timeout)"));
    m_state->setText(state.join(QStringLiteral(" · ")));
    m_state->setStyleSheet(s->emergency ? QStringLiteral("color:#c81e1e; font-weight:bold;") : QString());
    QStringList live;
    if (s->velocity && s->velocity->vx)
        live << tr("speed %1 m/s").arg(*s->velocity->vx, 0, 'f', 2);
    if (s->globalPose && s->globalPose->yaw)
        live << tr("heading %1°").arg(std::fmod(*s->globalPose->yaw * 180 / M_PI + 360, 360), 0, 'f', 0);
    if (s->globalPose && s->globalPose->lat && s->globalPose->lon)
        live << tr("pose %1, %2").arg(*s->globalPose->lat, 0, 'f', 6).arg(*s->globalPose->lon, 0, 'f', 6);
    if (s->localPose && s->localPose->x && s->localPose->y)
        live << tr("local %1 / %2 m").arg(*s->localPose->x, 0, 'f', 1).arg(*s->localPose->y, 0, 'f', 1);
    m_live->setText(live.join(QStringLiteral(" · ")));
    QStringList overlay;
    overlay << QStringLiteral("%1 [%2]").arg(s->callSign).arg(s->subsystem);
    if (s->velocity && s->velocity->vx)
        overlay << tr("speed %1 m/s").arg(*s->velocity->vx, 0, 'f', 2);
    if (s->globalPose && s->globalPose->yaw)
        overlay << tr("heading %1°").arg(std::fmod(*s->globalPose->yaw * 180 / M_PI + 360, 360), 0, 'f', 0);
    overlay << (s->emergency ? tr("EMERGENCY")
                : !videoOk   ? tr("driving held (video)")
                : s->driving ? tr("drive session open")
                : canDrive   ? tr("ready to drive")
                             : tr("not driving"));
    m_video->setOverlay(overlay);
    double maxFwd = 1.0;
    if (s->platform && s->platform->maxForwardSpeed)
        maxFwd = *s->platform->maxForwardSpeed;
    m_limitLabel->setText(
        velocityMode()
            ? tr("%1 % · %2 m/s").arg(m_limit->value()).arg(maxFwd * m_limit->value() / 100.0, 0, 'f', 2)
            : tr("%1 %").arg(m_limit->value()));
}

void TeleopPanel::keyPressEvent(QKeyEvent* e) {
    if (!m_controller->handleKey(e->key(), true, e->isAutoRepeat()) &&
        !m_panTilt->handleKey(e->key(), true, e->isAutoRepeat()))
        QWidget::keyPressEvent(e);
}

void TeleopPanel::keyReleaseEvent(QKeyEvent* e) {
    if (!m_controller->handleKey(e->key(), false, e->isAutoRepeat()) &&
        !m_panTilt->handleKey(e->key(), false, e->isAutoRepeat()))
        QWidget::keyReleaseEvent(e);
}

void TeleopPanel::focusOutEvent(QFocusEvent* e) {
    // The full-screen video window takes the keys over (they come back through eventFilter).
    if (!m_video->fullScreenWindow())
        releaseAll(tr("teleop panel lost keyboard focus"));
    QWidget::focusOutEvent(e);
}

void TeleopPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    // In a scroll area (the main window's docks) the panel is never narrower than it needs: the width it
    // really has is the viewport's.
    QWidget* source = parentWidget() ? parentWidget() : this;
    if (source != m_widthSource) {
        if (m_widthSource && m_widthSource != this)
            m_widthSource->removeEventFilter(this);
        m_widthSource = source;
        if (source != this)
            source->installEventFilter(this);
    }
    fitToWidth();
}

void TeleopPanel::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    if (m_widthSource == this)
        fitToWidth();
}

bool TeleopPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_widthSource && watched != this && event->type() == QEvent::Resize)
        fitToWidth();
    // Keys typed while the stick (or the full-screen video window) has focus drive too.
    const bool fullScreen = watched && watched == m_video->fullScreenWindow();
    if ((watched == m_stick || fullScreen) &&
        (event->type() == QEvent::KeyPress || event->type() == QEvent::KeyRelease)) {
        auto* k = static_cast<QKeyEvent*>(event);
        const bool press = event->type() == QEvent::KeyPress;
        if (fullScreen && press && k->key() == Qt::Key_Space) {
            emergencyStop();
            return true;
        }
        if (m_controller->handleKey(k->key(), press, k->isAutoRepeat()) ||
            m_panTilt->handleKey(k->key(), press, k->isAutoRepeat()))
            return true;
    }
    // Leaving the full-screen window (Esc, closed, another application): stop as on focus loss.
    if (fullScreen && (event->type() == QEvent::Close || event->type() == QEvent::WindowDeactivate))
        releaseAll(tr("video window closed or lost focus"));
    return QWidget::eventFilter(watched, event);
}

} // namespace ocu
