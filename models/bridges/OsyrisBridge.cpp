#include "models/bridges/OsyrisBridge.h"
#include "models/QtStrings.h"

#include <QJsonObject>
#include <QMetaObject>

#include <chrono>
#include <cmath>

namespace ocu {

using namespace osyris;

OsyrisBridge::OsyrisBridge(const OsyrisConfig& config, const GeoFrame& siteFrame, QObject* parent)
    : FleetBridge(Protocol::Osyris, parent), m_config(config), m_frame(siteFrame) {
    m_station = std::make_unique<OsyrisStack>(m_config, static_cast<OsyrisListener&>(*this));
    const EnuPoint o = m_frame.toLocal({config.originLat, config.originLon, config.originAlt});
    m_layer = std::make_unique<OsyrisPassCountLayer>(m_config.passCount.cellSize, QPointF(o.e, o.n));
    // Every station sends ALIVE each SendPeriod (§4), so silence is judged on the io thread, where "heard" is.
    connect(&m_silenceCheck, &QTimer::timeout, this, [this] { postToIo([this] { checkSilence(); }); });
}

OsyrisBridge::~OsyrisBridge() {
    stop();
}

void OsyrisBridge::setMessageTap(MessageTap* tap) {
    m_station->setMessageTap(tap);
}

QString OsyrisBridge::start() {
    std::string error;
    const QString link = QStringLiteral("osyris:%1:%2").arg(toQString(m_config.group)).arg(m_config.port);
    if (!m_station->start(&error)) {
        publishLink({link, ocu::LinkState::Down, -1, toQString(error)});
        return tr("OSYRIS: %1").arg(toQString(error));
    }
    m_running = true;
    publishLink({link, ocu::LinkState::Degraded, -1, tr("joined, waiting for stations")});
    m_silenceCheck.start(1000);
    return {};
}

void OsyrisBridge::stop() {
    const bool wasRunning = m_running;
    m_running = false;
    m_silenceCheck.stop();
    if (m_station)
        m_station->stop();
    if (wasRunning) {
        m_linkUp = false; // a restart publishes "up" again when a station is heard
        publishStackStopped(tr("OSYRIS station stopped"));
    }
}

osyris::PassCountSummary OsyrisBridge::passCountSummary() const {
    // GUI thread: the snapshot it holds, no lock shared with the io thread.
    return m_layer->snapshot() ? m_layer->snapshot()->summary() : osyris::PassCountSummary{};
}

// ---- io thread ----

namespace {
std::int64_t steadyMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

void OsyrisBridge::noteHeard() {
    m_heard = true;
    m_lastHeardMs = steadyMs();
    if (m_linkUp.exchange(true))
        return; // published once; positions keep the data age fresh
    publishLink({QStringLiteral("osyris:%1:%2").arg(toQString(m_config.group)).arg(m_config.port),
                 ocu::LinkState::Up, 0, tr("stations heard")});
}

void OsyrisBridge::checkSilence() {
    // Like JAUS's heartbeat rule: degraded after 2.5 periods of the stations' ALIVE without anything heard.
    const std::int64_t silentMs = steadyMs() - m_lastHeardMs;
    if (!m_running || silentMs <= m_config.sendPeriodMs * 5 / 2 || !m_linkUp.exchange(false))
        return;
    publishLink({QStringLiteral("osyris:%1:%2").arg(toQString(m_config.group)).arg(m_config.port),
                 ocu::LinkState::Degraded, silentMs, tr("no station heard for %1 s").arg(silentMs / 1000)});
}

void OsyrisBridge::onMachinePosition(const MachineSnapshot& s) {
    noteHeard();
    if (!s.implausible.empty()) {
        // The station's plausibility gate refused this position: keep what was good, say why.
        auto it = m_lastGoodIo.find(s.idx);
        MachineState m;
        if (it != m_lastGoodIo.end()) {
            m = it->second;
        } else {
            m.id = protocolPrefix(Protocol::Osyris) + QString::number(s.idx);
            m.protocol = Protocol::Osyris;
            m.name = s.name.empty() ? tr("Machine %1").arg(s.idx) : toQString(s.name);
            m.type = QStringLiteral("roller");
            m.hasPosition = false;
        }
        m.link = ocu::LinkState::Up;
        m.lastDataMs = clock().nowMs();
        m.health = HealthLevel::Warning;
        m.healthText =
            tr("implausible position ignored (slot %1): %2").arg(s.slot).arg(toQString(s.implausible));
        publishMachine(m);
        return;
    }
    MachineState m;
    m.id = protocolPrefix(Protocol::Osyris) + QString::number(s.idx);
    m.protocol = Protocol::Osyris;
    m.name = s.name.empty() ? tr("Machine %1").arg(s.idx) : toQString(s.name);
    const QString lower = m.name.toLower();
    const bool paver = lower.contains(QLatin1String("paver")) || lower.contains(QLatin1String("fertiger"));
    m.type = paver ? QStringLiteral("paver") : QStringLiteral("roller");
    m.link = ocu::LinkState::Up;
    m.lastDataMs = clock().nowMs();
    m.lastMessageMs = s.timestampMs;
    // Positions are geo-referenced by the station through the worksite origin; place them in the site frame.
    const EnuPoint p = m_frame.toLocal({s.lat, s.lon, m_config.originAlt + s.z});
    m.hasPosition = s.valid || s.lat != 0 || s.lon != 0;
    m.e = p.e;
    m.n = p.n;
    m.u = p.u;
    m.lat = s.lat;
    m.lon = s.lon;
    m.headingDeg = s.headingDeg;
    m.speed = s.speed;
    m.width = s.width > 0 ? s.width : (paver ? 3.0 : 2.0);
    m.length = paver ? 6.5 : 4.5;
    m.height = paver ? 3.5 : 3.0;
    QStringList mode;
    mode << (s.vibrating ? tr("vibration on") : tr("vibration off"));
    if (s.forward)
        mode << tr("forward");
    else if (s.backward)
        mode << tr("backward");
    else if (s.stopped)
        mode << tr("standing");
    m.modeText = mode.join(QStringLiteral(", "));
    m.mode = ModeCategory::Manual;
    m.stop = StopState::None; // OSYRIS carries no stop state: rollers and pavers are manned
    if (s.gpsShadow || !s.valid) {
        m.health = HealthLevel::Warning;
        m.healthText = s.gpsShadow ? tr("GPS shadow") : tr("position not valid");
    } else if (s.accuracy < 2) {
        m.health = HealthLevel::Warning;
        m.healthText = tr("low position accuracy");
    } else {
        m.health = HealthLevel::Ok;
        m.healthText = s.accuracy >= 3 ? tr("high accuracy") : tr("medium accuracy");
    }
    m_lastGoodIo[s.idx] = m;
    publishMachine(m);
}

void OsyrisBridge::onStationAlive(std::uint8_t idx, std::optional<SlotRange>) {
    (void)idx;
    noteHeard();
}

PassCountFilter OsyrisBridge::passCountFilter() const {
    const PassCountSettings& s = m_config.passCount;
    PassCountFilter f;
    f.vibration = s.vibration == VibrationFilter::On    ? PassCountFilter::Vibration::On
                  : s.vibration == VibrationFilter::Off ? PassCountFilter::Vibration::Off
                                                        : PassCountFilter::Vibration::Any;
    f.direction = s.direction == DirectionFilter::Forward    ? PassCountFilter::Direction::Forward
                  : s.direction == DirectionFilter::Backward ? PassCountFilter::Direction::Backward
                                                             : PassCountFilter::Direction::Any;
    f.speedMin = s.speedMin.value_or(0);
    f.speedMax = s.speedMax.value_or(0);
    f.timeFromMs = s.timeFrom.value_or(0);
    f.timeToMs = s.timeTo.value_or(0);
    f.liftThickness = s.liftThickness;
    f.liftBase = s.liftBase;
    return f;
}

void OsyrisBridge::setPassCountFilter(const PassCountFilter& f) {
    PassCountSettings s = m_config.passCount;
    s.vibration = f.vibration == PassCountFilter::Vibration::On    ? VibrationFilter::On
                  : f.vibration == PassCountFilter::Vibration::Off ? VibrationFilter::Off
                                                                   : VibrationFilter::Any;
    s.direction = f.direction == PassCountFilter::Direction::Forward    ? DirectionFilter::Forward
                  : f.direction == PassCountFilter::Direction::Backward ? DirectionFilter::Backward
                                                                        : DirectionFilter::Any;
    s.speedMin = f.speedMin > 0 ? std::optional<double>(f.speedMin) : std::nullopt;
    s.speedMax = f.speedMax > 0 ? std::optional<double>(f.speedMax) : std::nullopt;
    s.timeFrom = f.timeFromMs > 0 ? std::optional<std::int64_t>(f.timeFromMs) : std::nullopt;
    s.timeTo = f.timeToMs > 0 ? std::optional<std::int64_t>(f.timeToMs) : std::nullopt;
    s.liftThickness = std::max(0.0, f.liftThickness);
    s.liftBase = f.liftBase;
    if (s == m_config.passCount)
        return;
    m_config.passCount = s;
    if (m_station)
        m_station->setPassCountSettings(s);
}

QVector<PassCountLiftInfo> OsyrisBridge::passCountLifts() const {
    QVector<PassCountLiftInfo> out;
    if (const auto& snap = m_layer->snapshot())
        for (int i = 0; i < snap->liftCount(); ++i)
            out.push_back({snap->liftBottom(i), snap->liftTop(i)});
    return out;
}

QStringList OsyrisBridge::passCountGaps() const {
    QStringList out;
    if (const auto& snap = m_layer->snapshot())
        for (const auto& [idx, ranges] : snap->givenUp()) {
            QStringList parts;
            std::uint64_t n = 0;
            for (const auto& r : ranges) {
                parts << (r.from == r.to ? QString::number(r.from)
                                         : QStringLiteral("%1–%2").arg(r.from).arg(r.to));
                n += r.size();
            }
            out << tr("%1: %2 positions given up as unobtainable (slots %3); their cells are marked "
                      "incomplete")
                       .arg(stationName(idx))
                       .arg(n)
                       .arg(parts.join(QStringLiteral(", ")));
        }
    return out;
}

int OsyrisBridge::viewLift() const {
    return m_layer->viewLift();
}

void OsyrisBridge::setViewLift(int lift) {
    if (lift == m_layer->viewLift())
        return;
    m_layer->setViewLift(lift);
    emit passCountChanged();
}

QVector<CrewRecipient> OsyrisBridge::crewRecipients() const {
    std::set<int> ids(m_textSenders);
    for (const auto& [idx, name] : m_config.machineNames) {
        auto t = m_config.machineTypes.find(idx);
        if (t == m_config.machineTypes.end() || t->second != "relay")
            ids.insert(idx);
    }
    QVector<CrewRecipient> out;
    for (int idx : ids)
        if (idx != m_config.stationIndex)
            out.push_back({protocolPrefix(Protocol::Osyris) + QString::number(idx), stationName(idx)});
    return out;
}

QString OsyrisBridge::stationName(int idx) const {
    if (auto it = m_config.machineNames.find(static_cast<std::uint8_t>(idx));
        it != m_config.machineNames.end())
        return toQString(it->second);
    return tr("station %1").arg(idx);
}

void OsyrisBridge::onText(std::uint8_t idx, const std::string& text) {
    const QString id = protocolPrefix(Protocol::Osyris) + QString::number(idx);
    const QString name = stationName(idx);
    FleetEvent e =
        makeEvent(EventSeverity::Info, ocu::EventKind::TextMessage, id,
                  tr("Message from %1 (%2): %3").arg(name, id, toQString(text)), QStringLiteral("osyris"));
    // A message, not an alarm (EEMUA 191: an alarm is a condition that needs an operator's action): it goes
    // to the crew messages panel (unread count, notification) and to the event log as information, never
    // into the alarm list, its counts or its flood indicator.
    e.requiresAck = false;
    publishEvent(e);
    QMetaObject::invokeMethod(
        this,
        [this, idx, id, name, t = toQString(text)] {
            m_textSenders.insert(idx);
            emit textReceived(id, name, t);
        },
        Qt::QueuedConnection);
}

bool OsyrisBridge::readyForPassCounts() {
    return !m_passCountQueued.load();
}

void OsyrisBridge::onPassCounts(std::shared_ptr<const PassCountSnapshot> snapshot) {
    // One snapshot in flight at a time (the core keeps a newer change pending until this one is taken),
    // handed to the GUI thread by value: the GUI then reads it without any lock shared with the io thread.
    m_passCountQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this, snapshot = std::move(snapshot)]() mutable {
            m_layer->setSnapshot(std::move(snapshot));
            m_passCountQueued = false;
            emit passCountChanged();
        },
        Qt::QueuedConnection);
}

void OsyrisBridge::onEvent(Severity severity, const std::string& text) {
    const EventSeverity s = severity == Severity::Error     ? EventSeverity::Alarm
                            : severity == Severity::Warning ? EventSeverity::Warning
                                                            : EventSeverity::Info;
    publishEvent(makeEvent(s, ocu::EventKind::Info, {}, toQString(text), QStringLiteral("osyris")));
}

// ---- GUI thread ----

QString OsyrisBridge::linkRefusal(const QString& what) const {
    // A message sent while nobody listens would wait in the station's store for late joiners.
    if (!m_running)
        return tr("%1 refused: the OSYRIS station is not running; nothing sent").arg(what);
    if (!m_heard)
        return tr("%1 refused: no OSYRIS station heard on %2:%3 yet; nothing sent")
            .arg(what, toQString(m_config.group))
            .arg(m_config.port);
    return {};
}

void OsyrisBridge::stopAll(OutcomeCallback done) {
    const QString target = toQString(m_station->groupTarget());
    if (const QString why = linkRefusal(tr("STOP message")); !why.isEmpty()) {
        done({refusal(target, linkCause(), why)});
        return;
    }
    // OSYRIS has no stop command (manned machines); the stop reaches every driver's display as a message,
    // sent at once as its own datagram.
    m_station->sendText("STOP ALL issued by the operator control unit", std::move(done));
}

void OsyrisBridge::stopMachine(const QString& id, OutcomeCallback done) {
    if (!id.startsWith(protocolPrefix(Protocol::Osyris))) {
        done({refusal(id, OutcomeReason::UnknownTarget, tr("not an OSYRIS machine"))});
        return;
    }
    if (const QString why = linkRefusal(tr("STOP message")); !why.isEmpty()) {
        done({refusal(id, linkCause(), why)});
        return;
    }
    m_station->sendText("STOP " + id.mid(protocolPrefix(Protocol::Osyris).size()).toStdString() +
                            ": stop requested by the operator control unit",
                        std::move(done));
}

void OsyrisBridge::clearStop(const QString& id, OutcomeCallback done) {
    done({refusal(id, OutcomeReason::NotSupported, tr("OSYRIS machines carry no stop state to clear"))});
}

OutcomeReason OsyrisBridge::linkCause() const {
    return m_running ? OutcomeReason::LinkDown : OutcomeReason::NotRunning;
}

void OsyrisBridge::sendText(const SendText& c, OutcomeCallback done) {
    const QString target = toQString(m_station->groupTarget());
    // To one machine (its id) or to all (no id).
    int to = osyris::kIdxAll;
    if (!c.id.isEmpty()) {
        bool ok = false;
        to = c.id.startsWith(protocolPrefix(Protocol::Osyris))
                 ? c.id.mid(protocolPrefix(Protocol::Osyris).size()).toInt(&ok)
                 : -1;
        if (!ok || to < 0 || to > 253)
            return done({refusal(c.id, OutcomeReason::UnknownTarget,
                                 tr("send_text: \"%1\" is not an OSYRIS station").arg(c.id))});
    }
    const QString shown = c.id.isEmpty() ? target : c.id;
    if (c.text.isEmpty() || c.text.toUtf8().size() > 79) // §6: 80 bytes NUL-padded, so C peers find a NUL
        return done({refusal(shown, OutcomeReason::InvalidArgument,
                             tr("send_text: \"text\" must be 1 to 79 bytes (CmMsg)"))});
    if (const QString why = linkRefusal(QStringLiteral("send_text")); !why.isEmpty())
        return done({refusal(shown, linkCause(), why)});
    m_station->sendText(c.text.toStdString(), static_cast<std::uint8_t>(to), std::move(done));
}

void OsyrisBridge::command(const OperatorCommand& command, OutcomeCallback done) {
    std::visit(Overloaded{
                   [&](const SendText& c) { sendText(c, std::move(done)); },
                   [&](const PingStation& c) {
                       const QString target = toQString(m_station->groupTarget());
                       if (c.idx < 0 || c.idx > 253)
                           return done({refusal(target, OutcomeReason::InvalidArgument,
                                                tr("ping: \"idx\" must be a station index 0-253"))});
                       if (const QString why = linkRefusal(QStringLiteral("ping")); !why.isEmpty())
                           return done({refusal(target, linkCause(), why)});
                       // Sent at once as its own datagram; the outcome says whether the socket took it, the
                       // PONG (an event with the round trip) shows the effect.
                       m_station->ping(static_cast<std::uint8_t>(c.idx), std::move(done));
                   },
                   [&](const auto&) { FleetBridge::command(command, std::move(done)); },
               },
               command);
}

std::chrono::milliseconds OsyrisBridge::ioStalledFor() const {
    return m_station ? m_station->ioStalledFor() : std::chrono::milliseconds(0);
}

void OsyrisBridge::postToIo(std::function<void()> f) {
    if (m_station)
        m_station->postToIo(std::move(f));
}

QVector<LinkCounters> OsyrisBridge::linkCounters() const {
    return {LinkCounters::of(QStringLiteral("osyris:%1:%2").arg(toQString(m_config.group)).arg(m_config.port),
                             m_station->counters())};
}

} // namespace ocu
