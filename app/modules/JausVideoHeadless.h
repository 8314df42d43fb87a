#pragma once
// Headless video of the JAUS vehicles: local entries of the headless monitor's table
// (app/HeadlessCommands.h), answered from what is actually decoded here.
//   {"cmd":"video_play","id":"jaus:126","sensor":1000}  plays a camera (no "sensor": the first one; no "id":
//                                                       the first camera of every vehicle)
//   {"cmd":"video_stop","id":..,"sensor":..}             stops (no "id": all)
//   {"cmd":"video_status"[,"id":..]}                     per vehicle its cameras (announced or configured)
//   and,
//     for each, "state" (idle when this console does not play it, connecting, playing, lost, reconnecting),
//     "width", "height", "fps", "frame_age_ms" (capture time from the frame's time code when present:
//     "age_source":"timecode", else "arrival"), "frames", "decode_ms_per_frame", "reconnects", "error".
#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QPointer>

namespace ocu {

class HeadlessCommands;
class JausVehicleBridge;
class VideoPlayer;

class JausVideoHeadless : public QObject {
    Q_OBJECT
public:
    JausVideoHeadless(JausVehicleBridge* bridge, QObject* parent = nullptr);
    // Adds video_status, video_play and video_stop.
    void registerIn(HeadlessCommands& table);

    QJsonObject status(const QJsonObject& cmd) const;
    QJsonObject play(const QJsonObject& cmd);
    QJsonObject stop(const QJsonObject& cmd);

private:
    static quint32 key(quint16 subsystem, quint16 sensor) { return (quint32(subsystem) << 16) | sensor; }
    QPointer<JausVehicleBridge> m_bridge;
    QHash<quint32, VideoPlayer*> m_players;
};

} // namespace ocu
