#include "models/jaus/MissionJson.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>

namespace ocu {

namespace {

constexpr MissionState kStates[] = {
    MissionState::None,   MissionState::Uploading, MissionState::Uploaded, MissionState::Running,
    MissionState::Paused, MissionState::Completed, MissionState::Aborted,  MissionState::StoppedByEmergency,
    MissionState::Lost,   MissionState::Rejected};

using Path = QVector<QPair<double, double>>;

QJsonArray pointsJson(const Path& path, qsizetype from) {
    QJsonArray a;
    for (qsizetype i = from; i < path.size(); ++i)
        a << path[i].first << path[i].second;
    return a;
}

bool readPoints(const QJsonValue& v, Path& out) {
    const QJsonArray a = v.toArray();
    if (a.size() % 2 != 0)
        return false;
    for (qsizetype i = 0; i < a.size(); i += 2) {
        if (!a[i].isDouble() || !a[i + 1].isDouble())
            return false;
        out.push_back({a[i].toDouble(), a[i + 1].toDouble()});
    }
    return true;
}

// The smallest number of points dropped from the front of `before` after which `now` continues it (its
// start equals the rest of `before`); -1 when none does.
qsizetype continuation(const Path& before, const Path& now) {
    if (before.isEmpty())
        return 0;
    if (now.isEmpty())
        return -1;
    for (auto from = std::find(before.begin(), before.end(), now.front()); from != before.end();
         from = std::find(from + 1, before.end(), now.front())) {
        if (before.end() - from <= now.size() && std::equal(from, before.end(), now.begin()))
            return from - before.begin();
    }
    return -1;
}

void putOptional(QJsonObject& o, const QString& key, const std::optional<double>& v) {
    if (v)
        o[key] = *v;
}

} // namespace

bool onlyProgressDiffers(JausMission a, const JausMission& b) {
    a.distanceToGoM = b.distanceToGoM;
    a.etaS = b.etaS;
    a.drivenPath = b.drivenPath;
    return a == b;
}

std::optional<MissionState> missionStateFromText(const QString& text) {
    for (MissionState s : kStates)
        if (toText(s) == text)
            return s;
    return std::nullopt;
}

QJsonObject missionJson(const JausMission& m) {
    QJsonObject o{{QStringLiteral("state"), toText(m.state)},
                  {QStringLiteral("waypoints"), int(m.waypoints.size())},
                  {QStringLiteral("global"), m.global},
                  {QStringLiteral("ours"), m.ours}};
    if (m.activeIndex >= 0)
        o[QStringLiteral("active_waypoint")] = m.activeIndex + 1;
    if (m.state == MissionState::Lost && m.lastSeenIndex >= 0)
        o[QStringLiteral("last_seen_waypoint")] = m.lastSeenIndex + 1;
    putOptional(o, QStringLiteral("distance_to_go_m"), m.distanceToGoM);
    putOptional(o, QStringLiteral("eta_s"), m.etaS);
    if (!m.reason.isEmpty())
        o[QStringLiteral("reason")] = m.reason;
    if (!m.drivenPath.isEmpty()) {
        o[QStringLiteral("path_source")] = m.pathSource;
        o[QStringLiteral("path_points")] = int(m.drivenPath.size());
    }
    return o;
}

QByteArray encodeMissionRecord(const JausMission& before, const JausMission& now) {
    QJsonObject o{{QStringLiteral("state"), toText(now.state)},
                  {QStringLiteral("global"), now.global},
                  {QStringLiteral("active"), now.activeIndex},
                  {QStringLiteral("last_seen"), now.lastSeenIndex},
                  {QStringLiteral("ours"), now.ours},
                  {QStringLiteral("reason"), now.reason},
                  {QStringLiteral("path_source"), now.pathSource}};
    putOptional(o, QStringLiteral("dist"), now.distanceToGoM);
    putOptional(o, QStringLiteral("eta"), now.etaS);
    if (now.waypoints != before.waypoints) {
        QJsonArray w;
        for (const MissionWaypoint& p : now.waypoints)
            w << QJsonArray{p.lat, p.lon, p.speed, p.tolerance};
        o[QStringLiteral("waypoints")] = w;
    }
    if (now.drivenPath != before.drivenPath) {
        const qsizetype drop = continuation(before.drivenPath, now.drivenPath);
        if (drop < 0) {
            o[QStringLiteral("path")] = pointsJson(now.drivenPath, 0);
        } else {
            if (drop > 0)
                o[QStringLiteral("path_drop")] = double(drop);
            o[QStringLiteral("path_add")] = pointsJson(now.drivenPath, before.drivenPath.size() - drop);
        }
    }
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

bool applyMissionRecord(JausMission& mission, const QByteArray& record) {
    const QJsonDocument doc = QJsonDocument::fromJson(record);
    if (!doc.isObject())
        return false;
    const QJsonObject o = doc.object();
    const auto state = missionStateFromText(o.value(QStringLiteral("state")).toString());
    if (!state)
        return false;
    JausMission m = mission;
    m.state = *state;
    m.global = o.value(QStringLiteral("global")).toBool();
    m.activeIndex = o.value(QStringLiteral("active")).toInt(-1);
    m.lastSeenIndex = o.value(QStringLiteral("last_seen")).toInt(-1);
    m.ours = o.value(QStringLiteral("ours")).toBool(true);
    m.reason = o.value(QStringLiteral("reason")).toString();
    m.pathSource = o.value(QStringLiteral("path_source")).toString();
    auto optional = [&o](const QString& key) {
        const QJsonValue v = o.value(key);
        return v.isDouble() ? std::optional<double>(v.toDouble()) : std::nullopt;
    };
    m.distanceToGoM = optional(QStringLiteral("dist"));
    m.etaS = optional(QStringLiteral("eta"));
    if (o.contains(QStringLiteral("waypoints"))) {
        m.waypoints.clear();
        for (const QJsonValue& v : o.value(QStringLiteral("waypoints")).toArray()) {
            const QJsonArray p = v.toArray();
            if (p.size() != 4)
                return false;
            m.waypoints.push_back({p[0].toDouble(), p[1].toDouble(), p[2].toDouble(), p[3].toDouble()});
        }
    }
    if (o.contains(QStringLiteral("path"))) {
        m.drivenPath.clear();
        if (!readPoints(o.value(QStringLiteral("path")), m.drivenPath))
            return false;
    } else if (o.contains(QStringLiteral("path_add"))) {
        const qsizetype drop = qsizetype(o.value(QStringLiteral("path_drop")).toDouble(0));
        if (drop < 0 || drop > m.drivenPath.size())
            return false;
        m.drivenPath.remove(0, drop);
        if (!readPoints(o.value(QStringLiteral("path_add")), m.drivenPath))
            return false;
    }
    mission = std::move(m);
    return true;
}

} // namespace ocu
