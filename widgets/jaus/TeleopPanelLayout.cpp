// TeleopPanel's widgets and their layout: the video and status lines, the stop buttons, the stick and drive
// settings, and how they rearrange to the panel's width. The drive session's logic is in TeleopPanel.cpp.
#include "widgets/jaus/TeleopPanel.h"

#include "models/jaus/JausVehicleBridge.h"
#include "widgets/HoldToConfirmButton.h"
#include "widgets/jaus/IlluminationBar.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/teleop/JoystickMappingDialog.h"
#include "widgets/teleop/PanTiltController.h"
#include "widgets/teleop/SdlJoystickInput.h"
#include "widgets/teleop/TeleopController.h"
#include "widgets/teleop/VirtualStick.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSlider>
#include <QVBoxLayout>

namespace ocu {

// The video pane, the camera pan-tilt and the status lines above it.
void TeleopPanel::buildVideoAndLabels() {
    m_video = new TeleopVideoPane(this);
    m_video->setKeyFilter(this);
    m_panTilt = new PanTiltController(this);
    m_stickCamera = new QPushButton(tr("Stick: camera"), this);
    m_stickCamera->setObjectName(QStringLiteral("button-stick-camera"));
    m_stickCamera->setCheckable(true);
    m_stickCamera->setToolTip(tr("The on-screen stick pans and tilts the camera instead of driving"));
    m_videoHold = new QLabel(this);
    m_videoHold->setObjectName(QStringLiteral("label-video-watchdog"));
    m_videoHold->setWordWrap(true);
    m_videoHold->setStyleSheet(QStringLiteral("color:#c81e1e; font-weight:bold;"));
    m_videoHold->hide();

    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    m_title->setFont(big);
    // Long state lines wrap rather than widen the panel beyond its dock (the video needs the width).
    m_state->setWordWrap(true);
    m_live->setWordWrap(true);
}

// E-STOP (button, Space, Esc) and the hold-to-clear button.
void TeleopPanel::buildStopButtons() {
    m_estop->setObjectName(QStringLiteral("button-estop"));
    m_estop->setMinimumHeight(64);
    m_estop->setStyleSheet(QStringLiteral("QPushButton { background:#c81e1e; color:white; font-size:22px;"
                                          " font-weight:bold; border:3px solid #6d0a0a; border-radius:8px; }"
                                          "QPushButton:pressed { background:#8e1010; }"
                                          "QPushButton:focus { border:3px solid #ffd400; }"));
    m_estop->setToolTip(tr("Emergency stop of this vehicle (Space or Esc). Never asks for confirmation."));
    connect(m_estop, &QPushButton::clicked, this, &TeleopPanel::emergencyStop);
    // With or without the dead-man key (Shift) held: the stop must never depend on modifiers.
    for (QKeySequence k :
         {QKeySequence(Qt::Key_Space), QKeySequence(Qt::Key_Escape), QKeySequence(Qt::SHIFT | Qt::Key_Space),
          QKeySequence(Qt::SHIFT | Qt::Key_Escape)}) {
        auto* sc = new QShortcut(k, this);
        sc->setContext(Qt::WidgetWithChildrenShortcut);
        connect(sc, &QShortcut::activated, this, &TeleopPanel::emergencyStop);
    }
    m_clear->setObjectName(QStringLiteral("button-clear-emergency"));
    m_clear->setHoldDurationMs(1500);
}

// The on-screen stick beside the drive settings (mode, speed limit, joystick), the axes and the key hint.
QBoxLayout* TeleopPanel::buildInputs() {
    m_mode->setObjectName(QStringLiteral("combo-drive-mode"));
    m_mode->addItem(tr("Velocity (m/s, rad/s)"), QStringLiteral("velocity"));
    m_mode->addItem(tr("Wrench effort (%)"), QStringLiteral("effort"));
    m_limit->setRange(5, 100);
    m_limit->setValue(50);
    m_limit->setObjectName(QStringLiteral("slider-speed-limit"));
    connect(m_limit, &QSlider::valueChanged, this, [this](int v) {
        m_controller->setSpeedLimit(v / 100.0);
        refresh();
    });
    m_controller->setSpeedLimit(0.5);

    auto* settings = new QFormLayout;
    settings->addRow(tr("Mode"), m_mode);
    auto* limitRow = new QHBoxLayout;
    limitRow->addWidget(m_limit, 1);
    limitRow->addWidget(m_limitLabel);
    settings->addRow(tr("Speed limit"), limitRow);
    m_mapButton = new QPushButton(tr("Mapping…"), this);
    m_mapButton->setObjectName(QStringLiteral("button-joystick-mapping"));
    m_mapButton->setToolTip(tr("Choose the joystick axes, their direction and the dead zone"));
    connect(m_mapButton, &QPushButton::clicked, this, &TeleopPanel::openJoystickMapping);
    auto* deviceRow = new QHBoxLayout;
    deviceRow->addWidget(m_device, 1);
    deviceRow->addWidget(m_mapButton);
    settings->addRow(tr("Joystick"), deviceRow);

    // Labels wrap above their fields when the panel is narrow.
    settings->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto* inputs = new QBoxLayout(QBoxLayout::LeftToRight);
    m_inputs = inputs;
    // The settings get two thirds of the width (their labels then stay beside their fields, a row each: a
    // short dock, the laptop's side column, has no height to spare).
    inputs->addWidget(m_stick, 1);
    auto* right = new QVBoxLayout;
    m_inputsRight = right;
    right->addLayout(settings);
    right->addWidget(m_axes);
    right->addWidget(m_stickCamera);
    auto* keysHint = new QLabel(tr("Keyboard: hold Shift (dead-man) and use W/A/S/D or the arrows. Camera: "
                                   "J/L pan, I/K tilt (or the joystick hat)."),
                                this);
    keysHint->setWordWrap(true);
    m_keysHint = keysHint;
    right->addStretch(1);
    inputs->addLayout(right, 2);
    return inputs;
}

void TeleopPanel::buildLayout(QBoxLayout* inputs) {
    auto* l = new QVBoxLayout(this);
    l->addWidget(m_title);
    l->addWidget(m_state);
    l->addWidget(m_live);
    m_problem->setObjectName(QStringLiteral("label-drive-problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color:#c81e1e; font-weight:bold;"));
    m_problem->hide();
    l->addWidget(m_problem);
    // The stop above the video: below it, a large video (the UGV workspace) pushed it out of a short dock.
    auto* stops = new QBoxLayout(QBoxLayout::LeftToRight);
    m_stops = stops;
    stops->addWidget(m_estop, 2);
    stops->addWidget(m_clear, 1);
    l->addLayout(stops);
    l->addWidget(m_videoHold);
    l->addWidget(new IlluminationBar(
        m_bridge, m_gate, [this] { return m_subsystem; }, this));
    l->addWidget(m_video, 3);
    l->addLayout(inputs);     // at its size: every pixel of height more goes to the video
    l->addWidget(m_keysHint); // the whole width: fewer lines than beside the stick
}

// The on-screen stick drives or moves the camera; the video pane reports its watchdog and camera changes.
void TeleopPanel::connectStickAndVideo() {
    connect(m_stick, &VirtualStick::axesChanged, this, [this](DriveAxes a) {
        if (m_stickCamera->isChecked())
            m_panTilt->setStick(a);
        else
            m_controller->setStick(a);
    });
    connect(m_stickCamera, &QPushButton::toggled, this, [this] {
        m_controller->setStick({});
        m_panTilt->setStick({});
    });
    connect(m_panTilt, &PanTiltController::command, this, &TeleopPanel::onPanTilt);
    connect(m_video, &TeleopVideoPane::watchdogChanged, this, &TeleopPanel::onWatchdog);
    connect(m_video, &TeleopVideoPane::resumed, this, [this] {
        showDriveProblem({});
        refresh();
    });
    connect(m_video, &TeleopVideoPane::cameraChanged, this, [this] {
        m_panTilt->releaseAll(tr("camera changed"));
        refresh();
    });
}

void TeleopPanel::connectInputDevice(InputDevice* device) {
    m_inputDevice = device;
    if (device) {
        m_controller->setDevice(device);
        m_panTilt->setDevice(device);
        // The operator's saved mapping for this device wins over the site configuration's.
        auto applySaved = [device] {
            if (device->supportsMapping() && device->isConnected())
                if (auto m = loadSavedJoystickMapping(device->name()))
                    device->setMapping(*m);
        };
        applySaved();
        connect(device, &InputDevice::connectedChanged, this, [this, applySaved](bool connected) {
            if (connected)
                applySaved();
            refresh();
        });
        connect(device, &InputDevice::rawAxesChanged, m_axes, &AxisDisplay::setAxes);
    }
}

void TeleopPanel::fitToWidth() {
    if (!m_inputs || !m_widthSource)
        return;
    const QMargins m = layout()->contentsMargins();
    const int available = m_widthSource->width() - m.left() - m.right();
    const int sideBySide =
        m_stick->minimumSizeHint().width() + m_inputs->spacing() + m_inputsRight->minimumSize().width();
    const bool narrow = available < sideBySide;
    const auto dir = narrow ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight;
    if (m_inputs->direction() != dir)
        m_inputs->setDirection(dir);
    if (m_stops->direction() != dir)
        m_stops->setDirection(dir);
}

} // namespace ocu
