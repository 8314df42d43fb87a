#include "widgets/StopControls.h"

#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/HoldToConfirmButton.h"

#include <QHBoxLayout>

namespace ocu {

QAction* createStopAllAction(CommandGate* stop, QObject* parent) {
    auto* a = new QAction(QObject::tr("STOP ALL"), parent);
    a->setToolTip(QObject::tr("Stop every machine of every protocol (F12)"));
    a->setShortcuts({QKeySequence(Qt::Key_F12), QKeySequence(Qt::CTRL | Qt::Key_Space)});
    a->setShortcutContext(Qt::ApplicationShortcut);
    QObject::connect(a, &QAction::triggered, stop, [stop] { stop->stopAll(QStringLiteral("gui")); });
    return a;
}

StopAllButton::StopAllButton(CommandGate* stop, QWidget* parent) : QPushButton(tr("STOP ALL"), parent) {
    setObjectName(QStringLiteral("stopAllButton"));
    setToolTip(tr("Stop every machine of every protocol (F12)"));
    setMinimumHeight(44);
    setStyleSheet(QStringLiteral("QPushButton{background:#d01010;color:white;font-weight:bold;font-size:16px;"
                                 "border:2px solid #700;border-radius:6px;padding:4px 16px}"
                                 "QPushButton:pressed{background:#900}"));
    connect(this, &QPushButton::clicked, stop, [stop] { stop->stopAll(QStringLiteral("gui")); });
}

MachineStopControls::MachineStopControls(FleetModel* fleet, FleetSelection* selection, CommandGate* stop,
                                         QWidget* parent)
    : QWidget(parent), m_fleet(fleet), m_selection(selection), m_gate(stop), m_state(new QLabel(this)),
      m_stopButton(new QPushButton(tr("Stop"), this)),
      m_release(new HoldToConfirmButton(tr("Hold to release"), this)) {
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->addWidget(m_state, 1);
    lay->addWidget(m_stopButton);
    lay->addWidget(m_release);
    m_stopButton->setStyleSheet(
        QStringLiteral("QPushButton{background:#d01010;color:white;font-weight:bold}"));
    connect(m_stopButton, &QPushButton::clicked, this, [this] {
        if (m_gate && m_selection && !m_selection->currentId().isEmpty())
            m_gate->stopMachine(m_selection->currentId(), QStringLiteral("gui"));
    });
    connect(m_release, &HoldToConfirmButton::confirmed, this, [this] {
        if (!m_gate || !m_selection || m_selection->currentId().isEmpty())
            return;
        const QString id = m_selection->currentId();
        m_gate->clearStop(id, m_gate->requestClearToken(id), QStringLiteral("gui"));
    });
    connect(selection, &FleetSelection::currentMachineChanged, this, &MachineStopControls::refresh);
    connect(fleet, &FleetModel::machinesChanged, this, &MachineStopControls::refresh);
    connect(fleet, &FleetModel::machineRemoved, this, &MachineStopControls::refresh);
    refresh();
}

void MachineStopControls::refresh() {
    const QString id = m_selection ? m_selection->currentId() : QString();
    const MachineState* m = m_fleet && !id.isEmpty() ? m_fleet->machine(id) : nullptr;
    m_stopButton->setEnabled(m != nullptr);
    m_release->setEnabled(m != nullptr);
    if (!m) {
        m_state->setText(tr("No machine selected"));
        return;
    }
    // The machine's own report, never what we asked for.
    const QString stop =
        m->stop == StopState::Stopped
            ? tr("STOPPED%1")
                  .arg(m->stopText.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(m->stopText))
        : m->stop == StopState::None ? tr("running")
                                     : tr("stop state unknown");
    m_state->setText(QStringLiteral("%1: %2").arg(m->name.isEmpty() ? m->id : m->name, stop));
}

} // namespace ocu
