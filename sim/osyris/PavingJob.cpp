#include "sim/osyris/PavingJob.h"

#include "protocols/site/LandXml.h"

#include <GeographicLib/UTMUPS.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::sim::osyris {

namespace {
void finish(PavingJob& j) {
    j.stations.assign(j.xs.size(), 0.0);
    for (std::size_t i = 1; i < j.xs.size(); ++i)
        j.stations[i] = j.stations[i - 1] + std::hypot(j.xs[i] - j.xs[i - 1], j.ys[i] - j.ys[i - 1]);
}
} // namespace

void PavingJob::at(double s, double left, double& x, double& y, double& heading) const {
    x = y = heading = 0;
    if (xs.size() < 2)
        return;
    s = std::clamp(s, 0.0, length());
    auto it = std::upper_bound(stations.begin(), stations.end(), s);
    std::size_t i = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(it - stations.begin(), 1, std::ptrdiff_t(xs.size()) - 1));
    const double seg = stations[i] - stations[i - 1];
    const double f = seg > 0 ? (s - stations[i - 1]) / seg : 0;
    const double dx = xs[i] - xs[i - 1], dy = ys[i] - ys[i - 1];
    heading = std::atan2(dy, dx);
    x = xs[i - 1] + f * dx - std::sin(heading) * left;
    y = ys[i - 1] + f * dy + std::cos(heading) * left;
}

void PavingJob::liftOf(double d, int& lift, double& station) const {
    const double L = length();
    if (!(L > 0) || d <= 0) {
        lift = 0;
        station = 0;
        return;
    }
    lift = std::min(lifts - 1, static_cast<int>(std::floor(d / L)));
    station = std::min(L, d - lift * L); // after the last lift the train stays at the end
}

PavingJob builtInPavingJob() {
    PavingJob j;
    j.source = "built-in";
    for (double s = 0; s <= 900; s += 5) {
        j.xs.push_back(s);
        j.ys.push_back(0);
    }
    const double r = 600, cx = 900, cy = r; // arc to the left around (900, 600)
    for (double a = 5; a <= 500; a += 5) {
        const double th = a / r;
        j.xs.push_back(cx + r * std::sin(th));
        j.ys.push_back(cy - r * std::cos(th));
    }
    const double th = 500 / r;
    const double ex = cx + r * std::sin(th), ey = cy - r * std::cos(th);
    for (double s = 5; s <= 1200; s += 5) {
        j.xs.push_back(ex + s * std::cos(th));
        j.ys.push_back(ey + s * std::sin(th));
    }
    finish(j);
    return j;
}

Result<PavingJob> pavingJobFromLandXml(const std::string& path, const GeoPoint& origin) {
    auto d = landxml::loadLandXml(path);
    if (!d)
        return makeError("paving job " + path + ": " + d.error());
    const landxml::LandXmlDesign& design = d.value();
    if (design.alignments.empty() || design.alignments.front().elements.empty())
        return makeError("paving job " + path + ": the file has no alignment");
    const int epsg = design.epsg;
    const bool north = epsg >= 32601 && epsg <= 32660, south = epsg >= 32701 && epsg <= 32760;
    if (!north && !south)
        return makeError("paving job " + path + ": EPSG " + std::to_string(epsg) +
                         " is not a UTM zone (32601-32660, 32701-32760)");
    const int zone = epsg % 100;
    GeoFrame frame(origin);
    PavingJob j;
    j.source = path;
    for (const landxml::PlanPoint& p : design.alignments.front().polyline(5.0)) {
        double lat = 0, lon = 0;
        try {
            GeographicLib::UTMUPS::Reverse(zone, north, p.e, p.n, lat, lon);
        } catch (const std::exception& e) {
            return makeError("paving job " + path + ": " + e.what());
        }
        const EnuPoint l = frame.toLocal({lat, lon, origin.alt});
        j.xs.push_back(l.e);
        j.ys.push_back(l.n);
    }
    finish(j);
    if (j.length() > 100000)
        return makeError("paving job " + path + ": the alignment lies " +
                         std::to_string(int(j.length() / 1000)) + " km long: not near the site");
    const double far = std::hypot(j.xs.front(), j.ys.front());
    if (far > 50000)
        return makeError("paving job " + path + ": the alignment starts " + std::to_string(int(far / 1000)) +
                         " km from the site's origin");
    return j;
}

} // namespace ocu::sim::osyris
