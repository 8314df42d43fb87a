#include "models/commands/OperatorCommand.h"

#include "models/commands/PlatformCommandJson.h"

#include <QCoreApplication>

#include <cmath>

namespace ocu {

namespace {

QString text(const char* source) {
    return QCoreApplication::translate("OperatorCommand", source);
}
QString
dispatchText(const char* source) { // the assign arguments' texts, as the dispatch translations name them
    return QCoreApplication::translate("IsoDispatch", source);
}

const char* managementName(ManagementAction a) {
    switch (a) {
    case ManagementAction::Resume:
        return "resume";
    case ManagementAction::Standby:
        return "standby";
    case ManagementAction::Shutdown:
        return "shutdown";
    case ManagementAction::Reset:
        return "reset";
    }
    return "resume";
}

QString modeName(TimedDrive::Mode m) {
    return m == TimedDrive::Mode::Effort ? QStringLiteral("effort") : QStringLiteral("velocity");
}

// A JSON number that is an integer way/spot id within ±2^53.
std::optional<qint64> wholeNumber(const QJsonValue& v) {
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (!std::isfinite(d) || std::floor(d) != d || std::fabs(d) > 9007199254740992.0)
        return std::nullopt;
    return static_cast<qint64>(d);
}

void putIfSet(QJsonObject& o, const char* key, const QString& value) {
    if (!value.isEmpty())
        o[QLatin1String(key)] = value;
}

// Reads the JSON arguments of one command; the first problem wins.
class Args {
public:
    Args(const QString& name, const QJsonObject& args) : m_name(name), m_args(args) {}

    // A string argument; absent = empty. Not a string: a problem.
    QString string(const char* key) {
        const QJsonValue v = m_args.value(QLatin1String(key));
        if (v.isUndefined() || v.isNull())
            return {};
        if (!v.isString())
            fail(text("%1: \"%2\" must be a string").arg(m_name, QLatin1String(key)));
        return v.toString();
    }
    // The machine id every per-machine command needs.
    QString id() {
        const QString id = string("id");
        if (id.isEmpty() && m_error.isEmpty())
            m_error = QStringLiteral("missing \"id\"");
        return id;
    }
    // A number argument; absent = `otherwise`.
    double number(const char* key, double otherwise) {
        const QJsonValue v = m_args.value(QLatin1String(key));
        if (v.isUndefined() || v.isNull())
            return otherwise;
        if (!v.isDouble()) {
            fail(text("%1: \"%2\" must be a number").arg(m_name, QLatin1String(key)));
            return otherwise;
        }
        return v.toDouble();
    }
    void fail(const QString& why) {
        if (m_error.isEmpty())
            m_error = why;
    }
    // The command, or why not (with the machine it named, when it named one).
    ParsedCommand done(OperatorCommand command) const {
        if (m_error.isEmpty())
            return {std::move(command), {}, {}};
        return {std::nullopt, m_error, m_args.value(QStringLiteral("id")).toString()};
    }

private:
    QString m_name;
    const QJsonObject& m_args;
    QString m_error;
};

ParsedCommand parseDrive(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    TimedDrive d;
    d.id = a.id();
    const QString mode = a.string("mode");
    if (mode == QLatin1String("effort"))
        d.mode = TimedDrive::Mode::Effort;
    else if (!mode.isEmpty() && mode != QLatin1String("velocity"))
        a.fail(text("drive: \"mode\" must be \"velocity\" or \"effort\""));
    d.linear = a.number("linear", 0);
    d.angular = a.number("angular", 0);
    d.durationS = a.number("duration", 1.0);
    return a.done(d);
}

ParsedCommand parseAssign(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    Assign c;
    c.id = a.id();
    QString why;
    if (auto tasks = tasksFromJson(json, &why))
        c.tasks = *tasks;
    else
        a.fail(dispatchText("assign refused: %1; nothing sent").arg(why));
    return a.done(c);
}

ParsedCommand parseMissionUpload(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    MissionUpload c;
    c.id = a.id();
    const QJsonValue list = json.value(QStringLiteral("waypoints"));
    if (!list.isArray() || list.toArray().isEmpty())
        a.fail(text("mission_upload: \"waypoints\" must be a non-empty array of {\"lat\", \"lon\"} (or a "
                    "\"file\" with a GeoJSON route)"));
    for (const QJsonValue& v : list.toArray()) {
        QString why;
        if (auto w = waypointFromJson(v, &why))
            c.waypoints << *w;
        else
            a.fail(text("mission_upload: waypoint %1: %2").arg(c.waypoints.size() + 1).arg(why));
    }
    const QJsonValue global = json.value(QStringLiteral("global"));
    if (global.isBool())
        c.global = global.toBool();
    else if (!global.isUndefined() && !global.isNull())
        a.fail(text("mission_upload: \"global\" must be true or false"));
    return a.done(c);
}

ParsedCommand parseGoTo(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    GoTo c;
    c.id = a.id();
    QString why;
    if (auto w = waypointFromJson(json, &why))
        c.waypoint = *w;
    else
        a.fail(text("goto: %1").arg(why));
    return a.done(c);
}

// handoff_request {"id", "reason", "cancel"}; handoff_answer {"id", "request": queue ID, "accept": bool} or
// {"id", "request", "wait": true} (WAIT: "accept" is not asked for then).
ParsedCommand parseHandoff(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    const QString id = a.id();
    auto flag = [&](const char* key, bool required) {
        const QJsonValue v = json.value(QLatin1String(key));
        if ((v.isUndefined() && required) || (!v.isUndefined() && !v.isBool()))
            a.fail(text("%1: \"%2\" must be true or false").arg(name, QLatin1String(key)));
        return v.toBool(false);
    };
    if (name == QLatin1String("handoff_request")) {
        HandoffRequest c{id, a.string("reason"), flag("cancel", false)};
        if (c.reason.toUtf8().size() > 200)
            a.fail(text("handoff_request: \"reason\" is longer than 200 bytes"));
        return a.done(c);
    }
    HandoffAnswer c;
    c.id = id;
    const double request = a.number("request", -1);
    if (!(request >= 0 && request <= 255 && std::floor(request) == request))
        a.fail(text("handoff_answer: \"request\" must be the request's number (0-255)"));
    c.requestId = int(request);
    c.wait = flag("wait", false);
    c.accept = !c.wait && flag("accept", true);
    return a.done(c);
}

template <class LinkCommand> ParsedCommand parseLinkCommand(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    LinkCommand c;
    c.link = a.string("link");
    c.id = a.string("id");
    return a.done(c);
}

} // namespace

QString commandName(const OperatorCommand& command) {
    return std::visit(Overloaded{
                          [](const StopAll&) { return QStringLiteral("stop_all"); },
                          [](const StopMachine&) { return QStringLiteral("stop"); },
                          [](const ClearStop&) { return QStringLiteral("clear_stop"); },
                          [](const RequestControl&) { return QStringLiteral("request_control"); },
                          [](const ReleaseControl&) { return QStringLiteral("release_control"); },
                          [](const ReleaseAll&) { return QStringLiteral("release_all"); },
                          [](const Management& m) { return QString::fromLatin1(managementName(m.action)); },
                          [](const DriveStart&) { return QStringLiteral("drive_start"); },
                          [](const DriveStop&) { return QStringLiteral("drive_stop"); },
                          [](const TimedDrive&) { return QStringLiteral("drive"); },
                          [](const AllStopApply&) { return QStringLiteral("all_stop_apply"); },
                          [](const AllStopRemove&) { return QStringLiteral("all_stop_remove"); },
                          [](const FetchMap&) { return QStringLiteral("fetch_map"); },
                          [](const Assign&) { return QStringLiteral("assign"); },
                          [](const ResetAssignment&) { return QStringLiteral("reset_assignment"); },
                          [](const SendText&) { return QStringLiteral("send_text"); },
                          [](const PingStation&) { return QStringLiteral("ping"); },
                          [](const MissionUpload&) { return QStringLiteral("mission_upload"); },
                          [](const MissionStart&) { return QStringLiteral("mission_start"); },
                          [](const MissionPause&) { return QStringLiteral("mission_pause"); },
                          [](const MissionResume&) { return QStringLiteral("mission_resume"); },
                          [](const MissionAbort&) { return QStringLiteral("mission_abort"); },
                          [](const GoTo&) { return QStringLiteral("goto"); },
                          [](const SetPlatformMode&) { return QStringLiteral("platform_mode"); },
                          [](const SetPlatformState&) { return QStringLiteral("platform_state"); },
                          [](const SetLights&) { return QStringLiteral("lights"); },
                          [](const Odometry&) { return QStringLiteral("odometry"); },
                          [](const HandoffRequest&) { return QStringLiteral("handoff_request"); },
                          [](const HandoffAnswer&) { return QStringLiteral("handoff_answer"); },
                      },
                      command);
}

CommandRoute commandRoute(const OperatorCommand& command) {
    auto machineOr = [](const QString& id, Protocol p) {
        return id.isEmpty() ? CommandRoute{false, {}, p} : CommandRoute{false, id, std::nullopt};
    };
    return std::visit(Overloaded{
                          [](const StopAll&) {
                              return CommandRoute{true, {}, std::nullopt};
                          },
                          [](const ReleaseAll&) {
                              return CommandRoute{false, {}, Protocol::Jaus};
                          },
                          [&](const AllStopApply& c) { return machineOr(c.id, Protocol::Iso23725); },
                          [&](const AllStopRemove& c) { return machineOr(c.id, Protocol::Iso23725); },
                          [&](const FetchMap& c) { return machineOr(c.id, Protocol::Iso23725); },
                          [&](const SendText& c) { return machineOr(c.id, Protocol::Osyris); },
                          [](const PingStation&) {
                              return CommandRoute{false, {}, Protocol::Osyris};
                          },
                          [](const auto& c) {
                              return CommandRoute{false, c.id, std::nullopt};
                          },
                      },
                      command);
}

QJsonObject toJson(const OperatorCommand& command) {
    QJsonObject o;
    o[QStringLiteral("cmd")] = commandName(command);
    std::visit(Overloaded{
                   [](const StopAll&) {},
                   [&](const ClearStop& c) {
                       o[QStringLiteral("id")] = c.id;
                       o[QStringLiteral("confirm")] = c.confirm;
                   },
                   [&](const ReleaseAll&) { o[QStringLiteral("protocol")] = toText(Protocol::Jaus); },
                   [&](const DriveStart& c) {
                       o[QStringLiteral("id")] = c.id;
                       putIfSet(o, "reason", c.reason);
                   },
                   [&](const DriveStop& c) {
                       o[QStringLiteral("id")] = c.id;
                       putIfSet(o, "reason", c.reason);
                   },
                   [&](const TimedDrive& c) {
                       o[QStringLiteral("id")] = c.id;
                       o[QStringLiteral("mode")] = modeName(c.mode);
                       o[QStringLiteral("linear")] = c.linear;
                       o[QStringLiteral("angular")] = c.angular;
                       o[QStringLiteral("duration")] = c.durationS;
                   },
                   [&](const AllStopApply& c) {
                       putIfSet(o, "link", c.link);
                       putIfSet(o, "id", c.id);
                   },
                   [&](const AllStopRemove& c) {
                       putIfSet(o, "link", c.link);
                       putIfSet(o, "id", c.id);
                   },
                   [&](const FetchMap& c) {
                       putIfSet(o, "link", c.link);
                       putIfSet(o, "id", c.id);
                   },
                   [&](const Assign& c) {
                       o[QStringLiteral("id")] = c.id;
                       o[QStringLiteral("tasks")] = tasksToJson(c.tasks);
                   },
                   [&](const SendText& c) {
                       putIfSet(o, "id", c.id);
                       if (c.id.isEmpty())
                           o[QStringLiteral("protocol")] = toText(Protocol::Osyris);
                       o[QStringLiteral("text")] = c.text;
                   },
                   [&](const PingStation& c) { o[QStringLiteral("idx")] = c.idx; },
                   [&](const MissionUpload& c) {
                       o[QStringLiteral("id")] = c.id;
                       QJsonArray list;
                       for (const MissionWaypoint& w : c.waypoints)
                           list << waypointToJson(w);
                       o[QStringLiteral("waypoints")] = list;
                       if (c.global)
                           o[QStringLiteral("global")] = *c.global;
                   },
                   [&](const MissionStart& c) {
                       o[QStringLiteral("id")] = c.id;
                       o[QStringLiteral("from_index")] = c.fromIndex;
                   },
                   [&](const GoTo& c) {
                       o = waypointToJson(c.waypoint);
                       o[QStringLiteral("cmd")] = QStringLiteral("goto");
                       o[QStringLiteral("id")] = c.id;
                   },
                   [&](const SetPlatformMode& c) { platformjson::addArguments(o, c); },
                   [&](const SetPlatformState& c) { platformjson::addArguments(o, c); },
                   [&](const SetLights& c) { platformjson::addArguments(o, c); },
                   [&](const Odometry& c) { platformjson::addArguments(o, c); },
                   [&](const HandoffRequest& c) {
                       o[QStringLiteral("id")] = c.id;
                       putIfSet(o, "reason", c.reason);
                       if (c.cancel)
                           o[QStringLiteral("cancel")] = true;
                   },
                   [&](const HandoffAnswer& c) {
                       o[QStringLiteral("id")] = c.id;
                       o[QStringLiteral("request")] = c.requestId;
                       if (c.wait)
                           o[QStringLiteral("wait")] = true;
                       else
                           o[QStringLiteral("accept")] = c.accept;
                   },
                   [&](const auto& c) { o[QStringLiteral("id")] = c.id; }, // machine commands
               },
               command);
    return o;
}

bool isOperatorCommand(const QString& name) {
    static const QStringList names{QStringLiteral("stop_all"),        QStringLiteral("stop"),
                                   QStringLiteral("clear_stop"),      QStringLiteral("request_control"),
                                   QStringLiteral("release_control"), QStringLiteral("release_all"),
                                   QStringLiteral("resume"),          QStringLiteral("standby"),
                                   QStringLiteral("shutdown"),        QStringLiteral("reset"),
                                   QStringLiteral("drive_start"),     QStringLiteral("drive_stop"),
                                   QStringLiteral("drive"),           QStringLiteral("all_stop_apply"),
                                   QStringLiteral("all_stop_remove"), QStringLiteral("fetch_map"),
                                   QStringLiteral("assign"),          QStringLiteral("reset_assignment"),
                                   QStringLiteral("send_text"),       QStringLiteral("ping"),
                                   QStringLiteral("mission_upload"),  QStringLiteral("mission_start"),
                                   QStringLiteral("mission_pause"),   QStringLiteral("mission_resume"),
                                   QStringLiteral("mission_abort"),   QStringLiteral("goto"),
                                   QStringLiteral("handoff_request"), QStringLiteral("handoff_answer")};
    return names.contains(name) || platformjson::isPlatformCommand(name);
}

ParsedCommand parseOperatorCommand(const QString& name, const QJsonObject& json) {
    Args a(name, json);
    if (name == QLatin1String("stop_all"))
        return a.done(StopAll{});
    if (name == QLatin1String("stop"))
        return a.done(StopMachine{a.id()});
    if (name == QLatin1String("clear_stop")) {
        ClearStop c{a.id(), false, {}};
        const QJsonValue confirm = json.value(QStringLiteral("confirm"));
        if (!confirm.isUndefined() && !confirm.isBool())
            a.fail(text("clear_stop: \"confirm\" must be true or false"));
        c.confirm = confirm.toBool(false);
        return a.done(c);
    }
    if (name == QLatin1String("request_control"))
        return a.done(RequestControl{a.id()});
    if (name == QLatin1String("release_control"))
        return a.done(ReleaseControl{a.id()});
    if (name == QLatin1String("release_all")) {
        const QString protocol = a.string("protocol");
        if (!protocol.isEmpty() && protocolFromString(protocol) != Protocol::Jaus)
            a.fail(text("release_all: only JAUS vehicles are controlled (\"protocol\": \"jaus\")"));
        return a.done(ReleaseAll{});
    }
    for (ManagementAction m : {ManagementAction::Resume, ManagementAction::Standby,
                               ManagementAction::Shutdown, ManagementAction::Reset})
        if (name == QLatin1String(managementName(m)))
            return a.done(Management{a.id(), m});
    if (name == QLatin1String("drive_start") || name == QLatin1String("drive_stop")) {
        const QString id = a.id();
        const QString reason = a.string("reason");
        return name == QLatin1String("drive_start") ? a.done(DriveStart{id, reason})
                                                    : a.done(DriveStop{id, reason});
    }
    if (name == QLatin1String("drive"))
        return parseDrive(name, json);
    if (name == QLatin1String("all_stop_apply"))
        return parseLinkCommand<AllStopApply>(name, json);
    if (name == QLatin1String("all_stop_remove"))
        return parseLinkCommand<AllStopRemove>(name, json);
    if (name == QLatin1String("fetch_map"))
        return parseLinkCommand<FetchMap>(name, json);
    if (name == QLatin1String("assign"))
        return parseAssign(name, json);
    if (name == QLatin1String("reset_assignment"))
        return a.done(ResetAssignment{a.id()});
    if (name == QLatin1String("send_text")) {
        SendText c;
        c.id = a.string("id");
        c.text = a.string("text");
        return a.done(c);
    }
    if (name == QLatin1String("ping")) {
        const double idx = a.number("idx", -1);
        if (!(idx >= 0 && idx <= 253 && std::floor(idx) == idx))
            a.fail(text("ping: \"idx\" must be a station index 0-253"));
        return a.done(PingStation{int(idx)});
    }
    if (name == QLatin1String("mission_upload"))
        return parseMissionUpload(name, json);
    if (name == QLatin1String("mission_start")) {
        MissionStart c;
        c.id = a.id();
        const double from = a.number("from_index", 0);
        if (!(from >= 0 && from <= 65533 && std::floor(from) == from))
            a.fail(text("mission_start: \"from_index\" must be a waypoint index (0 = the first)"));
        c.fromIndex = int(from);
        return a.done(c);
    }
    if (name == QLatin1String("mission_pause"))
        return a.done(MissionPause{a.id()});
    if (name == QLatin1String("mission_resume"))
        return a.done(MissionResume{a.id()});
    if (name == QLatin1String("mission_abort"))
        return a.done(MissionAbort{a.id()});
    if (name == QLatin1String("goto"))
        return parseGoTo(name, json);
    if (platformjson::isPlatformCommand(name))
        return platformjson::parse(name, json);
    if (name == QLatin1String("handoff_request") || name == QLatin1String("handoff_answer"))
        return parseHandoff(name, json);
    if (name.isEmpty())
        return {std::nullopt, QStringLiteral("missing \"cmd\""), {}};
    return {std::nullopt, QStringLiteral("unknown command %1").arg(name), {}};
}

QJsonArray tasksToJson(const QVector<AssignTask>& tasks) {
    QJsonArray out;
    for (const auto& t : tasks) {
        QJsonObject o;
        if (!t.assignmentId.isEmpty())
            o[QStringLiteral("assignment_id")] = t.assignmentId;
        o[QStringLiteral("task")] = t.task;
        o[QStringLiteral("destination")] = double(t.destinationId);
        if (!t.destinationEquipmentId.isEmpty())
            o[QStringLiteral("equipment")] = t.destinationEquipmentId;
        if (t.destinationSpotId)
            o[QStringLiteral("spot")] = double(*t.destinationSpotId);
        if (t.route) {
            QJsonArray r;
            for (qint64 w : *t.route)
                r << double(w);
            o[QStringLiteral("route")] = r;
        }
        out << o;
    }
    return out;
}

std::optional<QVector<AssignTask>> tasksFromJson(const QJsonObject& args, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<QVector<AssignTask>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    QJsonArray list;
    if (args.contains(QStringLiteral("tasks"))) {
        if (!args.value(QStringLiteral("tasks")).isArray())
            return fail(dispatchText("\"tasks\" must be an array of tasks"));
        list = args.value(QStringLiteral("tasks")).toArray();
    } else {
        list << args; // single-task shorthand
    }
    if (list.isEmpty())
        return fail(dispatchText("no task given"));
    if (list.size() > 64)
        return fail(dispatchText("at most 64 tasks per request"));
    QVector<AssignTask> out;
    for (int i = 0; i < list.size(); ++i) {
        const QString where = list.size() > 1 || args.contains(QStringLiteral("tasks"))
                                  ? dispatchText("task %1: ").arg(i + 1)
                                  : QString();
        if (!list[i].isObject())
            return fail(where + dispatchText("must be an object"));
        const QJsonObject o = list[i].toObject();
        AssignTask t;
        t.task = o.value(QStringLiteral("task")).toString();
        if (t.task.isEmpty())
            return fail(where + dispatchText("\"task\" missing (Load, Offload, Fuel, Park or Wait)"));
        const auto dest = wholeNumber(o.value(QStringLiteral("destination")));
        if (!dest)
            return fail(where + dispatchText("\"destination\" must be a way id (integer)"));
        t.destinationId = *dest;
        t.assignmentId = o.value(QStringLiteral("assignment_id")).toString();
        t.destinationEquipmentId = o.value(QStringLiteral("equipment")).toString();
        if (o.contains(QStringLiteral("spot"))) {
            const auto spot = wholeNumber(o.value(QStringLiteral("spot")));
            if (!spot)
                return fail(where + dispatchText("\"spot\" must be an integer"));
            t.destinationSpotId = *spot;
        }
        if (o.contains(QStringLiteral("route"))) {
            if (!o.value(QStringLiteral("route")).isArray())
                return fail(where + dispatchText("\"route\" must be an array of way ids"));
            QVector<qint64> r;
            for (const auto& w : o.value(QStringLiteral("route")).toArray()) {
                const auto id = wholeNumber(w);
                if (!id)
                    return fail(where + dispatchText("\"route\" must be an array of way ids"));
                r << *id;
            }
            t.route = r;
        }
        out << t;
    }
    return out;
}

QJsonObject waypointToJson(const MissionWaypoint& w) {
    QJsonObject o;
    o[QStringLiteral("lat")] = w.lat;
    o[QStringLiteral("lon")] = w.lon;
    o[QStringLiteral("speed")] = w.speed;
    o[QStringLiteral("tolerance")] = w.tolerance;
    return o;
}

std::optional<MissionWaypoint> waypointFromJson(const QJsonValue& v, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<MissionWaypoint> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    MissionWaypoint w;
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        if (a.size() < 2 || !a[0].isDouble() || !a[1].isDouble())
            return fail(text("[lat, lon] must be two numbers"));
        w.lat = a[0].toDouble();
        w.lon = a[1].toDouble();
    } else if (v.isObject()) {
        const QJsonObject o = v.toObject();
        if (!o.value(QStringLiteral("lat")).isDouble() || !o.value(QStringLiteral("lon")).isDouble())
            return fail(text("\"lat\" and \"lon\" must be numbers (degrees WGS84)"));
        w.lat = o.value(QStringLiteral("lat")).toDouble();
        w.lon = o.value(QStringLiteral("lon")).toDouble();
        for (const char* key : {"speed", "tolerance"}) {
            const QJsonValue x = o.value(QLatin1String(key));
            if (!x.isUndefined() && !x.isNull() && !(x.isDouble() && x.toDouble() >= 0))
                return fail(text("\"%1\" must be a number, 0 or more").arg(QLatin1String(key)));
        }
        w.speed = o.value(QStringLiteral("speed")).toDouble(0);
        w.tolerance = o.value(QStringLiteral("tolerance")).toDouble(0);
    } else {
        return fail(text("a waypoint is {\"lat\", \"lon\", \"speed\", \"tolerance\"}"));
    }
    if (!(std::fabs(w.lat) <= 90 && std::fabs(w.lon) <= 180))
        return fail(text("latitude must lie within ±90° and longitude within ±180°"));
    if (w.tolerance > 100)
        return fail(text("\"tolerance\" must be at most 100 m (AS6009 waypoint tolerance)"));
    return w;
}

} // namespace ocu
