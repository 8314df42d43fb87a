#include "models/recording/ReplayController.h"

#include "models/AlarmModel.h"
#include "models/FleetModel.h"

#include <algorithm>
#include <cmath>

namespace ocu::recording {

// Forward moves up to this far continue from the current picture; further ones seek (a keyframe is closer).
constexpr qint64 kContinueLimitMs = 20000;

ReplayController::ReplayController(const Recording* recording, FleetModel* fleet, QObject* parent)
    : QObject(parent), m_rec(recording), m_fleet(fleet), m_alarmCap(AlarmModel::kDefaultMaxEntries),
      m_t(recording->startMs()), m_clock(std::make_shared<ManualModelClock>(m_t)) {
    fleet->setRefreshIntervalMs(0);
    fleet->setRemoveAfterMs(0); // removals are in the recording
    for (auto it = m_rec->staleAfterMs().cbegin(), end = m_rec->staleAfterMs().cend(); it != end; ++it)
        fleet->setStaleAfterMs(it.key(), it.value());
    fleet->setClock(m_clock);
    m_alarms = new AlarmModel(this);
    m_alarms->setMaxEntries(m_alarmCap);
    m_history = std::make_unique<AlarmHistory>(m_rec, m_alarmCap);
    m_timer.setInterval(40);
    connect(&m_timer, &QTimer::timeout, this, &ReplayController::tick);
}

QVector<double> ReplayController::speeds() {
    return {0.1, 0.25, 0.5, 1, 2, 4, 8, 16};
}

void ReplayController::seek(qint64 t) {
    t = std::clamp(t, startMs(), endMs());
    QElapsedTimer timer;
    timer.start();
    const qint64 before = m_t;
    const bool wasLoaded = m_loaded;
    m_t = t;
    m_clock->set(t);
    m_states = m_rec->statesAtIdx(t);
    QSet<QString> ids;
    QVector<MachineState> all;
    all.reserve(m_states.size());
    for (const MachineState& s : std::as_const(m_states)) {
        ids.insert(s.id);
        all.push_back(s);
    }
    if (m_fleet) {
        QStringList gone;
        for (const QString& id : m_fleet->ids())
            if (!ids.contains(id))
                gone << id;
        m_fleet->remove(gone);
        m_fleet->upsert(all);
        m_fleet->refresh();
    }
    // A short step forward adds the few events since the current position; anything else restores the rows
    // alive at t (at most the list's cap plus its open alarms), whatever the number of events before t.
    if (wasLoaded && t >= before && t - before <= kContinueLimitMs)
        applyAlarms(before, t);
    else
        restoreAlarms(t, !wasLoaded || t < before);
    emit linksReset(m_rec->linksAt(t));
    updateSiteMap(t);
    updatePassCounts(t);
    m_loaded = true;
    m_lastSeekMs = double(timer.nsecsElapsed()) / 1e6;
    emit positionChanged(m_t);
}

void ReplayController::applyAlarms(qint64 fromExclusive, qint64 toInclusive) {
    // A repeat of an open alarm is one row (AlarmModel groups by key); an acknowledgement closes the open
    // one. In the order the console took them, so that an alarm raised again after its acknowledgement is a
    // new row, as it was live.
    forEachInOrder(
        m_rec->events(fromExclusive, toInclusive), m_rec->acks(fromExclusive, toInclusive),
        [this](const RecordedEvent& e) { m_alarms->add(e.event); },
        [this](const RecordedAck& a) { m_alarms->acknowledgeKey(a.key, a.by, a.t); });
}

void ReplayController::restoreAlarms(qint64 t, bool backwards) {
    const QVector<AlarmModel::RestoredRow> rows = m_history->rowsAt(t);
    if (!backwards) {
        m_alarms->restore(rows);
        return;
    }
    // Backwards: a new model, as alarms() promises (alarmsReplaced); whoever shows the list takes it.
    auto* fresh = new AlarmModel(this);
    fresh->setMaxEntries(m_alarmCap);
    fresh->restore(rows);
    AlarmModel* old = m_alarms;
    m_alarms = fresh;
    emit alarmsReplaced(m_alarms);
    old->deleteLater();
}

void ReplayController::setMaxAlarmEntries(int n) {
    n = std::max(0, n);
    if (n == m_alarmCap)
        return;
    m_alarmCap = n;
    m_alarms->setMaxEntries(n);
    m_history = std::make_unique<AlarmHistory>(m_rec, n);
    if (m_loaded)
        restoreAlarms(m_t, true);
}

// Forward: the changes since the last time applied; backwards: rebuilt from the start (changes are rects of
// absolute counts, so applying them in order gives the counts of t).
void ReplayController::updatePassCounts(qint64 t) {
    if (t == m_passT)
        return;
    const PassCountLayer* before = m_pass.layer();
    const quint64 revBefore = before ? before->revision() : 0;
    if (t < m_passT) {
        m_pass.clear();
        m_passT = std::numeric_limits<qint64>::min();
    }
    m_rec->passCounts(m_passT, t, [this](qint64, const PassCountChange& c) { m_pass.apply(c); });
    m_passT = t;
    const PassCountLayer* after = m_pass.layer();
    if (after != before || (after && after->revision() != revBefore))
        emit passCountsChanged(after);
}

void ReplayController::updateSiteMap(qint64 t) {
    SiteMapData map = m_rec->siteMapAt(t);
    const QString stamp = QStringLiteral("%1/%2").arg(map.revision).arg(map.features.size());
    if (stamp == m_mapStamp)
        return;
    m_mapStamp = stamp;
    emit siteMapChanged(map);
}

void ReplayController::advanceTo(qint64 t) {
    if (!m_loaded || t < m_t || t - m_t > kContinueLimitMs) {
        seek(t);
        return;
    }
    if (t == m_t)
        return;
    const qint64 from = m_t;
    m_t = t;
    m_clock->set(t);
    QStringList removed;
    const QStringList changed = m_rec->advance(m_states, from, t, &removed);
    if (m_fleet) {
        if (!removed.isEmpty())
            m_fleet->remove(removed);
        if (!changed.isEmpty()) {
            QHash<QString, const MachineState*> byId;
            for (const MachineState& s : std::as_const(m_states))
                byId.insert(s.id, &s);
            QVector<MachineState> out;
            out.reserve(changed.size());
            for (const QString& id : changed)
                if (const MachineState* s = byId.value(id))
                    out.push_back(*s);
            m_fleet->upsert(out);
        }
        m_fleet->refresh();
    }
    applyAlarms(from, t);
    for (const RecordedLink& l : m_rec->links(from, t))
        emit linkChanged(l);
    updateSiteMap(t);
    updatePassCounts(t);
    emit positionChanged(m_t);
}

void ReplayController::moveTo(qint64 t) {
    advanceTo(std::clamp(t, startMs(), endMs()));
}

void ReplayController::play() {
    if (playing())
        return;
    if (!m_loaded)
        seek(m_t);
    // At an end, playing starts over from the other end.
    if (!m_reverse && m_t >= endMs())
        seek(startMs());
    else if (m_reverse && m_t <= startMs())
        seek(endMs());
    m_wall.start();
    m_carryMs = 0;
    m_timer.start();
    emit playingChanged(true);
}

void ReplayController::pause() {
    if (!playing())
        return;
    m_timer.stop();
    emit playingChanged(false);
}

void ReplayController::togglePlay() {
    playing() ? pause() : play();
}

void ReplayController::setSpeed(double speed) {
    speed = std::clamp(speed, 0.1, 16.0);
    if (speed == m_speed)
        return;
    m_speed = speed;
    emit speedChanged(m_speed);
}

void ReplayController::faster() {
    for (double s : speeds())
        if (s > m_speed + 1e-9) {
            setSpeed(s);
            return;
        }
}

void ReplayController::slower() {
    const QVector<double> all = speeds();
    for (auto it = all.rbegin(); it != all.rend(); ++it)
        if (*it < m_speed - 1e-9) {
            setSpeed(*it);
            return;
        }
}

void ReplayController::setReverse(bool reverse) {
    if (reverse == m_reverse)
        return;
    m_reverse = reverse;
    emit reverseChanged(m_reverse);
}

void ReplayController::step(int direction) {
    pause();
    moveTo(m_t + (direction >= 0 ? m_stepMs : -m_stepMs));
}

void ReplayController::tick() {
    // Recording time moves by the wall time since the last tick times the speed (not by the nominal
    // interval: a late tick under load must not slow the replay down).
    const double wallMs = double(m_wall.nsecsElapsed()) / 1e6;
    m_wall.start();
    m_carryMs += wallMs * m_speed;
    const auto delta = qint64(std::floor(m_carryMs));
    m_carryMs -= double(delta);
    if (delta == 0)
        return;
    const qint64 target = std::clamp(m_t + (m_reverse ? -delta : delta), startMs(), endMs());
    advanceTo(target);
    if ((!m_reverse && m_t >= endMs()) || (m_reverse && m_t <= startMs())) {
        pause();
        emit finished();
    }
}

} // namespace ocu::recording
