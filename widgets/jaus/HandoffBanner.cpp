#include "widgets/jaus/HandoffBanner.h"

#include "models/CommandGate.h"
#include "models/ControlRoomModel.h"
#include "models/FleetSelection.h"
#include "models/ModelClock.h"
#include "models/jaus/JausSubsystemModel.h"
#include "models/jaus/JausVehicleBridge.h"
#include "widgets/CommandPermissionHint.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
// Amber for a question waiting for this operator, neutral for our own request (day and night palettes keep
// the text readable: only the frame is coloured).
const char* kPromptStyle = "QFrame#handoff-prompt { border: 2px solid #d89400; border-radius: 4px; }";
const char* kBoxStyle = "QFrame#handoff-ask, QFrame#handoff-status { border: 1px solid palette(mid); "
                        "border-radius: 4px; }";

QFrame* box(const char* name, QWidget* parent) {
    auto* f = new QFrame(parent);
    f->setObjectName(QLatin1String(name));
    f->setVisible(false);
    return f;
}
} // namespace

HandoffBanner::HandoffBanner(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection,
                             QWidget* parent)
    : QFrame(parent), m_bridge(bridge), m_gate(gate), m_selection(selection), m_clock(systemModelClock()),
      m_promptBox(box("handoff-prompt", this)), m_promptLabel(new QLabel(m_promptBox)),
      m_countdown(new QLabel(m_promptBox)), m_accept(new QPushButton(tr("Accept"), m_promptBox)),
      m_deny(new QPushButton(tr("Deny"), m_promptBox)), m_wait(new QPushButton(tr("Wait"), m_promptBox)),
      m_askBox(box("handoff-ask", this)), m_askLabel(new QLabel(m_askBox)), m_reason(new QLineEdit(m_askBox)),
      m_ask(new QPushButton(tr("Ask for hand-off"), m_askBox)), m_statusBox(box("handoff-status", this)),
      m_statusLabel(new QLabel(m_statusBox)), m_withdraw(new QPushButton(tr("Withdraw"), m_statusBox)),
      m_dismiss(new QPushButton(tr("OK"), m_statusBox)), m_tick(new QTimer(this)) {
    setObjectName(QStringLiteral("handoff-banner"));
    setStyleSheet(QLatin1String(kPromptStyle) + QLatin1String(kBoxStyle));

    m_promptLabel->setObjectName(QStringLiteral("handoff-prompt-text"));
    m_promptLabel->setWordWrap(true);
    m_promptLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_countdown->setObjectName(QStringLiteral("handoff-countdown"));
    m_accept->setObjectName(QStringLiteral("handoff-accept"));
    m_accept->setToolTip(tr("Hand control of this vehicle to the console that asks"));
    m_deny->setObjectName(QStringLiteral("handoff-deny"));
    m_deny->setToolTip(tr("Keep control; the console that asks is told"));
    m_wait->setObjectName(QStringLiteral("handoff-wait"));
    m_wait->setToolTip(tr("Not yet: the request stays and the decision time starts again; the console that "
                          "asks is told to wait"));
    auto* promptButtons = new QHBoxLayout;
    promptButtons->addWidget(m_countdown, 1);
    promptButtons->addWidget(m_accept);
    promptButtons->addWidget(m_deny);
    promptButtons->addWidget(m_wait);
    auto* pl = new QVBoxLayout(m_promptBox);
    pl->setContentsMargins(6, 4, 6, 4);
    pl->addWidget(m_promptLabel);
    pl->addLayout(promptButtons);
    connect(m_accept, &QPushButton::clicked, this, [this] { answer(true); });
    connect(m_deny, &QPushButton::clicked, this, [this] { answer(false); });
    connect(m_wait, &QPushButton::clicked, this, [this] { answer(false, true); });

    m_askLabel->setObjectName(QStringLiteral("handoff-ask-text"));
    m_askLabel->setWordWrap(true);
    m_reason->setObjectName(QStringLiteral("handoff-reason"));
    m_reason->setPlaceholderText(tr("Reason the holder's operator sees"));
    m_reason->setMaxLength(120); // the explanation is at most 255 bytes on the wire, with our call sign
    m_ask->setObjectName(QStringLiteral("handoff-ask"));
    auto* askRow = new QHBoxLayout;
    askRow->addWidget(m_reason, 1);
    askRow->addWidget(m_ask);
    auto* al = new QVBoxLayout(m_askBox);
    al->setContentsMargins(6, 4, 6, 4);
    al->addWidget(m_askLabel);
    al->addLayout(askRow);
    auto ask = [this] {
        if (m_gate && m_askVehicle && m_ask->isEnabled())
            m_gate->command(
                HandoffRequest{JausVehicleBridge::machineId(m_askVehicle), m_reason->text().trimmed(), false},
                QStringLiteral("gui"));
    };
    connect(m_ask, &QPushButton::clicked, this, ask);
    connect(m_reason, &QLineEdit::returnPressed, this, ask);

    m_statusLabel->setObjectName(QStringLiteral("handoff-status-text"));
    m_statusLabel->setWordWrap(true);
    m_withdraw->setObjectName(QStringLiteral("handoff-withdraw"));
    m_dismiss->setObjectName(QStringLiteral("handoff-dismiss"));
    auto* sl = new QHBoxLayout(m_statusBox);
    sl->setContentsMargins(6, 4, 6, 4);
    sl->addWidget(m_statusLabel, 1);
    sl->addWidget(m_withdraw);
    sl->addWidget(m_dismiss);
    connect(m_withdraw, &QPushButton::clicked, this, [this] {
        if (m_gate && m_statusVehicle)
            m_gate->command(HandoffRequest{JausVehicleBridge::machineId(m_statusVehicle), {}, true},
                            QStringLiteral("gui"));
    });
    connect(m_dismiss, &QPushButton::clicked, this, [this] {
        m_dismissed[m_statusVehicle] = m_seen.value(m_statusVehicle).handoff.reason;
        refresh();
    });

    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(0, 2, 0, 2);
    l->setSpacing(3);
    l->addWidget(m_promptBox);
    l->addWidget(m_statusBox);
    l->addWidget(m_askBox);
    setVisible(false);

    m_tick->setInterval(1000);
    connect(m_tick, &QTimer::timeout, this, &HandoffBanner::updateCountdown);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, &HandoffBanner::onVehicle);
    for (quint16 ss : bridge->subsystems())
        if (auto v = bridge->subsystem(ss))
            m_seen[ss] = Seen{v->subsystem,      v->callSign, v->controller, v->controllerAuthority,
                              v->controlledByUs, v->link,     v->handoff};
    if (m_selection)
        connect(m_selection, &FleetSelection::currentMachineChanged, this, [this] { refresh(); });
    if (gate)
        connect(gate, &CommandGate::permissionsChanged, this, &HandoffBanner::refresh);
    refresh();
}

void HandoffBanner::setControlRoom(ControlRoomModel* room) {
    if (m_room)
        disconnect(m_room, nullptr, this, nullptr);
    m_room = room;
    if (room)
        connect(room, &ControlRoomModel::roomChanged, this, &HandoffBanner::refresh);
    refresh();
}

QString HandoffBanner::personAt(const QString& jausId) const {
    const auto console =
        m_room ? m_room->consoleControllingWith(QStringLiteral("jaus:") + jausId) : std::nullopt;
    return console ? ControlRoomModel::personAtConsole(*console) : QString();
}

void HandoffBanner::setClock(std::shared_ptr<const ModelClock> clock) {
    m_clock = clockOrSystem(std::move(clock));
    updateCountdown();
}

QString HandoffBanner::nameOf(const Seen& v) {
    return v.callSign.isEmpty() ? JausVehicleBridge::machineId(v.subsystem) : v.callSign;
}

void HandoffBanner::onVehicle(const JausVehicle& v) {
    Seen seen{v.subsystem,      v.callSign, v.controller, v.controllerAuthority,
              v.controlledByUs, v.link,     v.handoff};
    auto it = m_seen.find(v.subsystem);
    if (it != m_seen.end() && *it == seen)
        return;
    m_seen[v.subsystem] = std::move(seen);
    refresh();
}

void HandoffBanner::refresh() {
    const Seen* holder = nullptr;
    const Seen* own = nullptr;
    const Seen* selected = nullptr;
    const QString current = m_selection ? m_selection->currentId() : QString();
    for (const Seen& v : m_seen) {
        if (!holder && !v.handoff.prompts.isEmpty())
            holder = &v;
        const bool outcome =
            v.handoff.state != HandoffState::None && m_dismissed.value(v.subsystem) != v.handoff.reason;
        // Our own request: the selected vehicle's, else any that still waits.
        if (outcome &&
            (JausVehicleBridge::machineId(v.subsystem) == current || (!own && isWaiting(v.handoff.state))))
            own = &v;
        if (JausVehicleBridge::machineId(v.subsystem) == current)
            selected = &v;
    }
    showPrompt(holder);
    showStatus(own);
    showAsk(selected);
    setVisible(m_promptBox->isVisibleTo(this) || m_statusBox->isVisibleTo(this) ||
               m_askBox->isVisibleTo(this));
}

void HandoffBanner::showPrompt(const Seen* v) {
    if (!v) {
        m_promptVehicle = 0;
        m_promptBox->setVisible(false);
        m_tick->stop();
        return;
    }
    m_promptVehicle = v->subsystem;
    m_prompt = v->handoff.prompts.front();
    const QString person = personAt(m_prompt.requester);
    QString text = person.isEmpty() ? tr("Console %1 asks for control of %2 (authority %3).")
                                          .arg(m_prompt.requester, nameOf(*v))
                                          .arg(m_prompt.authority)
                                    : tr("%1 (console %2) asks for control of %3 (authority %4).")
                                          .arg(person, m_prompt.requester, nameOf(*v))
                                          .arg(m_prompt.authority);
    if (!m_prompt.explanation.isEmpty())
        text += QLatin1Char('\n') + tr("Reason: %1").arg(m_prompt.explanation);
    if (m_prompt.waited)
        text += QLatin1Char('\n') + tr("You asked it to wait; its console keeps the request up.");
    if (v->handoff.prompts.size() > 1)
        text += QLatin1Char('\n') +
                tr("%n more request(s) waiting after this one.", "", int(v->handoff.prompts.size() - 1));
    m_promptLabel->setText(text);
    const bool may = m_bridge->mayCommand();
    for (QPushButton* b : {m_accept, m_deny, m_wait})
        b->setEnabled(permittedShowingWhy(b, m_gate, QStringLiteral("handoff_answer")) && may);
    m_promptBox->setVisible(true);
    updateCountdown();
    if (!m_tick->isActive())
        m_tick->start();
}

void HandoffBanner::updateCountdown() {
    if (!m_promptVehicle)
        return;
    if (m_prompt.decisionTimeoutS <= 0) {
        m_countdown->setText(tr("No time limit: the vehicle waits for your answer."));
        return;
    }
    const double elapsedS = double(m_clock->nowMs() - m_prompt.receivedMs) / 1000.0;
    const int left = std::max(0, int(std::ceil(m_prompt.decisionTimeoutS - elapsedS)));
    m_countdown->setText(tr("Answer within %n s, else the vehicle refuses it (timeout).", "", left));
}

void HandoffBanner::answer(bool accept, bool wait) {
    if (!m_gate || !m_promptVehicle)
        return;
    m_gate->command(HandoffAnswer{JausVehicleBridge::machineId(m_promptVehicle), m_prompt.id, accept, wait},
                    QStringLiteral("gui"));
}

void HandoffBanner::showAsk(const Seen* v) {
    const bool heldByOther = v && v->controller.subsystem != 0 && !v->controlledByUs &&
                             v->link != JausLink::Down && !isWaiting(v->handoff.state) &&
                             v->handoff.prompts.isEmpty();
    if (!heldByOther || !m_bridge->mayCommand()) {
        m_askVehicle = 0;
        m_askBox->setVisible(false);
        return;
    }
    m_askVehicle = v->subsystem;
    const QString holder = QStringLiteral("%1.%2.%3")
                               .arg(v->controller.subsystem)
                               .arg(v->controller.node)
                               .arg(v->controller.component);
    const QString person = personAt(holder);
    if (v->handoff.offered && !person.isEmpty())
        m_askLabel->setText(tr("%1 is held by %2 (console %3, authority %4). Ask them to hand it over:")
                                .arg(nameOf(*v), person, holder)
                                .arg(v->controllerAuthority));
    else if (v->handoff.offered)
        m_askLabel->setText(tr("%1 is held by console %2 (authority %3). Ask its operator to hand it over:")
                                .arg(nameOf(*v), holder)
                                .arg(v->controllerAuthority));
    else
        m_askLabel->setText(
            tr("%1 is held by %2 (authority %3) and offers no Enhanced Access Control: asking "
               "takes control only with a higher authority than the holder's (ordinary "
               "pre-emption, authority %4 here).")
                .arg(nameOf(*v), holder)
                .arg(v->controllerAuthority)
                .arg(m_bridge->identity().authority));
    m_ask->setEnabled(permittedShowingWhy(m_ask, m_gate, QStringLiteral("handoff_request")));
    m_askBox->setVisible(true);
}

void HandoffBanner::showStatus(const Seen* v) {
    if (!v) {
        m_statusVehicle = 0;
        m_statusBox->setVisible(false);
        return;
    }
    m_statusVehicle = v->subsystem;
    const HandoffState s = v->handoff.state;
    QString state;
    switch (s) {
    case HandoffState::Requesting:
    case HandoffState::Queued:
        state = tr("Waiting for the holder's answer");
        break;
    case HandoffState::Granted:
        state = tr("Granted: taking control");
        break;
    case HandoffState::Completed:
        state = tr("Control handed over");
        break;
    case HandoffState::Denied:
        state = tr("Denied");
        break;
    case HandoffState::TimedOut:
        state = tr("No answer in time");
        break;
    case HandoffState::Refused:
        state = tr("Refused");
        break;
    case HandoffState::Cancelled:
        state = tr("Withdrawn");
        break;
    case HandoffState::Preempting:
        state = tr("Requesting control (ordinary pre-emption)");
        break;
    case HandoffState::Waiting:
        state = tr("The holder asks you to wait; the request is kept up");
        break;
    case HandoffState::None:
        break;
    }
    // The state in the operator's language, the details in the stack's words (as in the event log).
    m_statusLabel->setText(tr("Hand-off of %1: %2.").arg(nameOf(*v), state) + QLatin1Char('\n') +
                           v->handoff.reason);
    const bool waiting =
        s == HandoffState::Requesting || s == HandoffState::Queued || s == HandoffState::Waiting;
    m_withdraw->setVisible(waiting);
    m_dismiss->setVisible(!isWaiting(s));
    m_statusBox->setVisible(true);
}

QList<QWidget*> HandoffBanner::tabChain() const {
    return {m_accept, m_deny, m_wait, m_withdraw, m_dismiss, m_reason, m_ask};
}

QString HandoffBanner::promptText() const {
    return m_promptBox->isVisibleTo(this) ? m_promptLabel->text() + QLatin1Char('\n') + m_countdown->text()
                                          : QString();
}
QString HandoffBanner::statusText() const {
    return m_statusBox->isVisibleTo(this) ? m_statusLabel->text() : QString();
}
bool HandoffBanner::promptShown() const {
    return m_promptBox->isVisibleTo(this);
}

} // namespace ocu
