#pragma once
// The simulated AHS's open pit as an ISO 23725 map (§8, OSM style): a haul ramp as two one-way lanes, per
// shovel a bench road and a loading area, per dump a dump road and area (waste dumps, the primary crusher
// last), a park road and area, the autonomous operating zone, and the directed connectivity (§9.1).
// Generated from a layout, deterministically, without sockets: the AHS's map service serves it, the haul
// fleet drives on it.
#include "sim/iso23725/TruckKinematics.h"

#include "protocols/iso23725/MapModel.h"
#include "protocols/iso23725/Messages.h"

#include "protocols/common/GeoFrame.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ocu::sim {

struct PitLayout {
    int shovels = 2; // loading areas (at least one)
    int dumps = 2;   // waste dumps (at least one), plus the crusher
    GeoPoint origin{-23.36, 119.73, 500.0};
};

// One stretch of a drive: a way of the map in node order or reversed.
struct RouteLeg {
    std::int64_t wayId = 0;
    bool reversed = false;
};

struct PitMap {
    iso23725::MapModel map; // nodes (lat/lon/ele and ENU around the layout's origin) and ways
    iso23725::MapConnectivityV1 connectivity;
    std::vector<std::int64_t> loadAreas, loadRoads; // per shovel
    std::vector<std::int64_t> dumpAreas, dumpRoads; // per dump, the crusher last
    std::int64_t parkArea = 0, parkRoad = 0;
    std::int64_t rampDown = 0, rampUp = 0; // one-way lanes between the hub (top) and the pit bottom
    // Version of the map as the map service reports it (MapSummaryV1).
    std::int64_t changeSetMap = 18000;
    std::int64_t changeSetWay = 3100;
    std::int64_t modifiedUnixMs = 0;

    // A way's nodes in ENU, in node order or reversed.
    std::vector<EnuPoint> wayPoints(std::int64_t wayId, bool reversed) const;
    // The route driving these legs one after the other.
    Route route(const std::vector<RouteLeg>& legs) const;
    // Length along a way's nodes (3D), m.
    double wayLength(std::int64_t wayId) const;
    // Index of a load/dump area in loadAreas/dumpAreas, or -1.
    int loadIndex(std::int64_t areaId) const;
    int dumpIndex(std::int64_t areaId) const;

    // The map service's view (§10.6): the map as OSM documents of at most `chunkElements` elements each
    // (0 = four documents), and the summary announcing them.
    std::vector<std::string> osmChunks(std::size_t chunkElements) const;
    iso23725::MapSummaryV1 summary(std::size_t chunkElements) const;
    // The map was edited: new change sets, so FMSs fetch it again (§10.6.3).
    void edited(std::int64_t nowUnixMs);
};

PitMap generatePitMap(const PitLayout& layout, std::int64_t nowUnixMs);

} // namespace ocu::sim
