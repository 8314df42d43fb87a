// Decoding of ISO 23725 messages (§4, §5): the header, then each member through its decoder (validation per
// the requirement levels, errors naming <Message>.<Member>, unknown members kept), the fast path for clean
// MachinePositionV1 frames first.
#include "protocols/iso23725/JsonReader.h"
#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/PositionFastPath.h"

#include <unordered_map>

namespace ocu::iso23725 {

using nlohmann::json;
using namespace detail;

namespace {

PoseFields readPose(Obj& o) {
    PoseFields p;
    // All pose numbers are shall members but may be null = unavailable (§4.2.3).
    p.heading = o.integer("Heading", true, true);
    if (p.heading && (*p.heading < 0 || *p.heading > 359))
        o.fail("Heading", "out of range 0-359: " + std::to_string(*p.heading));
    p.latitude = o.number("Latitude", true, true);
    if (p.latitude && (*p.latitude < -90 || *p.latitude > 90))
        o.fail("Latitude", "out of range -90..90");
    p.longitude = o.number("Longitude", true, true);
    if (p.longitude && (*p.longitude < -180 || *p.longitude > 180))
        o.fail("Longitude", "out of range -180..180");
    p.elevation = o.number("Elevation", true, true);
    p.latitudeAccuracy = o.number("LatitudeAccuracy", true, true);
    p.longitudeAccuracy = o.number("LongitudeAccuracy", true, true);
    p.elevationAccuracy = o.number("ElevationAccuracy", true, true, "HeightAccuracy");
    p.headingAccuracy = o.number("HeadingAccuracy", true, true);
    p.speed = o.integer("Speed", true, true);
    return p;
}

MachinePositionV1 readPosition(Obj& o, Ctx& ctx) {
    o.prefetch({"Timestamp", "Heading", "Latitude", "Longitude", "Elevation", "LatitudeAccuracy",
                "LongitudeAccuracy", "ElevationAccuracy", "HeightAccuracy", "HeadingAccuracy", "Speed",
                "Attachment", "AttachmentV1"});
    MachinePositionV1 m;
    m.timestamp = o.timestamp("Timestamp");
    m.pose = readPose(o);
    if (const json* a = o.optArray("Attachment", "AttachmentV1")) {
        m.attachment.emplace();
        for (std::size_t i = 0; i < a->size(); ++i) {
            Obj it((*a)[i], o.item("Attachment", i), ctx);
            AttachmentPose ap;
            ap.equipmentId = it.guid("EquipmentId", "EquipmentID");
            ap.pose = readPose(it);
            it.extras();
            m.attachment->push_back(std::move(ap));
        }
    }
    return m;
}

template <class F> auto eachItem(Obj& o, const json& arr, std::string_view key, Ctx& ctx, F&& f) {
    for (std::size_t i = 0; i < arr.size(); ++i) {
        Obj it(arr[i], o.item(key, i), ctx);
        f(it);
        it.extras();
    }
}

// An array-valued member (MachineDiagnosticV2, MapConnectivityV1, ...): each element read with f.
template <class F> void eachTop(const json& v, std::string_view name, Ctx& ctx, F&& f) {
    if (!v.is_array())
        throw DecodeError{std::string(name) + ": " +
                          (v.is_null() ? std::string("must be an array (may be empty, not null)")
                                       : std::string("expected an array, got ") + typeName(v))};
    for (std::size_t i = 0; i < v.size(); ++i) {
        Obj it(v[i], std::string(name) + "[" + std::to_string(i) + "]", ctx);
        f(it);
        it.extras();
    }
}

using Decoder = Body (*)(const json&, Ctx&, json& extra);

template <class T, class F> Body objectMember(const json& v, const char* name, Ctx& ctx, json& extra, F&& f) {
    Obj o(v, name, ctx);
    T t;
    f(o, t);
    extra = o.extras();
    return t;
}

Body decFleet(const json& v, Ctx& c, json& x) {
    return objectMember<FleetDefinitionV2>(v, "FleetDefinitionV2", c, x, [&](Obj& o, FleetDefinitionV2& m) {
        m.ahsId = o.guid("AHSId");
        const json& arr = o.array("Equipment");
        eachItem(o, arr, "Equipment", c, [&](Obj& it) {
            Equipment e;
            e.equipmentId = it.guid("EquipmentId", "EquipmentID");
            e.hid = it.str("HID");
            e.type = it.enumeration("Type", enums::equipmentType);
            e.oem = it.str("OEM");
            e.model = it.str("Model");
            e.autonomous = it.boolean("Autonomous");
            e.length = it.number("Length", true, true);
            e.width = it.number("Width", true, true);
            m.equipment.push_back(std::move(e));
        });
    });
}
Body decAllStopReq(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopRequestV1>(v, "MachineAllStopRequestV1", c, x, [](Obj& o, auto& m) {
        m.modeAllStop = o.enumeration("ModeAllStop", enums::actionRequest);
        m.modeAllStopId = o.guid("ModeAllStopId");
    });
}
Body decAllStopResp(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopResponseV1>(v, "MachineAllStopResponseV1", c, x, [](Obj& o, auto& m) {
        m.response = o.enumeration("Response", enums::actionResponse);
        m.modeAllStopId = o.guid("ModeAllStopId");
        m.detail = o.optStr("Detail");
    });
}
Body decAllStop(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAllStopV1>(v, "MachineAllStopV1", c, x, [](Obj& o, auto& m) {
        m.modeAllStop = o.enumeration("ModeAllStop", enums::actionStatus);
        m.modeAllStopId = o.nullableGuid("ModeAllStopId", true);
    });
}
Body decPosition(const json& v, Ctx& c, json& x) {
    Obj o(v, "MachinePositionV1", c);
    MachinePositionV1 m = readPosition(o, c);
    x = o.extras();
    return m;
}
Body decHealth(const json& v, Ctx& c, json& x) {
    return objectMember<BasicMachineHealthV2>(v, "BasicMachineHealthV2", c, x, [&](Obj& o, auto& m) {
        m.fuelLevel = o.integer("FuelLevel", true, true);
        if (m.fuelLevel && (*m.fuelLevel < 0 || *m.fuelLevel > 100))
            o.fail("FuelLevel", "out of range 0-100: " + std::to_string(*m.fuelLevel));
        m.totalMachineHour = o.number("TotalMachineHour", false, true);
        m.totalEngineHour = o.number("TotalEngineHour", true, true);
        m.primeMoverTemp = o.integer("PrimeMoverTemp", false, true);
        if (const json* t = o.optArray("Tire")) {
            m.tire.emplace();
            eachItem(o, *t, "Tire", c, [&](Obj& it) {
                Tire tire;
                tire.tirePosition = it.str("TirePosition");
                tire.tirePressure = it.integer("TirePressure", true, true);
                tire.tireTemperature = it.integer("TireTemperature", true, true);
                m.tire->push_back(std::move(tire));
            });
        }
    });
}
Body decAutonomy(const json& v, Ctx& c, json& x) {
    return objectMember<MachineAutonomyModeV1>(v, "MachineAutonomyModeV1", c, x, [](Obj& o, auto& m) {
        m.autonomyMode = o.enumeration("AutonomyMode", enums::autonomyMode);
    });
}
Body decAvailability(const json& v, Ctx& c, json& x) {
    return objectMember<MachineDispatchAvailabilityV1>(
        v, "MachineDispatchAvailabilityV1", c, x, [](Obj& o, auto& m) {
            m.dispatchingCustodian = o.enumeration("DispatchingCustodian", enums::actor);
            m.impendingCustodian = o.optEnum("ImpendingCustodian", enums::actor);
            m.impendingTime = o.optTimestamp("ImpendingTime");
        });
}
Body decDiagnostic(const json& v, Ctx& c, json&) {
    MachineDiagnosticV2 m;
    eachTop(v, "MachineDiagnosticV2", c, [&](Obj& it) {
        m.entries.push_back(DiagnosticEntry{it.reqInt("ComponentId"), it.reqInt("FaultCode")});
    });
    return m;
}
Body decConnectivity(const json& v, Ctx& c, json&) {
    MapConnectivityV1 m;
    eachTop(v, "MapConnectivityV1", c, [&](Obj& it) {
        ConnectivityItem ci;
        ci.wayId = it.reqInt("WayId");
        ci.wayType = it.enumeration("WayType", enums::wayType);
        if (ci.wayType == "Road") {
            Obj rp(it.need("RoadProperty"), it.path() + ".RoadProperty", c);
            ci.roadLength = rp.number("Length", true, true);
            ci.roadName = rp.optStr("Name");
            rp.extras();
        } else {
            Obj ap(it.need("AreaProperty"), it.path() + ".AreaProperty", c);
            ci.areaDefaultTask = ap.enumeration("DefaultTask", enums::defaultTask);
            ci.areaName = ap.optStr("Name");
            ap.extras();
        }
        it.find(ci.wayType == "Road" ? "AreaProperty" : "RoadProperty"); // tolerated, not kept
        const json& conn = it.array("Connection");
        eachItem(it, conn, "Connection", c,
                 [&](Obj& w) { ci.connection.push_back(WayRef{w.reqInt("WayId")}); });
        m.items.push_back(std::move(ci));
    });
    return m;
}
Body decMapService(const json& v, Ctx& c, json& x) {
    return objectMember<MapServiceV1>(v, "MapServiceV1", c, x,
                                      [](Obj& o, auto& m) { m.api = o.reqInt("API"); });
}
Body decSummary(const json& v, Ctx& c, json& x) {
    return objectMember<MapSummaryV1>(v, "MapSummaryV1", c, x, [](Obj& o, auto& m) {
        m.timestamp = o.timestamp("Timestamp");
        m.changeSetMap = o.reqInt("ChangeSetMap");
        m.changeSetWay = o.reqInt("ChangeSetWay");
        m.uid = o.integer("uid", false, true);
        m.nodeCount = o.reqInt("NodeCount");
        m.wayCount = o.reqInt("WayCount");
        m.documentCount = o.reqInt("DocumentCount");
        if (m.documentCount < 0)
            o.fail("DocumentCount", "must not be negative");
    });
}
Body decMapCommand(const json& v, Ctx& c, json& x) {
    return objectMember<MapCommandV1>(v, "MapCommandV1", c, x, [](Obj& o, auto& m) {
        m.method = o.str("Method");
        std::string up = m.method;
        std::transform(up.begin(), up.end(), up.begin(), [](unsigned char ch) { return std::toupper(ch); });
        if (up != "GET") // the source says "Get", examples "GET": accept either case
            o.fail("Method", "'" + m.method + "' is not GET");
        m.method = up;
        m.scope = o.str("Scope");
    });
}
Body decInterfaceDiag(const json& v, Ctx& c, json& x) {
    return objectMember<InterfaceDiagnosticV1>(v, "InterfaceDiagnosticV1", c, x, [&](Obj& o, auto& m) {
        if (const json* a = o.optArray("Measurement"))
            eachItem(o, *a, "Measurement", c, [&](Obj& it) {
                m.measurement.push_back(
                    DiagMeasurement{it.str("Name"), it.number("Value", true, true), it.str("Unit")});
            });
        if (const json* a = o.optArray("Message"))
            eachItem(o, *a, "Message", c, [&](Obj& it) {
                DiagMessage d;
                d.severity = it.enumeration("Severity", enums::severity);
                d.code = it.str("Code");
                d.detail = it.optStr("Detail");
                d.refMember = it.optStr("RefMember");
                d.refTimestamp = it.optTimestamp("RefTimestamp");
                m.message.push_back(std::move(d));
            });
    });
}
Body decCycle(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionCycleV1>(
        v, "HaulTruckProductionCycleV1", c, x, [&](Obj& o, auto& m) {
            m.cycleId = o.guid("CycleId");
            m.assignmentId = o.nullableGuid("AssignmentId", false);
            m.loadWayId = o.reqInt("LoadWayId");
            m.dumpWayId = o.reqInt("DumpWayId");
            m.loaderEquipmentId = o.nullableGuid("LoaderEquipmentId", false);
            m.payloadWeight = o.integer("PayloadWeight", false, true);
            if (const json* a = o.optArray("StateTimes"))
                eachItem(o, *a, "StateTimes", c, [&](Obj& it) {
                    m.stateTimes.push_back(
                        StateTime{it.enumeration("ProductionState", enums::productionState),
                                  it.timestamp("Start"), it.number("Duration", true, true)});
                });
        });
}
Body decProdState(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionStateV2>(
        v, "HaulTruckProductionStateV2", c, x, [](Obj& o, auto& m) {
            m.assignmentId = o.nullableGuid("AssignmentId", true);
            m.wayId = o.integer("WayId", true, true);
            m.autonomyMode = o.enumeration("AutonomyMode", enums::autonomyMode);
            m.productionState = o.enumeration("ProductionState", enums::productionState);
        });
}
Body decSensor(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckProductionStateSensorV1>(
        v, "HaulTruckProductionStateSensorV1", c, x, [](Obj& o, auto& m) {
            m.loaded = o.optBool("Loaded");
            m.bodyRaised = o.optBool("BodyRaised");
            m.parkBrake = o.optBool("ParkBrake");
            m.payloadWeight = o.integer("PayloadWeight", false, true);
            m.inLoadArea = o.optBool("InLoadArea");
            m.inDumpArea = o.optBool("InDumpArea");
        });
}
Body decPayload(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckPayloadV1>(v, "HaulTruckPayloadV1", c, x, [](Obj& o, auto& m) {
        m.payloadWeight = o.integer("PayloadWeight", true, true);
        m.accuracy = o.number("Accuracy", false, true);
        if (const json* s = o.find("PayloadSourceId")) {
            if (s->is_string() && !isGuid(s->get_ref<const std::string&>()))
                o.fail("PayloadSourceId", "malformed GUID '" + s->get<std::string>() + "'");
            if (!s->is_string() && !s->is_number() && !s->is_null())
                o.fail("PayloadSourceId",
                       std::string("expected a GUID, a number or null, got ") + typeName(*s));
            m.payloadSourceId = *s;
        }
    });
}
Body decDump(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckDumpV1>(v, "HaulTruckDumpV1", c, x, [](Obj& o, auto& m) {
        m.assignmentId = o.nullableGuid("AssignmentId", false);
        m.wayId = o.reqInt("WayId");
        m.dumpedWeight = o.integer("DumpedWeight", false, true);
        m.destinationSpotId = o.integer("DestinationSpotId", false, true);
        m.dumpEquipmentId = o.nullableGuid("DumpEquipmentId", false);
    });
}
Body decAssignReq(const json& v, Ctx& c, json&) {
    HaulTruckAssignmentRequestV2 m;
    eachTop(v, "HaulTruckAssignmentRequestV2", c, [&](Obj& it) {
        AssignmentItem a;
        a.assignmentId = it.guid("AssignmentId");
        a.task = it.enumeration("Task", enums::haulTask);
        a.destinationId = it.reqInt("DestinationId");
        a.destinationEquipmentId = it.nullableGuid("DestinationEquipmentId", false);
        a.destinationSpotId = it.integer("DestinationSpotId", false, true);
        if (a.destinationEquipmentId && a.destinationSpotId)
            it.fail("DestinationSpotId", "mutually exclusive with DestinationEquipmentId");
        if (const json* r = it.optArray("RouteV1")) {
            a.route.emplace();
            eachItem(it, *r, "RouteV1", c, [&](Obj& w) { a.route->push_back(WayRef{w.reqInt("WayId")}); });
        }
        m.items.push_back(std::move(a));
    });
    if (m.items.empty())
        throw DecodeError{"HaulTruckAssignmentRequestV2: must hold at least one assignment"};
    return m;
}
Body decAssignResp(const json& v, Ctx& c, json&) {
    HaulTruckAssignmentResponseV1 m;
    eachTop(v, "HaulTruckAssignmentResponseV1", c, [&](Obj& it) {
        m.items.push_back(AssignmentResponseItem{
            it.guid("AssignmentId"), it.enumeration("Response", enums::actionResponse), it.optStr("Detail")});
    });
    return m;
}
Body decReset(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckAssignmentResetV1>(v, "HaulTruckAssignmentResetV1", c, x,
                                                    [](Obj& o, auto& m) { m.resetId = o.guid("ResetId"); });
}
Body decAssignment(const json& v, Ctx& c, json& x) {
    return objectMember<HaulTruckAssignmentV1>(v, "HaulTruckAssignmentV1", c, x, [](Obj& o, auto& m) {
        m.assignmentId = o.nullableGuid("AssignmentId", true);
        m.status = o.enumeration("Status", enums::assignmentStatus);
        m.task = o.optEnum("Task", enums::haulTask);
        m.destinationId = o.integer("DestinationId", false, true);
    });
}

struct MemberInfo {
    Decoder decode;
    bool perMachine; // header EquipmentId required (§4.1)
};

const std::unordered_map<std::string_view, MemberInfo>& decoders() {
    static const std::unordered_map<std::string_view, MemberInfo> m = {
        {"FleetDefinitionV2", {decFleet, false}},
        {"MachineAllStopRequestV1", {decAllStopReq, false}},
        {"MachineAllStopResponseV1", {decAllStopResp, false}},
        {"MachineAllStopV1", {decAllStop, false}},
        {"MachinePositionV1", {decPosition, true}},
        {"BasicMachineHealthV2", {decHealth, true}},
        {"MachineAutonomyModeV1", {decAutonomy, true}},
        {"MachineDispatchAvailabilityV1", {decAvailability, true}},
        {"MachineDiagnosticV2", {decDiagnostic, true}},
        {"MapConnectivityV1", {decConnectivity, false}},
        {"MapServiceV1", {decMapService, false}},
        {"MapSummaryV1", {decSummary, false}},
        {"MapCommandV1", {decMapCommand, false}},
        {"InterfaceDiagnosticV1", {decInterfaceDiag, false}},
        {"HaulTruckProductionCycleV1", {decCycle, true}},
        {"HaulTruckProductionStateV2", {decProdState, true}},
        {"HaulTruckProductionStateSensorV1", {decSensor, true}},
        {"HaulTruckPayloadV1", {decPayload, true}},
        {"HaulTruckDumpV1", {decDump, true}},
        {"HaulTruckAssignmentRequestV2", {decAssignReq, true}},
        {"HaulTruckAssignmentResponseV1", {decAssignResp, true}},
        {"HaulTruckAssignmentResetV1", {decReset, true}},
        {"HaulTruckAssignmentV1", {decAssignment, true}},
    };
    return m;
}

bool isHeaderKey(std::string_view k) {
    return k == "Protocol" || k == "Version" || k == "Timestamp" || k == "EquipmentId" || k == "EquipmentID";
}

} // namespace

Result<Envelope> decodeJson(const json& doc, const InferredRules& rules) {
    Envelope env;
    if (!doc.is_object())
        return makeError(std::string("message: expected a JSON object, got ") + typeName(doc));
    Ctx ctx{rules, env.warnings};
    try {
        Obj h(doc, "header", ctx);
        h.prefetch({"Protocol", "Version", "Timestamp", "EquipmentId", "EquipmentID"});
        env.header.protocol = h.str("Protocol");
        if (const json* v = h.find("Version")) {
            env.header.version = h.asInteger("Version", *v, false);
        } else if (rules.acceptMissingVersion) {
            env.header.version.reset();
            env.warnings.push_back("header.Version: required member missing (tolerated)");
        } else {
            h.fail("Version", "required member missing");
        }
        env.header.timestamp = h.timestamp("Timestamp");
        env.header.equipmentId = h.nullableGuid("EquipmentId", false);
        if (!env.header.equipmentId) {
            if (const json* v = h.find("EquipmentID"); v && rules.acceptAliases) {
                env.header.equipmentId = h.asGuid("EquipmentID", *v);
                env.warnings.push_back("header: alias 'EquipmentID' accepted for 'EquipmentId'");
            }
        }
    } catch (const DecodeError& e) {
        return makeError(e.message);
    }
    if (env.header.protocol != rules.protocol) {
        env.outOfStandard = true;
        env.warnings.push_back("header.Protocol: out-of-standard protocol '" + env.header.protocol + "'");
    }
    const auto& table = decoders();
    for (auto it = doc.begin(); it != doc.end(); ++it) {
        const std::string& key = it.key();
        if (isHeaderKey(key))
            continue;
        std::string_view name = key;
        bool alias = false;
        if (name == rules.allStopStatusAlias) {
            name = "MachineAllStopV1";
            alias = true;
        } else if (name == rules.mapServiceMember) {
            name = "MapServiceV1";
        }
        auto d = table.find(name);
        if (d == table.end()) {
            env.members.push_back(Member{UnknownMember{key, it.value()}, json()});
            env.warnings.push_back("unknown member '" + key + "' kept");
            continue;
        }
        if (alias)
            env.warnings.push_back("member '" + key + "' accepted as MachineAllStopV1");
        try {
            if (d->second.perMachine && !env.header.equipmentId)
                throw DecodeError{std::string(name) + ": header EquipmentId required for this message"};
            json extra;
            Body body = d->second.decode(it.value(), ctx, extra);
            env.members.push_back(Member{std::move(body), std::move(extra)});
        } catch (const DecodeError& e) {
            env.errors.push_back(e.message);
        } catch (const json::exception& e) {
            env.errors.push_back(std::string(name) + ": " + e.what());
        }
    }
    if (env.members.empty() && env.errors.empty())
        env.errors.push_back("message: no message member besides the header");
    return env;
}

Result<Envelope> decodeMessage(std::string_view text, const InferredRules& rules) {
    // Hot path (ISO §7.4, note §5 row 5: 1-10 Hz per machine): clean MachinePositionV1 frames skip the DOM.
    if (auto fast = tryDecodePositionFast(text, rules))
        return std::move(*fast);
    return decodeMessageDom(text, rules);
}

Result<Envelope> decodeMessageDom(std::string_view text, const InferredRules& rules) {
    json doc = json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded())
        return makeError("message: invalid JSON");
    return decodeJson(doc, rules);
}

} // namespace ocu::iso23725
