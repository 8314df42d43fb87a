#pragma once
// Protocol-neutral picture of one machine, filled by a protocol bridge (JAUS, ISO 23725, OSYRIS) and
// consumed by the fleet model, the 2D map, the 3D view and the headless monitor.
// Units are SI (anchors-features.md §8.2): metres, m/s, degrees for heading/lat/lon, times in ms since
// the Unix epoch (UTC).
#include "protocols/common/GeoFrame.h"

#include <QColor>
#include <QMetaType>
#include <QString>
#include <QVector>

namespace ocu {

enum class Protocol { Jaus, Iso23725, Osyris, Other };
enum class LinkState { Unknown, Up, Degraded, Down };
enum class StopState { Unknown, None, Stopped };
enum class HealthLevel { Unknown, Ok, Warning, Fault };
// Autonomy-mode channel (anchors-features.md §8.1/§8.4); the raw protocol text stays in modeText.
enum class ModeCategory { Unknown, Manual, Autonomous, Remote, Idle, Transition, Stopped, Fault, Shutdown };
// JAUS access control seen from this console; other protocols leave it None.
enum class ControlState { None, Monitoring, ControlledByMe, ControlledByOther, Denied };

// What the fleet list and the map colour a machine with (anchors-features.md §8.1).
enum class StatusCategory { Ok, Warning, FaultOrStopped, Stale, Autonomous };

struct MachineState {
    QString id; // protocol-qualified: "jaus:101", "iso23725:<hid>", "osyris:3"
    Protocol protocol = Protocol::Other;
    QString name; // call sign / HID / mission id
    QString type; // equipment type: "haul truck", "UGV", "roller", "paver", ...

    LinkState link = LinkState::Unknown;
    qint64 lastDataMs = 0; // when this console last received data about the machine

    bool hasPosition = false;
    double e = 0, n = 0, u = 0;               // local ENU in the site frame (m)
    double lat = 0, lon = 0;                  // WGS84 degrees
    double headingDeg = 0;                    // 0 = north, clockwise
    double speed = 0;                         // m/s
    double length = 0, width = 0, height = 0; // footprint (m); 0 = unknown

    QString modeText; // raw autonomy mode / management state
    ModeCategory mode = ModeCategory::Unknown;

    StopState stop = StopState::Unknown; // as reported by the machine, never what we asked
    QString stopText;                    // e.g. "emergency", "all-stop"

    QString controller; // JAUS: component id of the controlling client
    ControlState control = ControlState::None;

    HealthLevel health = HealthLevel::Unknown;
    QString healthText;

    // What the machine is doing for production (ISO 23725 haul trucks: production state, way, payload,
    // body and brake sensors, assignment); empty when the protocol reports nothing of the kind.
    QString workText;

    qint64 lastMessageMs = 0; // timestamp of the last message as the machine stamped it (0 = unknown)

    bool operator==(const MachineState&) const = default;
};

QString toText(Protocol p); // "jaus", "iso23725", "osyris", "other"
Protocol protocolFromString(const QString& s);
QString toText(LinkState s);        // "up", "degraded", "down", "unknown"
QString toText(StopState s);        // "none", "stopped", "unknown"
QString toText(HealthLevel h);      // "ok", "warning", "fault", "unknown"
QString toText(ModeCategory m);     // "manual", "autonomous", ...
QString toText(ControlState c);     // "none", "monitoring", "me", "other", "denied"
QString toText(StatusCategory c);   // "ok", "warning", "fault", "stale", "autonomous"
QString protocolPrefix(Protocol p); // "jaus:" ...
Protocol protocolOfId(const QString& id);

// Status precedence: stale/no comms (grey) > fault or stopped (red) > warning/degraded (amber) >
// autonomous (blue) > OK (green).
StatusCategory statusOf(const MachineState& m, bool stale);
QColor statusColor(StatusCategory c);

// A position fix as a row shows it: the point in the site frame and the same point in WGS84.
inline void placeAt(MachineState& m, const EnuPoint& site, const GeoPoint& wgs84) {
    m.hasPosition = true;
    m.e = site.e;
    m.n = site.n;
    m.u = site.u;
    m.lat = wgs84.lat;
    m.lon = wgs84.lon;
}

} // namespace ocu

Q_DECLARE_METATYPE(ocu::MachineState)
