#include "sim/iso23725/PitTerrain.h"

#include <algorithm>
#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cstdio>
#include <filesystem>
#include <gdal.h>
#include <mutex>
#include <ogr_srs_api.h>
#include <unistd.h>

namespace ocu::sim {

namespace {
constexpr double kRampHalfWidth = 14.0; // flat corridor each side of a lane's centre line (m)
constexpr double kRampBlend = 30.0;     // then blending into the benches over this run (m)
constexpr double kFloorMargin = 20.0;   // floor beyond the floor-level roads and areas (m)
constexpr double kFaceShare = 0.35;     // share of a bench's run that is the face (the rest is the berm)

double smooth(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Distance from p to a polyline and the height interpolated at the nearest point.
void nearestOnPolyline(const std::vector<EnuPoint>& line, double e, double n, double& dist, double& up) {
    dist = 1e300;
    up = 0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const EnuPoint& a = line[i];
        const EnuPoint& b = line[i + 1];
        const double dx = b.e - a.e, dy = b.n - a.n;
        const double len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((e - a.e) * dx + (n - a.n) * dy) / len2, 0.0, 1.0) : 0.0;
        const double px = a.e + t * dx, py = a.n + t * dy;
        const double d = std::hypot(e - px, n - py);
        if (d < dist) {
            dist = d;
            up = a.u + t * (b.u - a.u);
        }
    }
}
} // namespace

PitTerrainModel::PitTerrainModel(const PitMap& pit) {
    // The floor: every road/area node at the pit bottom's level.
    double floorU = 0;
    for (const auto& [id, node] : pit.map.nodes)
        floorU = std::min(floorU, node.enu.u);
    m_floorU = floorU;
    bool any = false;
    double rampTop = -1e300;
    m_west = m_south = 1e300;
    m_east = m_north = -1e300;
    for (const auto& [id, way] : pit.map.ways) {
        if (!way.tag("autonomy:area").empty())
            continue; // the operating zone is a zone, not ground
        for (auto nid : way.nodes) {
            const EnuPoint& p = pit.map.nodes.at(nid).enu;
            m_west = std::min(m_west, p.e);
            m_east = std::max(m_east, p.e);
            m_south = std::min(m_south, p.n);
            m_north = std::max(m_north, p.n);
            if (p.u <= floorU + 0.5) {
                if (!any) {
                    m_x0 = m_x1 = p.e;
                    m_y0 = m_y1 = p.n;
                    any = true;
                }
                m_x0 = std::min(m_x0, p.e);
                m_x1 = std::max(m_x1, p.e);
                m_y0 = std::min(m_y0, p.n);
                m_y1 = std::max(m_y1, p.n);
            }
        }
    }
    m_x0 -= kFloorMargin;
    m_x1 += kFloorMargin;
    m_y0 -= kFloorMargin;
    m_y1 += kFloorMargin;
    m_rampMinE = 1e300;
    m_rampMaxE = -1e300;
    for (auto id : {pit.rampDown, pit.rampUp}) {
        if (!pit.map.ways.count(id))
            continue;
        for (const EnuPoint& p : pit.wayPoints(id, false)) {
            if (p.u > -0.5)
                rampTop = std::max(rampTop, p.n);
            m_rampMinE = std::min(m_rampMinE, p.e);
            m_rampMaxE = std::max(m_rampMaxE, p.e);
        }
    }
    // Every road and lane is a graded corridor at its own height (the ramp cut through the benches, the
    // roads on the floor and on the surface), so wherever roads meet, the ground agrees with all of them.
    for (const auto& [id, way] : pit.map.ways) {
        if (way.kind == iso23725::WayKind::Area || way.nodes.size() < 2)
            continue;
        Corridor c;
        c.points = pit.wayPoints(id, false);
        c.minE = c.minN = 1e300;
        c.maxE = c.maxN = -1e300;
        for (const EnuPoint& p : c.points) {
            c.minE = std::min(c.minE, p.e);
            c.maxE = std::max(c.maxE, p.e);
            c.minN = std::min(c.minN, p.n);
            c.maxN = std::max(c.maxN, p.n);
        }
        m_roads.push_back(std::move(c));
    }
    m_benchCount = std::max(1, int(std::lround(-m_floorU / kBenchHeight)));
    // The north wall runs from the floor to where the ramp leaves the surface, so the ramp follows its slope;
    // the other walls are steeper.
    if (rampTop > m_y1 + 60)
        m_northWidth = (rampTop - 15 - m_y1) / m_benchCount;
    const double margin = 150;
    m_west = std::min(m_west, m_x0 - m_benchCount * m_sideWidth) - margin;
    m_east = std::max(m_east, m_x1 + m_benchCount * m_sideWidth) + margin;
    m_south = std::min(m_south, m_y0 - m_benchCount * m_sideWidth) - margin;
    m_north = std::max(m_north, m_y1 + m_benchCount * m_northWidth) + margin;
}

double PitTerrainModel::benches(double e, double n) const {
    if (m_floorU >= 0)
        return 0;
    const double dx = std::max({0.0, m_x0 - e, e - m_x1});
    const double dyS = std::max(0.0, m_y0 - n), dyN = std::max(0.0, n - m_y1);
    // The north wall is long (the ramp climbs along it) only where the ramp is; elsewhere steep like the
    // others.
    const double off = std::max({0.0, m_rampMinE - 40 - e, e - m_rampMaxE - 40});
    const double northWidth = m_sideWidth + (m_northWidth - m_sideWidth) * (1 - smooth(off / 150));
    const double b =
        std::sqrt((dx / m_sideWidth) * (dx / m_sideWidth) + (dyS / m_sideWidth) * (dyS / m_sideWidth) +
                  (dyN / northWidth) * (dyN / northWidth));
    const double k = std::floor(b);
    if (k >= m_benchCount)
        return 0;
    const double rise = smooth((b - k) / kFaceShare);
    return std::min(0.0, m_floorU + kBenchHeight * (k + rise));
}

double PitTerrainModel::up(double e, double n) const {
    const double bench = benches(e, n);
    double best = 1e300, rampUp = 0;
    const double reach = kRampHalfWidth + kRampBlend;
    for (const auto& r : m_roads) {
        if (e < r.minE - reach || e > r.maxE + reach || n < r.minN - reach || n > r.maxN + reach)
            continue;
        double d, u;
        nearestOnPolyline(r.points, e, n, d, u);
        if (d < best) {
            best = d;
            rampUp = u;
        }
    }
    if (best <= kRampHalfWidth)
        return rampUp;
    if (best <= kRampHalfWidth + kRampBlend)
        return rampUp + (bench - rampUp) * smooth((best - kRampHalfWidth) / kRampBlend);
    return bench;
}

std::string defaultPitTerrainDir(const PitLayout& layout) {
    char name[160];
    std::snprintf(name, sizeof name, "ocu-pit-terrain-v2_%.6f_%.6f_%.1f_%d_%d", layout.origin.lat,
                  layout.origin.lon, layout.origin.alt, layout.shovels, layout.dumps);
    std::error_code ec;
    std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
    if (ec)
        tmp = "/tmp";
    return (tmp / name).string();
}

PitTerrainFiles writePitTerrain(const PitMap& pit, const GeoPoint& origin, const std::string& dir,
                                double cellM) {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    namespace fs = std::filesystem;
    PitTerrainFiles out;
    out.dem = (fs::path(dir) / "pit_dem.tif").string();
    out.hillshade = (fs::path(dir) / "pit_hillshade.tif").string();
    std::error_code ec;
    if (fs::exists(out.dem, ec) && fs::exists(out.hillshade, ec))
        return out; // written by an earlier run for the same layout
    fs::create_directories(dir, ec);
    if (ec) {
        out.error = "cannot create " + dir + ": " + ec.message();
        return out;
    }
    if (!(cellM > 0.1 && cellM < 100)) {
        out.error = "terrain cell size out of range";
        return out;
    }
    const PitTerrainModel model(pit);
    const double west = std::floor(model.west() / cellM) * cellM,
                 north = std::ceil(model.north() / cellM) * cellM;
    const int cols = int(std::ceil((model.east() - west) / cellM));
    const int rows = int(std::ceil((north - model.south()) / cellM));
    std::vector<float> z(std::size_t(cols) * std::size_t(rows));
    for (int r = 0; r < rows; ++r) {
        const double n = north - (r + 0.5) * cellM;
        for (int c = 0; c < cols; ++c)
            z[std::size_t(r) * std::size_t(cols) + std::size_t(c)] =
                float(origin.alt + model.up(west + (c + 0.5) * cellM, n));
    }

    char proj[256];
    std::snprintf(proj, sizeof proj,
                  "+proj=ortho +lat_0=%.10f +lon_0=%.10f +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs",
                  origin.lat, origin.lon);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    char* wkt = nullptr;
    if (OSRSetFromUserInput(srs, proj) != OGRERR_NONE || OSRExportToWkt(srs, &wkt) != OGRERR_NONE) {
        OSRDestroySpatialReference(srs);
        out.error = "PROJ cannot describe the site frame";
        return out;
    }
    OSRDestroySpatialReference(srs);
    const std::string suffix = ".tmp" + std::to_string(::getpid());
    const std::string demTmp = out.dem + suffix, hsTmp = out.hillshade + suffix;
    GDALDriverH gtiff = GDALGetDriverByName("GTiff");
    const char* co[] = {"COMPRESS=DEFLATE", "TILED=YES", nullptr};
    GDALDatasetH ds =
        gtiff ? GDALCreate(gtiff, demTmp.c_str(), cols, rows, 1, GDT_Float32, const_cast<char**>(co))
              : nullptr;
    if (!ds) {
        CPLFree(wkt);
        out.error = "cannot create " + demTmp + ": " + CPLGetLastErrorMsg();
        return out;
    }
    double gt[6] = {west, cellM, 0, north, 0, -cellM};
    GDALSetGeoTransform(ds, gt);
    GDALSetProjection(ds, wkt);
    CPLFree(wkt);
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    bool ok =
        GDALRasterIO(band, GF_Write, 0, 0, cols, rows, z.data(), cols, rows, GDT_Float32, 0, 0) == CE_None;
    GDALSetMetadataItem(ds, "TIFFTAG_IMAGEDESCRIPTION",
                        "OCU simulated open pit: ground height above the WGS84 ellipsoid (m)", nullptr);
    GDALSetRasterUnitType(band, "m");
    // The hillshade (Horn's gradient, light from the north-west at 55°), compressed towards white so that it
    // sits under the map's roads and symbols as a light relief: flat ground ~234, faces away from the light
    // down to ~140, faces towards it up to 255.
    std::vector<unsigned char> shade(z.size());
    const double az = 315 * M_PI / 180, zen = (90 - 55) * M_PI / 180;
    auto at = [&](int c, int r) {
        c = std::clamp(c, 0, cols - 1);
        r = std::clamp(r, 0, rows - 1);
        return double(z[std::size_t(r) * std::size_t(cols) + std::size_t(c)]);
    };
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const double dzdx = ((at(c + 1, r - 1) + 2 * at(c + 1, r) + at(c + 1, r + 1)) -
                                 (at(c - 1, r - 1) + 2 * at(c - 1, r) + at(c - 1, r + 1))) /
                                (8 * cellM);
            const double dzdy = ((at(c - 1, r + 1) + 2 * at(c, r + 1) + at(c + 1, r + 1)) -
                                 (at(c - 1, r - 1) + 2 * at(c, r - 1) + at(c + 1, r - 1))) /
                                (8 * cellM); // towards the south (rows grow southwards)
            const double slope = std::atan(std::hypot(dzdx, dzdy));
            const double aspect = std::atan2(dzdy, -dzdx);
            const double lit =
                std::max(0.0, std::cos(zen) * std::cos(slope) +
                                  std::sin(zen) * std::sin(slope) * std::cos(az - M_PI / 2 - aspect));
            shade[std::size_t(r) * std::size_t(cols) + std::size_t(c)] =
                static_cast<unsigned char>(std::clamp(255.0 - 0.45 * (255.0 - 255.0 * lit), 0.0, 255.0));
        }
    GDALDatasetH hs =
        ok ? GDALCreate(gtiff, hsTmp.c_str(), cols, rows, 1, GDT_Byte, const_cast<char**>(co)) : nullptr;
    if (hs) {
        GDALSetGeoTransform(hs, gt);
        GDALSetProjection(hs, GDALGetProjectionRef(ds));
        ok = GDALRasterIO(GDALGetRasterBand(hs, 1), GF_Write, 0, 0, cols, rows, shade.data(), cols, rows,
                          GDT_Byte, 0, 0) == CE_None;
        GDALClose(hs);
    } else {
        ok = false;
    }
    GDALClose(ds);
    if (!ok) {
        out.error = std::string("writing the pit terrain failed: ") + CPLGetLastErrorMsg();
        fs::remove(demTmp, ec);
        fs::remove(hsTmp, ec);
        return out;
    }
    fs::rename(demTmp, out.dem, ec);
    if (!ec)
        fs::rename(hsTmp, out.hillshade, ec);
    if (ec)
        out.error = "cannot move the terrain files into " + dir + ": " + ec.message();
    return out;
}

} // namespace ocu::sim
