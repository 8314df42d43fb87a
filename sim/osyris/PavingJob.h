#pragma once
// A long paving job for the simulated paving train: the centre line of the road as a polyline
// in the worksite's local frame (x east, y north, metres), paved in several lifts, each lift's height
// liftThickness above the one before. The paver goes along the line at paverSpeed, the rollers follow behind
// it; after the last station of a lift the train starts the next lift at station 0.
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Result.h"

#include <string>
#include <vector>

namespace ocu::sim::osyris {

struct PavingJob {
    std::vector<double> xs, ys;   // polyline vertices (local ENU)
    std::vector<double> stations; // cumulative length at each vertex
    int lifts = 3;
    double liftThickness = 0.05;    // m
    double baseZ = 100.0;           // m: z of the bottom of lift 0
    double paverSpeed = 5.0 / 60.0; // m/s (5 m/min)
    std::string source;             // "built-in" or the file

    double length() const { return stations.empty() ? 0 : stations.back(); }
    // Point and heading (radians counter-clockwise from east) at station s (clamped to the line), offset to
    // the left of the direction of travel (negative = right).
    void at(double s, double leftOffset, double& x, double& y, double& heading) const;
    // Which lift the distance d driven along the job (over all lifts) is in, and the station within it.
    void liftOf(double d, int& lift, double& station) const;
    // z of a machine on lift `lift`: the middle of its band, so GNSS noise does not cross a band boundary.
    double zOf(int lift) const { return baseZ + (lift + 0.5) * liftThickness; }
};

// The shape of the shipped design (resources/designs/paving-job.xml) without the file: 900 m line, a 500 m
// arc of radius 600 m to the left, 1200 m line; starting at the local origin heading east.
PavingJob builtInPavingJob();

// The first alignment of a LandXML file in a UTM CRS (EPSG 326zz / 327zz), as local coordinates around
// `origin` (UTM -> WGS 84 -> local ENU through GeographicLib), sampled every 5 m.
Result<PavingJob> pavingJobFromLandXml(const std::string& path, const GeoPoint& origin);

} // namespace ocu::sim::osyris
