#include "app/modules/JausVideoHeadless.h"

#include "app/HeadlessCommands.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/video/VideoPlayer.h"

#include <QJsonArray>

namespace ocu {

namespace {
QJsonObject failure(const QString& message) {
    return {{QStringLiteral("ok"), false}, {QStringLiteral("message"), message}};
}
} // namespace

JausVideoHeadless::JausVideoHeadless(JausVehicleBridge* bridge, QObject* parent)
    : QObject(parent), m_bridge(bridge) {}

void JausVideoHeadless::registerIn(HeadlessCommands& table) {
    QPointer<JausVideoHeadless> self(this);
    const auto gone = [] { return failure(QStringLiteral("no JAUS bridge")); };
    table.addLocal(QStringLiteral("video_status"),
                   [self, gone](const QJsonObject& c) { return self ? self->status(c) : gone(); });
    table.addLocal(QStringLiteral("video_play"),
                   [self, gone](const QJsonObject& c) { return self ? self->play(c) : gone(); });
    table.addLocal(QStringLiteral("video_stop"),
                   [self, gone](const QJsonObject& c) { return self ? self->stop(c) : gone(); });
}

QJsonObject JausVideoHeadless::status(const QJsonObject& cmd) const {
    if (!m_bridge)
        return failure(QStringLiteral("no JAUS bridge"));
    const QString id = cmd.value(QStringLiteral("id")).toString();
    QJsonArray vehicles;
    int streams = 0, playing = 0;
    for (quint16 sub : m_bridge->subsystems()) {
        if (!id.isEmpty() && JausVehicleBridge::machineId(sub) != id)
            continue;
        const auto v = m_bridge->subsystem(sub);
        if (!v)
            continue;
        QJsonArray cams;
        for (const JausVideoEndpoint& e : v->videoEndpoints) {
            QJsonObject o{
                {QStringLiteral("sensor"), e.sensorId},  {QStringLiteral("resource"), e.resourceId},
                {QStringLiteral("name"), e.name},        {QStringLiteral("url"), e.url},
                {QStringLiteral("pan_tilt"), e.panTilt}, {QStringLiteral("configured"), e.configured}};
            ++streams;
            VideoPlayer* p = m_players.value(key(sub, e.sensorId));
            if (!p || p->url() != e.url) {
                o[QStringLiteral("state")] = QStringLiteral("idle");
                cams.append(o);
                continue;
            }
            const VideoStatus s = p->status();
            o[QStringLiteral("state")] = videoStateKey(s.state);
            if (s.state == VideoState::Playing)
                ++playing;
            if (s.frames) {
                o[QStringLiteral("width")] = s.resolution.width();
                o[QStringLiteral("height")] = s.resolution.height();
                o[QStringLiteral("fps")] = std::round(s.fps * 10) / 10;
                if (s.frameAgeMs)
                    o[QStringLiteral("frame_age_ms")] = qint64(*s.frameAgeMs);
                o[QStringLiteral("age_source")] =
                    s.ageFromTimeCode ? QStringLiteral("timecode") : QStringLiteral("arrival");
                o[QStringLiteral("decode_ms_per_frame")] = std::round(s.decodeMsPerFrame * 100) / 100;
            }
            o[QStringLiteral("frames")] = qint64(s.frames);
            o[QStringLiteral("reconnects")] = s.reconnects;
            if (!s.error.isEmpty())
                o[QStringLiteral("error")] = s.error;
            cams.append(o);
        }
        vehicles.append(QJsonObject{{QStringLiteral("id"), JausVehicleBridge::machineId(sub)},
                                    {QStringLiteral("name"), v->callSign},
                                    {QStringLiteral("streams"), cams}});
    }
    return {{QStringLiteral("ok"), true},
            {QStringLiteral("message"), QStringLiteral("%1 streams, %2 playing").arg(streams).arg(playing)},
            {QStringLiteral("vehicles"), vehicles}};
}

QJsonObject JausVideoHeadless::play(const QJsonObject& cmd) {
    if (!m_bridge)
        return failure(QStringLiteral("no JAUS bridge"));
    QString why;
    if (!VideoPlayer::available(&why))
        return failure(why);
    const QString id = cmd.value(QStringLiteral("id")).toString();
    const bool anySensor = !cmd.contains(QStringLiteral("sensor"));
    const int sensor = cmd.value(QStringLiteral("sensor")).toInt(-1);
    if (!id.isEmpty() && !JausVehicleBridge::subsystemOf(id))
        return failure(QStringLiteral("not a JAUS vehicle: %1").arg(id));
    QStringList started;
    for (quint16 sub : m_bridge->subsystems()) {
        if (!id.isEmpty() && JausVehicleBridge::machineId(sub) != id)
            continue;
        const auto v = m_bridge->subsystem(sub);
        if (!v)
            continue;
        for (const JausVideoEndpoint& e : v->videoEndpoints) {
            if (!anySensor && e.sensorId != sensor)
                continue;
            VideoPlayer*& p = m_players[key(sub, e.sensorId)];
            if (!p)
                p = new VideoPlayer(this);
            p->setUrl(e.url);
            p->play();
            started << QStringLiteral("%1/%2").arg(JausVehicleBridge::machineId(sub)).arg(e.sensorId);
            if (anySensor)
                break; // the first camera of the vehicle
        }
    }
    if (started.isEmpty())
        return failure(id.isEmpty() ? QStringLiteral("no vehicle announces a camera")
                                    : QStringLiteral("%1 has no such camera").arg(id));
    return {
        {QStringLiteral("ok"), true},
        {QStringLiteral("message"), QStringLiteral("playing %1").arg(started.join(QStringLiteral(", ")))}};
}

QJsonObject JausVideoHeadless::stop(const QJsonObject& cmd) {
    const QString id = cmd.value(QStringLiteral("id")).toString();
    const int sensor = cmd.value(QStringLiteral("sensor")).toInt(-1);
    int stopped = 0;
    for (auto it = m_players.begin(); it != m_players.end();) {
        const quint16 sub = quint16(it.key() >> 16), sen = quint16(it.key() & 0xffff);
        if ((id.isEmpty() || JausVehicleBridge::machineId(sub) == id) && (sensor < 0 || sen == sensor)) {
            delete it.value();
            it = m_players.erase(it);
            ++stopped;
        } else {
            ++it;
        }
    }
    return {{QStringLiteral("ok"), stopped > 0},
            {QStringLiteral("message"), QStringLiteral("%1 stopped").arg(stopped)}};
}

} // namespace ocu
