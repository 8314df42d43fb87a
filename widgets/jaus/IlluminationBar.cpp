#include "widgets/jaus/IlluminationBar.h"

#include "models/CommandGate.h"
#include "models/jaus/JausVehicleBridge.h"
#include "widgets/CommandPermissionHint.h"

#include <QGridLayout>
#include <QLabel>
#include <QToolButton>

#include <algorithm>

namespace ocu {

namespace {

// Short labels: the bar shares the teleop panel's width with nothing else.
QString shortLabel(JausLight l) {
    switch (l) {
    case JausLight::Headlights:
        return IlluminationBar::tr("Head");
    case JausLight::RunningLights:
        return IlluminationBar::tr("Running");
    case JausLight::LeftTurnSignal:
        return IlluminationBar::tr("◀ Turn");
    case JausLight::RightTurnSignal:
        return IlluminationBar::tr("Turn ▶");
    case JausLight::BrakeLights:
        return IlluminationBar::tr("Brake");
    case JausLight::IrSource:
        return IlluminationBar::tr("IR");
    }
    return {};
}

} // namespace

IlluminationBar::IlluminationBar(JausVehicleBridge* bridge, CommandGate* gate,
                                 std::function<quint16()> vehicle, QWidget* parent)
    : QWidget(parent), m_bridge(bridge), m_gate(gate), m_vehicle(std::move(vehicle)),
      m_label(new QLabel(this)) {
    setObjectName(QStringLiteral("illumination-bar"));
    // A light the vehicle reports on stands out (amber, like a lamp) in the day and the night palette.
    setStyleSheet(
        QStringLiteral("QToolButton:checked { background: #f2b01e; color: black; font-weight: bold; "
                       "border: 1px solid #8a6200; border-radius: 3px; padding: 2px 6px; }"
                       "QToolButton { padding: 2px 6px; }"));
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(3);
    m_label->setText(tr("Lights:"));
    m_grid->addWidget(m_label, 0, 0);
    for (JausLight l : kJausLights) {
        auto* b = new QToolButton(this);
        b->setObjectName(QStringLiteral("light-") + jausLightKey(l));
        b->setText(shortLabel(l));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::StrongFocus); // reachable by Tab, toggled by Space
        connect(b, &QToolButton::clicked, this, [this, l] { clicked(l); });
        m_toggles.append({l, b});
    }
    // A narrow dock (the teleop panel in a side column) wraps the toggles into more rows instead of
    // widening the panel.
    setMinimumWidth(m_label->sizeHint().width() + 3 + m_toggles.front().second->sizeHint().width() * 2);
    arrange();
    if (gate) // another operator or role, or the lock: what may be sent changes
        connect(gate, &CommandGate::permissionsChanged, this, &IlluminationBar::refresh);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, [this](const JausVehicle& v) {
        if (v.subsystem == m_vehicle())
            refresh();
    });
    refresh();
}

void IlluminationBar::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    arrange();
}

void IlluminationBar::arrange() {
    int widest = 0, oneRow = -m_grid->spacing();
    for (const auto& [l, b] : m_toggles) {
        widest = std::max(widest, b->sizeHint().width());
        oneRow += b->sizeHint().width() + m_grid->spacing();
    }
    const int room = width() - m_label->sizeHint().width() - m_grid->spacing();
    // One row when the toggles fit side by side at their own widths (each its own column); more rows are
    // columns of the widest toggle.
    const int perRow = oneRow <= room
                           ? int(m_toggles.size())
                           : std::clamp(room / (widest + m_grid->spacing()), 1, int(m_toggles.size()));
    if (perRow == m_perRow)
        return;
    m_perRow = perRow;
    for (int i = 0; i < m_toggles.size(); ++i)
        m_grid->addWidget(m_toggles[i].second, i / perRow, 1 + i % perRow);
    for (int c = 1; c <= int(m_toggles.size()); ++c)
        m_grid->setColumnStretch(c, 0);
    m_grid->setColumnStretch(perRow + 1, 1);
}

QToolButton* IlluminationBar::toggle(JausLight light) const {
    for (const auto& [l, b] : m_toggles)
        if (l == light)
            return b;
    return nullptr;
}

void IlluminationBar::refresh() {
    const quint16 sub = m_vehicle();
    const auto v = sub ? m_bridge->subsystem(sub) : std::nullopt;
    const JausPlatformServices p = v ? v->platformServices : JausPlatformServices{};
    const bool offered = p.illuminationService.offered;
    const bool may = m_bridge->mayCommand() && v && v->link != JausLink::Down;
    m_label->setText(offered || !v ? tr("Lights:") : tr("Lights: not offered by this vehicle"));
    for (const auto& [l, b] : m_toggles) {
        const QSignalBlocker block(b);
        b->setChecked(p.lightOn(l)); // as the vehicle reports it
        b->setVisible(offered || !v);
        const QString name = JausPlatformText::lightName(l);
        b->setToolTip(!p.hasLight(l) ? tr("%1: this vehicle has none").arg(name)
                      : !p.lights    ? tr("%1: not reported yet").arg(name)
                      : p.lightOn(l) ? tr("%1: on, as the vehicle reports (click to switch off)").arg(name)
                                     : tr("%1: off, as the vehicle reports (click to switch on)").arg(name));
        b->setEnabled(permittedShowingWhy(b, m_gate, QStringLiteral("lights")) && offered && may &&
                      p.hasLight(l));
    }
}

void IlluminationBar::clicked(JausLight light) {
    const quint16 sub = m_vehicle();
    const auto v = sub ? m_bridge->subsystem(sub) : std::nullopt;
    refresh(); // the toggle keeps showing the vehicle's report until the vehicle reports the change
    if (!v || !m_gate)
        return;
    const bool on = !v->platformServices.lightOn(light);
    m_gate->command(SetLights{JausVehicleBridge::machineId(sub), bitOf(light), on ? bitOf(light) : 0u},
                    QStringLiteral("gui"));
}

} // namespace ocu
