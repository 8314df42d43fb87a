#include "protocols/iso23725/FleetDiscrepancies.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace ocu::iso23725 {

std::vector<std::string> fleetDiscrepancies(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                            double dimensionTolerance) {
    std::vector<std::string> items;
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
                items.push_back("machine " + mine.hid + " (" + mine.equipmentId +
                                ") is missing from the AHS fleet definition");
            continue;
        }
        const Equipment& a = *it->second;
        const std::string who = "machine " + mine.equipmentId + ": ";
        if (!mine.autonomous)
            items.push_back(who + "listed by both the FMS (manned) and the AHS");
        if (a.hid != mine.hid)
            items.push_back(who + "HID '" + a.hid + "' at the AHS, '" + mine.hid + "' at the FMS");
        if (a.type != mine.type)
            items.push_back(who + "type " + a.type + " at the AHS, " + mine.type + " at the FMS");
        if (dimDiff(a.length, mine.length) || dimDiff(a.width, mine.width))
            items.push_back(who + "dimensions " + fmt(a.length) + " x " + fmt(a.width) + " m at the AHS, " +
                            fmt(mine.length) + " x " + fmt(mine.width) + " m at the FMS");
    }
    std::set<Guid> mineIds;
    for (auto& e : fms)
        mineIds.insert(e.equipmentId);
    for (auto& a : ahs.equipment)
        if (!mineIds.count(a.equipmentId))
            items.push_back("machine " + a.hid + " (" + a.equipmentId + ", " + a.type +
                            ") of the AHS is not in the FMS fleet");
    return items;
}

} // namespace ocu::iso23725
