// IsoBridge: the ISO 23725 production reports (§12) as protocol-neutral ProductionReports for the production
// model, one signal per report as it arrived.
#include "models/bridges/IsoBridge.h"

namespace ocu {

using namespace ocu::iso23725;

namespace {

QString qs(const std::string& s) {
    return QString::fromStdString(s);
}

QString qs(const std::optional<std::string>& s) {
    return s ? QString::fromStdString(*s) : QString();
}

std::optional<double> tonnes(const std::optional<std::int64_t>& t) {
    return t ? std::optional<double>(static_cast<double>(*t)) : std::nullopt;
}

} // namespace

void IsoBridge::onProductionReport(const IsoMachineSnapshot& machine, const Body& member,
                                   std::int64_t headerUnixMs) {
    ProductionReport r;
    r.truckId = QStringLiteral("iso23725:") + qs(machine.equipmentId);
    r.truckName = machine.hid.empty() ? qs(machine.equipmentId) : qs(machine.hid);
    r.unixMs = headerUnixMs;
    if (auto* s = std::get_if<HaulTruckProductionStateV2>(&member)) {
        r.kind = ProductionReport::Kind::State;
        r.state = qs(s->productionState);
        r.wayId = s->wayId;
        r.assignmentId = qs(s->assignmentId);
    } else if (auto* p = std::get_if<HaulTruckPayloadV1>(&member)) {
        r.kind = ProductionReport::Kind::Payload;
        r.tonnes = tonnes(p->payloadWeight);
        // PayloadSourceId: a GUID string, a number or null (§9 tolerance).
        if (p->payloadSourceId && p->payloadSourceId->is_string())
            r.loaderId = qs(p->payloadSourceId->get<std::string>());
        else if (p->payloadSourceId && p->payloadSourceId->is_number())
            r.loaderId = qs(p->payloadSourceId->dump());
    } else if (auto* d = std::get_if<HaulTruckDumpV1>(&member)) {
        r.kind = ProductionReport::Kind::Dump;
        r.wayId = d->wayId;
        r.dumpWayId = d->wayId;
        r.tonnes = tonnes(d->dumpedWeight);
        r.assignmentId = qs(d->assignmentId);
    } else if (auto* c = std::get_if<HaulTruckProductionCycleV1>(&member)) {
        r.kind = ProductionReport::Kind::Cycle;
        r.cycleId = qs(c->cycleId);
        r.assignmentId = qs(c->assignmentId);
        r.loadWayId = c->loadWayId;
        r.dumpWayId = c->dumpWayId;
        r.loaderId = qs(c->loaderEquipmentId);
        r.tonnes = tonnes(c->payloadWeight);
        for (const auto& st : c->stateTimes)
            r.periods.push_back(
                ProductionStatePeriod{qs(st.productionState), st.start.unixMs.value_or(0), st.duration});
    } else {
        return;
    }
    emit productionReport(r);
}

} // namespace ocu
