#include "protocols/iso23725/FleetDiscrepancies.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace ocu::iso23725 {

const char* causeId(DiscrepancyCause cause) {
    switch (cause) {
    case DiscrepancyCause::MissingFromAhs:
        return "fleet.missing_from_ahs";
    case DiscrepancyCause::ListedByBoth:
        return "fleet.listed_by_both";
    case DiscrepancyCause::HidDiffers:
        return "fleet.hid_differs";
    case DiscrepancyCause::TypeDiffers:
        return "fleet.type_differs";
    case DiscrepancyCause::DimensionsDiffer:
        return "fleet.dimensions_differ";
    case DiscrepancyCause::NotInFms:
        return "fleet.not_in_fms";
    }
    return "fleet.unknown";
}

std::vector<std::string> discrepancyTexts(const std::vector<FleetDiscrepancy>& items) {
    std::vector<std::string> out;
    out.reserve(items.size());
    for (const auto& i : items)
        out.push_back(i.text);
    return out;
}

std::vector<std::string> fleetDiscrepancies(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                            double dimensionTolerance) {
    return discrepancyTexts(checkFleet(ahs, fms, dimensionTolerance));
}

std::vector<FleetDiscrepancy> checkFleet(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                         double dimensionTolerance) {
    std::vector<FleetDiscrepancy> items;
    using C = DiscrepancyCause;
    std::map<Guid, const Equipment*> ahsById;
    for (auto& e : ahs.equipment)
        ahsById[e.equipmentId] = &e;
    auto dimDiff = [&](const std::optional<double>& a, const std::optional<double>& b) {
        return a.has_value() != b.has_value() || (a && std::fabs(*a - *b) > dimensionTolerance);
    };
    auto fmt = [](const std::optional<double>& v) {
        if (!v)
            return std::string("null");
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f", *v);
        return std::string(buf);
    };
    for (auto& mine : fms) {
        auto it = ahsById.find(mine.equipmentId);
        if (it == ahsById.end()) {
            if (mine.autonomous)
                items.push_back({C::MissingFromAhs, mine.equipmentId,
                                 "machine " + mine.hid + " (" + mine.equipmentId +
                                     ") is missing from the AHS fleet definition"});
            continue;
        }
        const Equipment& a = *it->second;
        const std::string who = "machine " + mine.equipmentId + ": ";
        if (!mine.autonomous)
            items.push_back(
                {C::ListedByBoth, mine.equipmentId, who + "listed by both the FMS (manned) and the AHS"});
        if (a.hid != mine.hid)
            items.push_back({C::HidDiffers, mine.equipmentId,
                             who + "HID '" + a.hid + "' at the AHS, '" + mine.hid + "' at the FMS"});
        if (a.type != mine.type)
            items.push_back({C::TypeDiffers, mine.equipmentId,
                             who + "type " + a.type + " at the AHS, " + mine.type + " at the FMS"});
        if (dimDiff(a.length, mine.length) || dimDiff(a.width, mine.width))
            items.push_back({C::DimensionsDiffer, mine.equipmentId,
                             who + "dimensions " + fmt(a.length) + " x " + fmt(a.width) + " m at the AHS, " +
                                 fmt(mine.length) + " x " + fmt(mine.width) + " m at the FMS"});
    }
    std::set<Guid> mineIds;
    for (auto& e : fms)
        mineIds.insert(e.equipmentId);
    for (auto& a : ahs.equipment)
        if (!mineIds.count(a.equipmentId))
            items.push_back({C::NotInFms, a.equipmentId,
                             "machine " + a.hid + " (" + a.equipmentId + ", " + a.type +
                                 ") of the AHS is not in the FMS fleet"});
    return items;
}

} // namespace ocu::iso23725
