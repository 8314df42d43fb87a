// The plan geometry of alignments (LandXML 1.2 CoordGeom): points, headings and feet on lines, arcs and
// clothoids; stationing and offsets; polylines; boundary area and containment.
#include "protocols/site/LandXmlParser.h"

#include <algorithm>
#include <cmath>

namespace ocu::landxml {

namespace detail {

double normAngle(double a) { // [0, 2pi)
    a = std::fmod(a, 2 * kPi);
    if (a < 0)
        a += 2 * kPi;
    return a;
}

// Position and heading on an element at distance t from its start (0 <= t <= length).
PlanPoint elementPoint(const AlignmentElement& el, double t, double* heading) {
    switch (el.kind) {
    case ElementKind::Line: {
        const double c = std::cos(el.startHeading), s = std::sin(el.startHeading);
        if (heading)
            *heading = el.startHeading;
        return {el.start.e + t * c, el.start.n + t * s};
    }
    case ElementKind::Arc: {
        const double a0 = std::atan2(el.start.n - el.center.n, el.start.e - el.center.e);
        const double a = a0 + el.turn * t / el.radius;
        if (heading)
            *heading = a + el.turn * kPi / 2;
        return {el.center.e + el.radius * std::cos(a), el.center.n + el.radius * std::sin(a)};
    }
    case ElementKind::Spiral: {
        const double L = el.length, k0 = el.curvatureStart, dk = el.curvatureEnd - el.curvatureStart;
        auto theta = [&](double s) { return el.startHeading + k0 * s + (L > 0 ? dk * s * s / (2 * L) : 0); };
        int n = std::max(8, static_cast<int>(std::ceil(t / 0.5)));
        n += n & 1;
        const double h = t / n;
        double se = 0, sn = 0;
        for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 1 : (i & 1) ? 4 : 2;
            const double th = theta(i * h);
            se += w * std::cos(th);
            sn += w * std::sin(th);
        }
        if (heading)
            *heading = theta(t);
        return {el.start.e + se * h / 3, el.start.n + sn * h / 3};
    }
    }
    return el.start;
}

// Nearest point of one element to p: distance along the element (clamped to [0, length]).
double elementFoot(const AlignmentElement& el, PlanPoint p) {
    switch (el.kind) {
    case ElementKind::Line: {
        const double t =
            (p.e - el.start.e) * std::cos(el.startHeading) + (p.n - el.start.n) * std::sin(el.startHeading);
        return std::clamp(t, 0.0, el.length);
    }
    case ElementKind::Arc: {
        const double sweep = el.length / el.radius;
        const double a0 = std::atan2(el.start.n - el.center.n, el.start.e - el.center.e);
        const double ap = std::atan2(p.n - el.center.n, p.e - el.center.e);
        const double d = normAngle(el.turn > 0 ? ap - a0 : a0 - ap);
        if (d <= sweep)
            return d * el.radius;
        // Outside the sweep: the nearer end (by angle past the end vs. before the start).
        return (d - sweep) < (2 * kPi - d) ? el.length : 0.0;
    }
    case ElementKind::Spiral: {
        const int n = std::max(4, static_cast<int>(std::ceil(el.length / 2.0)));
        double best = 0, bestD = 1e300;
        // March along the spiral once (positions by small chords), then refine around the best sample.
        for (int i = 0; i <= n; ++i) {
            const double t = el.length * i / n;
            const double d = dist(elementPoint(el, t, nullptr), p);
            if (d < bestD) {
                bestD = d;
                best = t;
            }
        }
        double lo = std::max(0.0, best - el.length / n), hi = std::min(el.length, best + el.length / n);
        for (int it = 0; it < 40 && hi - lo > 1e-5; ++it) {
            const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (dist(elementPoint(el, m1, nullptr), p) < dist(elementPoint(el, m2, nullptr), p))
                hi = m2;
            else
                lo = m1;
        }
        return (lo + hi) / 2;
    }
    }
    return 0;
}

} // namespace detail

using namespace detail;

double Alignment::length() const {
    double l = 0;
    for (const auto& e : elements)
        l += e.length;
    return l;
}

std::optional<PlanPoint> Alignment::pointAt(double station, double offset) const {
    if (elements.empty() || !std::isfinite(station) || !std::isfinite(offset))
        return std::nullopt;
    const double tol = 1e-9;
    if (station < staStart - tol || station > staEnd() + tol)
        return std::nullopt;
    // Elements are few; a binary search would matter only for very long chains.
    auto it = std::upper_bound(elements.begin(), elements.end(), station,
                               [](double s, const AlignmentElement& e) { return s < e.staStart; });
    const AlignmentElement& el = it == elements.begin() ? elements.front() : *(it - 1);
    const double t = std::clamp(station - el.staStart, 0.0, el.length);
    double h = 0;
    PlanPoint p = elementPoint(el, t, &h);
    p.e += offset * std::sin(h);
    p.n -= offset * std::cos(h);
    return p;
}

std::optional<double> Alignment::headingAt(double station) const {
    if (elements.empty() || !std::isfinite(station) || station < staStart - 1e-9 || station > staEnd() + 1e-9)
        return std::nullopt;
    auto it = std::upper_bound(elements.begin(), elements.end(), station,
                               [](double s, const AlignmentElement& e) { return s < e.staStart; });
    const AlignmentElement& el = it == elements.begin() ? elements.front() : *(it - 1);
    double h = 0;
    elementPoint(el, std::clamp(station - el.staStart, 0.0, el.length), &h);
    return h;
}

std::optional<StationOffset> Alignment::stationOf(PlanPoint p) const {
    if (elements.empty() || !std::isfinite(p.e) || !std::isfinite(p.n))
        return std::nullopt;
    StationOffset best;
    best.distance = 1e300;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const AlignmentElement& el = elements[i];
        const double t = elementFoot(el, p);
        double h = 0;
        const PlanPoint f = elementPoint(el, t, &h);
        const double d = dist(f, p);
        if (d < best.distance - 1e-12) {
            // + right: the component of (p - foot) along the right normal (sin h, -cos h).
            const double side = (p.e - f.e) * std::sin(h) - (p.n - f.n) * std::cos(h);
            const double along = (p.e - f.e) * std::cos(h) + (p.n - f.n) * std::sin(h);
            best.station = el.staStart + t;
            best.distance = d;
            best.offset = side >= 0 ? d : -d;
            best.element = static_cast<int>(i);
            best.inside = !((i == 0 && t <= 0 && along < -1e-9) ||
                            (i + 1 == elements.size() && t >= el.length && along > 1e-9));
            if (best.inside && std::fabs(along) > 1e-6 * std::max(1.0, d))
                best.offset = side; // at a kink: the lateral part
        }
    }
    return best;
}

std::vector<PlanPoint> Alignment::polyline(double maxChord, std::vector<double>* stations) const {
    std::vector<PlanPoint> out;
    if (stations)
        stations->clear();
    if (!(maxChord > 0))
        maxChord = 10;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const AlignmentElement& el = elements[i];
        double chord = maxChord;
        if (el.kind == ElementKind::Arc)
            chord = std::min(maxChord, std::sqrt(8 * el.radius * 0.001));
        else if (el.kind == ElementKind::Spiral) {
            const double k = std::max(std::fabs(el.curvatureStart), std::fabs(el.curvatureEnd));
            if (k > 0)
                chord = std::min(maxChord, std::sqrt(8 * 0.001 / k));
        }
        const int n =
            el.kind == ElementKind::Line ? 1 : std::max(1, static_cast<int>(std::ceil(el.length / chord)));
        for (int k = (i == 0 ? 0 : 1); k <= n; ++k) {
            const double t = el.length * k / n;
            out.push_back(k == n && el.kind == ElementKind::Line ? el.end : elementPoint(el, t, nullptr));
            if (stations)
                stations->push_back(el.staStart + t);
        }
    }
    return out;
}

double DesignBoundary::area() const {
    double a = 0;
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++)
        a += (points[j].e - points[0].e) * (points[i].n - points[0].n) -
             (points[i].e - points[0].e) * (points[j].n - points[0].n);
    return std::fabs(a) / 2;
}

bool DesignBoundary::contains(PlanPoint p) const {
    bool in = false;
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
        const PlanPoint& a = points[i];
        const PlanPoint& b = points[j];
        if ((a.n > p.n) != (b.n > p.n) && p.e < (b.e - a.e) * (p.n - a.n) / (b.n - a.n) + a.e)
            in = !in;
    }
    return in;
}
} // namespace ocu::landxml
