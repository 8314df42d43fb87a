#include "models/MachineJson.h"

namespace ocu {

QJsonObject machineStateJson(const MachineState& m) {
    QJsonObject o;
    o[QStringLiteral("type")] = QStringLiteral("machine");
    o[QStringLiteral("id")] = m.id;
    o[QStringLiteral("protocol")] = toText(m.protocol);
    o[QStringLiteral("name")] = m.name;
    o[QStringLiteral("machine_type")] = m.type;
    if (m.hasPosition) {
        o[QStringLiteral("lat")] = m.lat;
        o[QStringLiteral("lon")] = m.lon;
        o[QStringLiteral("e")] = m.e;
        o[QStringLiteral("n")] = m.n;
        o[QStringLiteral("u")] = m.u;
        o[QStringLiteral("heading")] = m.headingDeg;
    } else {
        o[QStringLiteral("lat")] = QJsonValue::Null;
        o[QStringLiteral("lon")] = QJsonValue::Null;
        o[QStringLiteral("e")] = QJsonValue::Null;
        o[QStringLiteral("n")] = QJsonValue::Null;
        o[QStringLiteral("heading")] = QJsonValue::Null;
    }
    o[QStringLiteral("speed")] = m.speed;
    o[QStringLiteral("state")] = m.modeText.isEmpty() ? toText(m.mode) : m.modeText;
    o[QStringLiteral("mode")] = toText(m.mode);
    o[QStringLiteral("stop")] = toText(m.stop);
    if (!m.stopText.isEmpty())
        o[QStringLiteral("stop_text")] = m.stopText;
    o[QStringLiteral("controller")] =
        m.controller.isEmpty() ? QJsonValue(QJsonValue::Null) : QJsonValue(m.controller);
    o[QStringLiteral("control")] = toText(m.control);
    o[QStringLiteral("health")] = toText(m.health);
    if (!m.healthText.isEmpty())
        o[QStringLiteral("health_text")] = m.healthText;
    if (!m.workText.isEmpty())
        o[QStringLiteral("work")] = m.workText;
    o[QStringLiteral("link")] = toText(m.link);
    return o;
}

} // namespace ocu
