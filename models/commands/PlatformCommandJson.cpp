#include "models/commands/PlatformCommandJson.h"

#include <QCoreApplication>

#include <cmath>

namespace ocu::platformjson {

namespace {

QString text(const char* source) {
    return QCoreApplication::translate("OperatorCommand", source);
}

const char* const kModes[] = {"standard", "training", "maintenance"};
const char* const kStates[] = {"initialize",   "operational", "shutdown",
                               "system_abort", "emergency",   "render_useless"};

// The machine id, or why not: the first problem wins.
ParsedCommand done(OperatorCommand command, const QString& error, const QJsonObject& json) {
    if (error.isEmpty())
        return {std::move(command), {}, {}};
    return {std::nullopt, error, json.value(QStringLiteral("id")).toString()};
}

QString idOf(const QJsonObject& json, QString& error) {
    const QString id = json.value(QStringLiteral("id")).toString();
    if (id.isEmpty())
        error = QStringLiteral("missing \"id\"");
    return id;
}

// A name from `names` (its index) or, for modes, a number 175-255.
std::optional<int> choice(const QJsonValue& v, const char* const* names, int count, bool programRange) {
    for (int i = 0; i < count; ++i)
        if (v.toString() == QLatin1String(names[i]))
            return i;
    if (v.isDouble()) {
        const double d = v.toDouble();
        const bool whole = std::floor(d) == d;
        if (whole && d >= 0 && d < count)
            return int(d);
        if (whole && programRange && d >= 175 && d <= 255)
            return int(d);
    }
    return std::nullopt;
}

} // namespace

QStringList names() {
    return {QStringLiteral("platform_mode"), QStringLiteral("platform_state"), QStringLiteral("lights"),
            QStringLiteral("odometry")};
}

bool isPlatformCommand(const QString& name) {
    return names().contains(name);
}

void addArguments(QJsonObject& o, const SetPlatformMode& c) {
    o[QStringLiteral("id")] = c.id;
    if (c.mode >= 0 && c.mode < 3)
        o[QStringLiteral("mode")] = QLatin1String(kModes[c.mode]);
    else
        o[QStringLiteral("mode")] = c.mode;
}

void addArguments(QJsonObject& o, const SetPlatformState& c) {
    o[QStringLiteral("id")] = c.id;
    if (c.state >= 0 && c.state < 6)
        o[QStringLiteral("state")] = QLatin1String(kStates[c.state]);
    else
        o[QStringLiteral("state")] = c.state;
}

void addArguments(QJsonObject& o, const SetLights& c) {
    o[QStringLiteral("id")] = c.id;
    for (JausLight l : kJausLights)
        if (c.mask & bitOf(l))
            o[jausLightKey(l)] = bool(c.on & bitOf(l));
}

void addArguments(QJsonObject& o, const Odometry& c) {
    o[QStringLiteral("id")] = c.id;
    if (c.resetTrip)
        o[QStringLiteral("reset_trip")] = true;
}

ParsedCommand parse(const QString& name, const QJsonObject& json) {
    QString error;
    const QString id = idOf(json, error);
    if (name == QLatin1String("platform_mode")) {
        const auto mode = choice(json.value(QStringLiteral("mode")), kModes, 3, true);
        if (!mode && error.isEmpty())
            error = text("platform_mode: \"mode\" must be standard, training, maintenance or a program mode "
                         "175-255");
        return done(SetPlatformMode{id, mode.value_or(0)}, error, json);
    }
    if (name == QLatin1String("platform_state")) {
        const auto state = choice(json.value(QStringLiteral("state")), kStates, 6, false);
        if (!state && error.isEmpty())
            error = text("platform_state: \"state\" must be initialize, operational, shutdown, system_abort, "
                         "emergency or render_useless");
        return done(SetPlatformState{id, state.value_or(1)}, error, json);
    }
    if (name == QLatin1String("lights")) {
        SetLights c{id, 0, 0};
        for (JausLight l : kJausLights) {
            const QJsonValue v = json.value(jausLightKey(l));
            if (v.isUndefined())
                continue;
            if (!v.isBool() && error.isEmpty())
                error = text("lights: \"%1\" must be true or false").arg(jausLightKey(l));
            c.mask |= bitOf(l);
            if (v.toBool())
                c.on |= bitOf(l);
        }
        if (json.contains(QStringLiteral("visible_light")) && error.isEmpty())
            error =
                text("lights: the whole vehicle's visible-light source is never switched from the console "
                     "(AEP-4818 §9.2.2)");
        if (c.mask == 0 && error.isEmpty())
            error = text("lights: name at least one of headlights, running_lights, left_turn_signal, "
                         "right_turn_signal, brake_lights, ir_light (true or false)");
        return done(c, error, json);
    }
    const QJsonValue reset = json.value(QStringLiteral("reset_trip"));
    if (!reset.isUndefined() && !reset.isBool() && error.isEmpty())
        error = text("odometry: \"reset_trip\" must be true or false");
    return done(Odometry{id, reset.toBool(false)}, error, json);
}

} // namespace ocu::platformjson
