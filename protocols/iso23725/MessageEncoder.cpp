// Encoding of ISO 23725 messages: the header and every member as the catalogue names its fields (§5), unknown
// members written back verbatim.
#include "protocols/iso23725/Messages.h"

#include <chrono>

namespace ocu::iso23725 {

using nlohmann::json;

namespace {

json num(const std::optional<double>& v) {
    return v ? json(*v) : json(nullptr);
}
json num(const std::optional<std::int64_t>& v) {
    return v ? json(*v) : json(nullptr);
}
json ts(const Timestamp& t) {
    return t.text.empty() && t.unixMs ? json(formatTimestamp(*t.unixMs)) : json(t.text);
}
template <class T> void putOpt(json& o, const char* k, const std::optional<T>& v) {
    if (v)
        o[k] = *v;
}
void putOptTs(json& o, const char* k, const std::optional<Timestamp>& v) {
    if (v)
        o[k] = ts(*v);
}
json guidOrNull(const std::optional<Guid>& g) {
    return g ? json(*g) : json(nullptr);
}

void putPose(json& o, const PoseFields& p) {
    o["Heading"] = num(p.heading);
    o["Latitude"] = num(p.latitude);
    o["Longitude"] = num(p.longitude);
    o["Elevation"] = num(p.elevation);
    o["LatitudeAccuracy"] = num(p.latitudeAccuracy);
    o["LongitudeAccuracy"] = num(p.longitudeAccuracy);
    o["ElevationAccuracy"] = num(p.elevationAccuracy);
    o["HeadingAccuracy"] = num(p.headingAccuracy);
    o["Speed"] = num(p.speed);
}

json wayRefs(const std::vector<WayRef>& v) {
    json a = json::array();
    for (auto& w : v)
        a.push_back({{"WayId", w.wayId}});
    return a;
}

struct Encoder {
    json operator()(const FleetDefinitionV2& m) const {
        json eq = json::array();
        for (auto& e : m.equipment)
            eq.push_back({{"EquipmentId", e.equipmentId},
                          {"HID", e.hid},
                          {"Type", e.type},
                          {"OEM", e.oem},
                          {"Model", e.model},
                          {"Autonomous", e.autonomous},
                          {"Length", num(e.length)},
                          {"Width", num(e.width)}});
        return {{"AHSId", m.ahsId}, {"Equipment", eq}};
    }
    json operator()(const MachineAllStopRequestV1& m) const {
        return {{"ModeAllStop", m.modeAllStop}, {"ModeAllStopId", m.modeAllStopId}};
    }
    json operator()(const MachineAllStopResponseV1& m) const {
        json o = {{"Response", m.response}, {"ModeAllStopId", m.modeAllStopId}};
        putOpt(o, "Detail", m.detail);
        return o;
    }
    json operator()(const MachineAllStopV1& m) const {
        return {{"ModeAllStop", m.modeAllStop}, {"ModeAllStopId", guidOrNull(m.modeAllStopId)}};
    }
    json operator()(const MachinePositionV1& m) const {
        json o = json::object();
        o["Timestamp"] = ts(m.timestamp);
        putPose(o, m.pose);
        if (m.attachment) {
            json a = json::array();
            for (auto& at : *m.attachment) {
                json x = {{"EquipmentId", at.equipmentId}};
                putPose(x, at.pose);
                a.push_back(std::move(x));
            }
            o["Attachment"] = std::move(a);
        }
        return o;
    }
    json operator()(const BasicMachineHealthV2& m) const {
        json o = {{"FuelLevel", num(m.fuelLevel)},
                  {"TotalMachineHour", num(m.totalMachineHour)},
                  {"TotalEngineHour", num(m.totalEngineHour)}};
        if (m.tire) {
            json a = json::array();
            for (auto& t : *m.tire)
                a.push_back({{"TirePosition", t.tirePosition},
                             {"TirePressure", num(t.tirePressure)},
                             {"TireTemperature", num(t.tireTemperature)}});
            o["Tire"] = std::move(a);
        }
        if (m.primeMoverTemp)
            o["PrimeMoverTemp"] = *m.primeMoverTemp;
        return o;
    }
    json operator()(const MachineAutonomyModeV1& m) const { return {{"AutonomyMode", m.autonomyMode}}; }
    json operator()(const MachineDispatchAvailabilityV1& m) const {
        json o = {{"DispatchingCustodian", m.dispatchingCustodian}};
        putOpt(o, "ImpendingCustodian", m.impendingCustodian);
        putOptTs(o, "ImpendingTime", m.impendingTime);
        return o;
    }
    json operator()(const MachineDiagnosticV2& m) const {
        json a = json::array();
        for (auto& d : m.entries)
            a.push_back({{"ComponentId", d.componentId}, {"FaultCode", d.faultCode}});
        return a;
    }
    json operator()(const MapConnectivityV1& m) const {
        json a = json::array();
        for (auto& c : m.items) {
            json o = {{"WayId", c.wayId}, {"WayType", c.wayType}, {"Connection", wayRefs(c.connection)}};
            if (c.wayType == "Road") {
                json p = {{"Length", num(c.roadLength)}};
                putOpt(p, "Name", c.roadName);
                o["RoadProperty"] = p;
            } else {
                json p = {{"DefaultTask", c.areaDefaultTask.value_or("Drive")}};
                putOpt(p, "Name", c.areaName);
                o["AreaProperty"] = p;
            }
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const MapServiceV1& m) const { return {{"API", m.api}}; }
    json operator()(const MapSummaryV1& m) const {
        json o = {{"Timestamp", ts(m.timestamp)},   {"ChangeSetMap", m.changeSetMap},
                  {"ChangeSetWay", m.changeSetWay}, {"NodeCount", m.nodeCount},
                  {"WayCount", m.wayCount},         {"DocumentCount", m.documentCount}};
        putOpt(o, "uid", m.uid);
        return o;
    }
    json operator()(const MapCommandV1& m) const { return {{"Method", m.method}, {"Scope", m.scope}}; }
    json operator()(const InterfaceDiagnosticV1& m) const {
        json me = json::array(), ms = json::array();
        for (auto& x : m.measurement)
            me.push_back({{"Name", x.name}, {"Value", num(x.value)}, {"Unit", x.unit}});
        for (auto& x : m.message) {
            json o = {{"Severity", x.severity}, {"Code", x.code}};
            putOpt(o, "Detail", x.detail);
            putOpt(o, "RefMember", x.refMember);
            putOptTs(o, "RefTimestamp", x.refTimestamp);
            ms.push_back(std::move(o));
        }
        return {{"Measurement", me}, {"Message", ms}};
    }
    json operator()(const HaulTruckProductionCycleV1& m) const {
        json o = {{"CycleId", m.cycleId}, {"LoadWayId", m.loadWayId}, {"DumpWayId", m.dumpWayId}};
        putOpt(o, "AssignmentId", m.assignmentId);
        putOpt(o, "LoaderEquipmentId", m.loaderEquipmentId);
        putOpt(o, "PayloadWeight", m.payloadWeight);
        json st = json::array();
        for (auto& s : m.stateTimes)
            st.push_back({{"ProductionState", s.productionState},
                          {"Start", ts(s.start)},
                          {"Duration", num(s.duration)}});
        o["StateTimes"] = std::move(st);
        return o;
    }
    json operator()(const HaulTruckProductionStateV2& m) const {
        return {{"AssignmentId", guidOrNull(m.assignmentId)},
                {"WayId", num(m.wayId)},
                {"AutonomyMode", m.autonomyMode},
                {"ProductionState", m.productionState}};
    }
    json operator()(const HaulTruckProductionStateSensorV1& m) const {
        json o = json::object();
        putOpt(o, "Loaded", m.loaded);
        putOpt(o, "BodyRaised", m.bodyRaised);
        putOpt(o, "ParkBrake", m.parkBrake);
        putOpt(o, "PayloadWeight", m.payloadWeight);
        putOpt(o, "InLoadArea", m.inLoadArea);
        putOpt(o, "InDumpArea", m.inDumpArea);
        return o;
    }
    json operator()(const HaulTruckPayloadV1& m) const {
        json o = {{"PayloadWeight", num(m.payloadWeight)}};
        putOpt(o, "Accuracy", m.accuracy);
        if (m.payloadSourceId)
            o["PayloadSourceId"] = *m.payloadSourceId;
        return o;
    }
    json operator()(const HaulTruckDumpV1& m) const {
        json o = {{"WayId", m.wayId}};
        putOpt(o, "AssignmentId", m.assignmentId);
        putOpt(o, "DumpedWeight", m.dumpedWeight);
        putOpt(o, "DestinationSpotId", m.destinationSpotId);
        putOpt(o, "DumpEquipmentId", m.dumpEquipmentId);
        return o;
    }
    json operator()(const HaulTruckAssignmentRequestV2& m) const {
        json a = json::array();
        for (auto& x : m.items) {
            json o = {{"AssignmentId", x.assignmentId}, {"Task", x.task}, {"DestinationId", x.destinationId}};
            putOpt(o, "DestinationEquipmentId", x.destinationEquipmentId);
            putOpt(o, "DestinationSpotId", x.destinationSpotId);
            if (x.route)
                o["RouteV1"] = wayRefs(*x.route);
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const HaulTruckAssignmentResponseV1& m) const {
        json a = json::array();
        for (auto& x : m.items) {
            json o = {{"AssignmentId", x.assignmentId}, {"Response", x.response}};
            putOpt(o, "Detail", x.detail);
            a.push_back(std::move(o));
        }
        return a;
    }
    json operator()(const HaulTruckAssignmentResetV1& m) const { return {{"ResetId", m.resetId}}; }
    json operator()(const HaulTruckAssignmentV1& m) const {
        json o = {{"AssignmentId", guidOrNull(m.assignmentId)}, {"Status", m.status}};
        putOpt(o, "Task", m.task);
        putOpt(o, "DestinationId", m.destinationId);
        return o;
    }
    json operator()(const UnknownMember& m) const { return m.value; }
};

} // namespace

json toJson(const Envelope& env) {
    json o = json::object();
    o["Protocol"] = env.header.protocol;
    if (env.header.version)
        o["Version"] = *env.header.version;
    o["Timestamp"] = ts(env.header.timestamp);
    if (env.header.equipmentId)
        o["EquipmentId"] = *env.header.equipmentId;
    for (auto& m : env.members) {
        json v = std::visit(Encoder{}, m.body);
        if (v.is_object() && m.extra.is_object())
            for (auto it = m.extra.begin(); it != m.extra.end(); ++it)
                v[it.key()] = it.value();
        o[std::string(memberName(m.body))] = std::move(v);
    }
    return o;
}

std::string encodeMessage(const Envelope& env) {
    return toJson(env).dump();
}

std::string encodeMessage(const Body& body, std::optional<Guid> equipmentId, std::int64_t unixMs) {
    Envelope env;
    env.header.timestamp = makeTimestamp(unixMs < 0 ? std::chrono::duration_cast<std::chrono::milliseconds>(
                                                          std::chrono::system_clock::now().time_since_epoch())
                                                          .count()
                                                    : unixMs);
    env.header.equipmentId = std::move(equipmentId);
    env.members.push_back(Member{body, json::object()});
    return encodeMessage(env);
}

} // namespace ocu::iso23725
