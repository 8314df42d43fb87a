#include "widgets/jaus/PlatformServicesWidget.h"

#include "models/CommandGate.h"
#include "models/jaus/JausVehicleBridge.h"
#include "widgets/CommandPermissionHint.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardItemModel>

namespace ocu {

PlatformServicesWidget::PlatformServicesWidget(JausVehicleBridge* bridge, CommandGate* gate, QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_gate(gate), m_mode(new QLabel(this)), m_state(new QLabel(this)),
      m_odometer(new QLabel(this)), m_commsLost(new QLabel(this)), m_modeChoice(new QComboBox(this)),
      m_stateChoice(new QComboBox(this)), m_setMode(new QPushButton(tr("Set mode"), this)),
      m_setState(new QPushButton(tr("Set state…"), this)),
      m_emergency(new QPushButton(tr("Emergency state"), this)),
      m_resetTrip(new QPushButton(tr("Reset trip"), this)) {
    setObjectName(QStringLiteral("platform-services"));
    m_confirm = [this](const QString& question) {
        return QMessageBox::question(this, tr("Platform state"), question) == QMessageBox::Yes;
    };
    for (JausPlatformMode m :
         {JausPlatformMode::Standard, JausPlatformMode::Training, JausPlatformMode::Maintenance})
        m_modeChoice->addItem(JausPlatformText::modeName(int(m)), int(m));
    // The emergency state has its own button; every other state is chosen here and confirmed.
    for (JausPlatformState s :
         {JausPlatformState::Operational, JausPlatformState::Initialize, JausPlatformState::Shutdown,
          JausPlatformState::SystemAbort, JausPlatformState::RenderUseless})
        m_stateChoice->addItem(JausPlatformText::stateName(int(s)), int(s));
    m_modeChoice->setObjectName(QStringLiteral("platform-mode-choice"));
    m_stateChoice->setObjectName(QStringLiteral("platform-state-choice"));
    m_setMode->setObjectName(QStringLiteral("platform-set-mode"));
    m_setState->setObjectName(QStringLiteral("platform-set-state"));
    m_emergency->setObjectName(QStringLiteral("platform-emergency"));
    m_resetTrip->setObjectName(QStringLiteral("platform-reset-trip"));
    m_emergency->setToolTip(tr("Put the whole platform in its emergency state: every component halts and "
                               "refuses commands until it is set back to operational (AEP-4818 §6.2.6)"));
    m_commsLost->setWordWrap(true);
    auto* g = new QGridLayout(this);
    g->setContentsMargins(4, 2, 4, 2);
    g->setVerticalSpacing(2);
    g->addWidget(new QLabel(tr("Platform mode:"), this), 0, 0);
    g->addWidget(m_mode, 0, 1);
    g->addWidget(m_modeChoice, 0, 2);
    g->addWidget(m_setMode, 0, 3);
    g->addWidget(new QLabel(tr("Platform state:"), this), 1, 0);
    g->addWidget(m_state, 1, 1);
    g->addWidget(m_stateChoice, 1, 2);
    g->addWidget(m_setState, 1, 3);
    g->addWidget(m_emergency, 1, 4);
    g->addWidget(new QLabel(tr("Odometer:"), this), 2, 0);
    g->addWidget(m_odometer, 2, 1, 1, 3);
    g->addWidget(m_resetTrip, 2, 4);
    g->addWidget(m_commsLost, 3, 0, 1, 5);
    g->setColumnStretch(1, 1);

    connect(m_setMode, &QPushButton::clicked, this, [this] {
        send(SetPlatformMode{JausVehicleBridge::machineId(m_subsystem), m_modeChoice->currentData().toInt()});
    });
    connect(m_setState, &QPushButton::clicked, this,
            [this] { commandState(m_stateChoice->currentData().toInt()); });
    connect(m_emergency, &QPushButton::clicked, this,
            [this] { commandState(int(JausPlatformState::Emergency)); });
    connect(m_resetTrip, &QPushButton::clicked, this, [this] {
        send(Odometry{JausVehicleBridge::machineId(m_subsystem), true});
    });
    if (gate) // another operator or role, or the lock: what may be sent changes
        connect(gate, &CommandGate::permissionsChanged, this, &PlatformServicesWidget::refresh);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, [this](const JausVehicle& v) {
        if (v.subsystem == m_subsystem)
            refresh();
    });
    refresh();
}

void PlatformServicesWidget::setVehicle(quint16 subsystem) {
    m_subsystem = subsystem;
    refresh();
}

void PlatformServicesWidget::commandState(int state) {
    const QString id = JausVehicleBridge::machineId(m_subsystem);
    // The emergency state stops, so it never waits for a question; leaving it or shutting down does.
    if (state != int(JausPlatformState::Emergency)) {
        const auto v = m_bridge->subsystem(m_subsystem);
        const QString name = v ? v->callSign : id;
        if (!m_confirm(
                tr("Put %1 in the platform state \"%2\"?").arg(name, JausPlatformText::stateName(state))))
            return;
    }
    send(SetPlatformState{id, state});
}

void PlatformServicesWidget::send(const OperatorCommand& command) {
    if (m_gate && m_subsystem)
        m_gate->command(command, QStringLiteral("gui"));
}

void PlatformServicesWidget::refresh() {
    const auto v = m_subsystem ? m_bridge->subsystem(m_subsystem) : std::nullopt;
    setVisible(v.has_value());
    if (!v)
        return;
    const JausPlatformServices& p = v->platformServices;
    const bool may = m_bridge->mayCommand() && v->link != JausLink::Down;
    auto reported = [this](const JausOfferedService& s, const std::optional<int>& value, auto name) {
        if (!s.offered)
            return tr("not offered");
        return value ? name(*value) : tr("not reported yet");
    };
    m_mode->setText(reported(p.modeService, p.mode, [](int m) { return JausPlatformText::modeName(m); }));
    QString state = reported(p.stateService, p.state, [](int s) { return JausPlatformText::stateName(s); });
    if (!p.stateRefusal.isEmpty())
        state += tr(" (last request refused: %1)").arg(p.stateRefusal);
    m_state->setText(state);
    m_state->setStyleSheet(p.emergencyState() ? QStringLiteral("color:#c81e1e; font-weight:bold;")
                                              : QString());
    // A mode the vehicle does not list is not offered for choosing.
    if (auto* model = qobject_cast<QStandardItemModel*>(m_modeChoice->model()))
        for (int i = 0; i < model->rowCount(); ++i) {
            const int mode = m_modeChoice->itemData(i).toInt();
            model->item(i)->setEnabled(p.supportedModes.isEmpty() || p.supportedModes.contains(mode));
        }
    const bool mayMode = permittedShowingWhy(m_setMode, m_gate, QStringLiteral("platform_mode"));
    const bool mayState = permittedShowingWhy(m_setState, m_gate, QStringLiteral("platform_state"));
    permittedShowingWhy(m_emergency, m_gate, QStringLiteral("platform_state"));
    m_modeChoice->setEnabled(may && mayMode && p.modeService.offered);
    m_setMode->setEnabled(may && mayMode && p.modeService.offered);
    m_stateChoice->setEnabled(may && mayState && p.stateService.offered);
    m_setState->setEnabled(may && mayState && p.stateService.offered);
    m_emergency->setEnabled(may && mayState && p.stateService.offered && !p.emergencyState());
    if (!p.odometryService.offered)
        m_odometer->setText(tr("not offered"));
    else
        m_odometer->setText(tr("%1 · trip %2")
                                .arg(p.odometerM ? tr("%1 m").arg(*p.odometerM) : tr("not reported yet"),
                                     p.tripM ? tr("%1 m").arg(*p.tripM) : tr("not reported yet")));
    m_resetTrip->setEnabled(permittedShowingWhy(m_resetTrip, m_gate, QStringLiteral("odometry")) && may &&
                            p.odometryService.offered);
    m_commsLost->setText(
        p.commsLostService.offered
            ? tr("Comms-lost policy: offered (%1 %2); setting a policy waits for a published "
                 "message layout")
                  .arg(p.commsLostService.uri, p.commsLostService.versionText())
            : tr("Comms-lost policy: not offered by this vehicle"));
}

} // namespace ocu
