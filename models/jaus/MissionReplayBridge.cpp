#include "models/jaus/MissionReplayBridge.h"

#include "models/FleetModel.h"
#include "models/jaus/MissionJson.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>

namespace ocu {

namespace {

QString replayRefusal() {
    return QCoreApplication::translate("MissionReplayBridge", "replay: commands are disabled");
}

} // namespace

MissionReplayBridge::MissionReplayBridge(QVector<Record> records, const FleetModel* fleet, QObject* parent)
    : JausVehicleBridge(parent), m_records(std::move(records)), m_fleet(fleet) {}

void MissionReplayBridge::setTime(qint64 t) {
    QHash<quint16, JausMission> before = m_missions; // what the views were told
    const bool forwards = t >= m_t;
    if (!forwards) { // backwards: the paths grow record by record, so start over
        m_missions.clear();
        m_next = 0;
    }
    m_t = t;
    for (; m_next < m_records.size() && m_records[m_next].t <= t; ++m_next) {
        const Record& r = m_records[m_next];
        const auto sub = subsystemOf(r.machine);
        JausMission* m = sub ? &m_missions[*sub] : nullptr;
        const JausMission was = forwards && m ? *m : JausMission{}; // only compared forwards
        if (!m || !applyMissionRecord(*m, r.data)) {
            ++m_malformed;
            continue;
        }
        // Playing forwards, each change of state, waypoint, ownership or reason is told on its own, as live
        // (two within one step of the replay clock are two headless lines, not one).
        if (forwards && !onlyProgressDiffers(was, *m) && m_next + 1 < m_records.size() &&
            m_records[m_next + 1].t <= t) {
            emit subsystemUpdated(*subsystem(*sub));
            before[*sub] = *m;
        }
    }
    QSet<quint16> ids(m_missions.keyBegin(), m_missions.keyEnd());
    for (auto it = before.keyBegin(); it != before.keyEnd(); ++it)
        ids.insert(*it);
    QList<quint16> changed;
    for (quint16 id : ids)
        if (!(before.value(id) == m_missions.value(id)))
            changed << id;
    std::sort(changed.begin(), changed.end());
    for (quint16 id : changed) { // a vehicle sought back to before its first record has no mission again
        JausVehicle none;
        none.subsystem = id;
        emit subsystemUpdated(subsystem(id).value_or(none));
    }
}

JausConsoleIdentity MissionReplayBridge::identity() const {
    JausConsoleIdentity id;
    id.mayControl = false;
    id.mayStop = false;
    return id;
}

QList<quint16> MissionReplayBridge::subsystems() const {
    QList<quint16> out = m_missions.keys();
    std::sort(out.begin(), out.end());
    return out;
}

std::optional<JausVehicle> MissionReplayBridge::subsystem(quint16 id) const {
    JausVehicle v;
    v.subsystem = id;
    v.mission = m_missions.value(id);
    const MachineState* m = m_fleet ? m_fleet->machine(machineId(id)) : nullptr;
    if (!m && !m_missions.contains(id))
        return std::nullopt;
    if (m) {
        v.callSign = m->name;
        v.link = m->link == LinkState::Down       ? JausLink::Down
                 : m->link == LinkState::Degraded ? JausLink::Degraded
                                                  : JausLink::Up;
        if (m->hasPosition)
            v.globalPose = JausGlobalPose{m->lat, m->lon, m->u, std::nullopt};
    }
    return v;
}

CommandResult MissionReplayBridge::drive(quint16, const JausDrive&) {
    return CommandResult::failure(replayRefusal());
}

CommandResult MissionReplayBridge::stopDriving(quint16) {
    return CommandResult::failure(replayRefusal());
}

void MissionReplayBridge::stopAll(OutcomeCallback done) {
    done({refusal(toText(Protocol::Jaus), OutcomeReason::NotSupported, replayRefusal())});
}

void MissionReplayBridge::stopMachine(const QString& id, OutcomeCallback done) {
    done({refusal(id, OutcomeReason::NotSupported, replayRefusal())});
}

void MissionReplayBridge::clearStop(const QString& id, OutcomeCallback done) {
    done({refusal(id, OutcomeReason::NotSupported, replayRefusal())});
}

} // namespace ocu
