// LandXML 1.2 import: the shipped design of the simulated paving job, stationing against points
// computed by hand (from the file's own Start/Center numbers with plain trigonometry, or from the generator's
// unrounded geometry, written here as literals), spirals against the clothoid series, units, and hostile
// input.
#include "protocols/site/LandXml.h"

#include <QtTest>

#include <cmath>

using namespace ocu::landxml;

namespace {

void near(PlanPoint got, double e, double n, double tol, const char* what) {
    const double d = std::hypot(got.e - e, got.n - n);
    if (d > tol)
        QFAIL(qPrintable(QStringLiteral("%1: (%2, %3) is %4 m from (%5, %6)")
                             .arg(what)
                             .arg(got.e, 0, 'f', 4)
                             .arg(got.n, 0, 'f', 4)
                             .arg(d)
                             .arg(e, 0, 'f', 4)
                             .arg(n, 0, 'f', 4)));
}

std::string wrap(const std::string& body) {
    return "<?xml version=\"1.0\"?><LandXML xmlns=\"http://www.landxml.org/schema/LandXML-1.2\" "
           "version=\"1.2\">" +
           body + "</LandXML>";
}

} // namespace

class TestLandXml : public QObject {
    Q_OBJECT
private slots:
    void shippedPavingJob() {
        auto r = loadLandXml(OCU_SOURCE_DIR "/resources/designs/paving-job.xml");
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        const LandXmlDesign& d = *r;
        QVERIFY2(d.warnings.empty(), d.warnings.empty() ? "" : d.warnings.front().c_str());
        QCOMPARE(d.epsg, 32632);
        QCOMPARE(d.alignments.size(), std::size_t(1));
        const Alignment& a = d.alignments[0];
        QCOMPARE(a.name, std::string("Main road"));
        QCOMPARE(a.elements.size(), std::size_t(7));
        QVERIFY(std::fabs(a.length() - 5400.0) < 0.01);
        QCOMPARE(a.staStart, 0.0);

        // Station 0 and the end: the file's first Start and last End ("northing easting").
        near(*a.pointAt(0), 683201.7615, 5342234.7012, 1e-4, "0+000");
        near(*a.pointAt(5400), 687756.4803, 5344377.4133, 0.005, "5+400");
        // 0+450: the midpoint of the first line (Start 683201.7615/5342234.7012, End
        // 684101.2977/5342263.5922).
        near(*a.pointAt(450), (683201.7615 + 684101.2977) / 2, (5342234.7012 + 5342263.5922) / 2, 1e-3,
             "0+450");
        // 0+450, 6 m right: the right normal of the first line (heading atan2(dN, dE)) is (sin h, -cos h).
        const double h = std::atan2(5342263.5922 - 5342234.7012, 684101.2977 - 683201.7615);
        near(*a.pointAt(450, 6), (683201.7615 + 684101.2977) / 2 + 6 * std::sin(h),
             (5342234.7012 + 5342263.5922) / 2 - 6 * std::cos(h), 1e-3, "0+450 R6");
        // 1+150: 250 m into the first (counter-clockwise, R 600) arc: from its Start about its Center.
        {
            const double ce = 684082.0370, cn = 5342863.2830, se = 684101.2977, sn = 5342263.5922;
            const double a0 = std::atan2(sn - cn, se - ce) + 250.0 / 600.0;
            near(*a.pointAt(1150), ce + 600 * std::cos(a0), cn + 600 * std::sin(a0), 2e-3, "1+150 (file)");
        }
        // The same and more from the generator's unrounded geometry (scripts/make-paving-job.py).
        near(*a.pointAt(1150), 684342.3534, 5342322.6950, 2e-3, "1+150");
        near(*a.pointAt(2000), 684927.8485, 5342931.1283, 2e-3, "2+000");
        near(*a.pointAt(2950), 685593.9381, 5343597.1706, 2e-3, "2+950");
        near(*a.pointAt(2950, 4), 685595.5980, 5343593.5313, 2e-3, "2+950 R4");
        QVERIFY(std::fabs(*a.headingAt(2000) - 0.865440025) < 1e-6);
        QVERIFY(!a.pointAt(-0.5));
        QVERIFY(!a.pointAt(5400.5));

        // Point -> station/offset: 3 m left of 2+000 on the second line, 4 m right of 2+950 on the cw arc.
        auto so = a.stationOf({684925.5643, 5342933.0732});
        QVERIFY(so);
        QVERIFY2(std::fabs(so->station - 2000) < 2e-3, qPrintable(QString::number(so->station, 'f', 4)));
        QVERIFY2(std::fabs(so->offset + 3) < 2e-3, qPrintable(QString::number(so->offset, 'f', 4)));
        QVERIFY(so->inside);
        so = a.stationOf({685595.5980, 5343593.5313});
        QVERIFY(std::fabs(so->station - 2950) < 2e-3 && std::fabs(so->offset - 4) < 2e-3);
        QCOMPARE(so->element, 3);
        // Before the start: outside, nearest station 0.
        so = a.stationOf({683201.7615 - 20 * std::cos(h), 5342234.7012 - 20 * std::sin(h)});
        QVERIFY(!so->inside);
        QVERIFY(std::fabs(so->station) < 1e-6 && std::fabs(so->distance - 20) < 1e-3);
        // Round trip at every 37 m with offsets on both sides.
        for (double s = 0; s <= 5400; s += 37)
            for (double off : {-5.5, 0.0, 2.5}) {
                const auto p = a.pointAt(s, off);
                const auto back = a.stationOf(*p);
                QVERIFY(std::fabs(back->station - s) < 1e-3 && std::fabs(back->offset - off) < 1e-3);
            }

        // The 12 m paving boundary and its TIN.
        QCOMPARE(d.boundaries.size(), std::size_t(1));
        const DesignBoundary& b = d.boundaries[0];
        QCOMPARE(b.kind, std::string("outer"));
        QCOMPARE(b.surface, std::string("Paving area"));
        // A band of width w along a curve of length L (offset < radius) has the area w * L; chords cut a
        // little.
        QVERIFY2(std::fabs(b.area() - 12 * 5400) < 0.001 * 12 * 5400, qPrintable(QString::number(b.area())));
        QVERIFY(b.contains(*a.pointAt(1150, 5.9)));
        QVERIFY(b.contains(*a.pointAt(2950, -5.9)));
        QVERIFY(!b.contains(*a.pointAt(2950, 6.5)));
        QCOMPARE(d.surfaces.size(), std::size_t(1));
        QCOMPARE(d.surfaces[0].faces.size(), d.surfaces[0].points.size() - 2);
        QCOMPARE(d.surfaces[0].elevMin, 480.0);

        // The polyline stays on the arcs (sagitta about 1 mm).
        std::vector<double> st;
        const auto line = a.polyline(10, &st);
        QCOMPARE(line.size(), st.size());
        for (std::size_t i = 0; i + 1 < line.size(); ++i) {
            const PlanPoint mid{(line[i].e + line[i + 1].e) / 2, (line[i].n + line[i + 1].n) / 2};
            QVERIFY(a.stationOf(mid)->distance < 0.0015);
        }
    }

    void spiralAgainstClothoidSeries() {
        // A clothoid from a tangent (R = INF) to R = 200 over L = 80 m, starting at (1000, 2000) heading
        // east, turning left. Series: A^2 = R L; x = L - L^5/(40 A^4), y = L^3/(6 A^2) - L^7/(336 A^6).
        const double L = 80, R = 200, A2 = R * L;
        const double x = L - std::pow(L, 5) / (40 * A2 * A2) + std::pow(L, 9) / (3456 * A2 * A2 * A2 * A2);
        const double y = std::pow(L, 3) / (6 * A2) - std::pow(L, 7) / (336 * A2 * A2 * A2);
        const std::string xml = wrap(
            "<Alignments><Alignment name=\"S\" staStart=\"1000\"><CoordGeom>"
            "<Line><Start>2000 900</Start><End>2000 1000</End></Line>"
            "<Spiral length=\"80\" radiusStart=\"INF\" radiusEnd=\"200\" rot=\"ccw\" spiType=\"clothoid\">"
            "<Start>2000 1000</Start><PI>2000 1053.34</PI><End>" +
            std::to_string(2000 + y) + " " + std::to_string(1000 + x) +
            "</End></Spiral></CoordGeom></Alignment></Alignments>");
        auto r = parseLandXml(xml);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QVERIFY2(r->warnings.empty(), r->warnings.empty() ? "" : r->warnings.front().c_str());
        const Alignment& a = r->alignments[0];
        QCOMPARE(a.staStart, 1000.0);
        QVERIFY(std::fabs(a.staEnd() - 1180) < 1e-9);
        near(*a.pointAt(1050), 950, 2000, 1e-9, "line");
        near(*a.pointAt(1180), 1000 + x, 2000 + y, 1e-4, "spiral end");
        // Heading at the end: L / (2R).
        QVERIFY(std::fabs(*a.headingAt(1180) - L / (2 * R)) < 1e-9);
        const auto so = a.stationOf(*a.pointAt(1140, -1.5));
        QVERIFY(std::fabs(so->station - 1140) < 1e-3 && std::fabs(so->offset + 1.5) < 1e-3);
    }

    void unitsPlanFeaturesAndCurveFromPi() {
        // US survey feet; a clockwise curve given by PI and radius (no Center); a closed plan feature.
        const double ft = 1200.0 / 3937.0;
        const std::string xml = wrap(
            "<Units><Imperial linearUnit=\"USSurveyFoot\"/></Units>"
            "<CoordinateSystem epsgCode=\"2229\"/>"
            "<Alignments><Alignment name=\"F\" staStart=\"100\"><CoordGeom>"
            "<Curve rot=\"cw\" radius=\"100\"><Start>0 0</Start><PI>0 100</PI><End>-100 100</End></Curve>"
            "</CoordGeom></Alignment></Alignments>"
            "<PlanFeatures><PlanFeature name=\"Pad\"><CoordGeom>"
            "<Line><Start>0 0</Start><End>0 10</End></Line><Line><Start>0 10</Start><End>10 10</End></Line>"
            "<Line><Start>10 10</Start><End>0 0</End></Line></CoordGeom></PlanFeature></PlanFeatures>");
        auto r = parseLandXml(xml);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QCOMPARE(r->epsg, 2229);
        QCOMPARE(r->linearUnit, std::string("USSurveyFoot"));
        const Alignment& a = r->alignments[0];
        QVERIFY(std::fabs(a.staStart - 100 * ft) < 1e-9);
        // Quarter circle of 100 ft: length pi/2 * 100 ft; centre (0, -100) ft; halfway at 45 degrees.
        QVERIFY(std::fabs(a.length() - M_PI / 2 * 100 * ft) < 1e-9);
        near(*a.pointAt(a.staStart + a.length() / 2), 100 * ft * std::sin(M_PI / 4),
             -100 * ft + 100 * ft * std::cos(M_PI / 4), 1e-9, "cw arc middle");
        QCOMPARE(r->boundaries.size(), std::size_t(1));
        QCOMPARE(r->boundaries[0].name, std::string("Pad"));
        QVERIFY(std::fabs(r->boundaries[0].area() - 50 * ft * ft) < 1e-9);
        QCOMPARE(formatStation(1234.5), std::string("1+234.50"));
        QCOMPARE(formatStation(12.345, 1), std::string("0+012.3"));
        QCOMPARE(formatStation(-12.0, 0), std::string("-0+012"));
    }

    void hostileInputIsRefusedOrReported() {
        QVERIFY(!parseLandXml("").ok());
        QVERIFY(!parseLandXml("<notLandXML/>").ok());
        QVERIFY(QString::fromStdString(parseLandXml("<LandXML><Alignments>").error()).contains("XML"));
        // Nothing usable.
        QVERIFY(!parseLandXml(wrap("")).ok());
        // A broken element drops its alignment with a warning; the good one stays.
        auto r =
            parseLandXml(wrap("<Alignments>"
                              "<Alignment name=\"bad\"><CoordGeom><Line><Start>0 0</Start></Line></CoordGeom>"
                              "</Alignment>"
                              "<Alignment name=\"nan\"><CoordGeom><Line><Start>nan 0</Start><End>1 1</End>"
                              "</Line></CoordGeom></Alignment>"
                              "<Alignment name=\"odd\"><CoordGeom><Chain>1 2</Chain></CoordGeom></Alignment>"
                              "<Alignment name=\"arc\"><CoordGeom><Curve rot=\"cw\"><Start>0 0</Start>"
                              "<Center>0 10</Center><End>0 30</End></Curve></CoordGeom></Alignment>"
                              "<Alignment name=\"good\"><CoordGeom><Line><Start>0 0</Start><End>0 10</End>"
                              "</Line></CoordGeom></Alignment></Alignments>"));
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QCOMPARE(r->alignments.size(), std::size_t(1));
        QCOMPARE(r->alignments[0].name, std::string("good"));
        QVERIFY(r->warnings.size() >= 4);
        // Limits: too many elements, too large, boundary vertex budget.
        LandXmlLimits lim;
        lim.maxElements = 2;
        auto many = parseLandXml(wrap("<Alignments><Alignment><CoordGeom>"
                                      "<Line><Start>0 0</Start><End>0 1</End></Line>"
                                      "<Line><Start>0 1</Start><End>0 2</End></Line>"
                                      "<Line><Start>0 2</Start><End>0 3</End></Line>"
                                      "</CoordGeom></Alignment></Alignments>"),
                                 lim);
        QVERIFY(!many.ok());
        QVERIFY(QString::fromStdString(many.error()).contains("more than 2"));
        lim = {};
        lim.maxBytes = 10;
        QVERIFY(QString::fromStdString(parseLandXml(wrap(""), lim).error()).contains("larger"));
        lim = {};
        lim.maxBoundaryVertices = 3;
        auto big =
            parseLandXml(wrap("<Surfaces><Surface><SourceData><Boundaries><Boundary><PntList2D>0 0 0 1 1 1 "
                              "1 0 0.5 0.5</PntList2D></Boundary></Boundaries></SourceData></Surface>"
                              "</Surfaces>"),
                         lim);
        QVERIFY(!big.ok());
        // Entities are not expanded (no billion laughs); huge coordinates are refused.
        auto ent =
            parseLandXml("<!DOCTYPE LandXML [<!ENTITY a \"1 1 1 1 1 1 1 1\"><!ENTITY b \"&a;&a;&a;&a;\">]>"
                         "<LandXML><Alignments><Alignment><CoordGeom><Line><Start>&b;</Start><End>0 1</End>"
                         "</Line></CoordGeom></Alignment></Alignments></LandXML>");
        QVERIFY(!ent.ok());
        auto far =
            parseLandXml(wrap("<Alignments><Alignment><CoordGeom><Line><Start>0 0</Start><End>1e12 1</End>"
                              "</Line></CoordGeom></Alignment></Alignments>"));
        QVERIFY(!far.ok());
        // Deep nesting parses without recursion and is ignored.
        std::string deep = "<LandXML>";
        for (int i = 0; i < 200000; ++i)
            deep += "<a>";
        for (int i = 0; i < 200000; ++i)
            deep += "</a>";
        deep += "</LandXML>";
        QVERIFY(!parseLandXml(deep).ok());
        // Faces naming unknown points are skipped and reported.
        auto tin = parseLandXml(wrap("<Surfaces><Surface name=\"T\"><Definition><Pnts><P id=\"1\">0 0 1</P>"
                                     "<P id=\"2\">0 1 1</P><P id=\"3\">1 0 2</P></Pnts><Faces><F>1 2 3</F>"
                                     "<F>1 2 9</F><F>1 2 3 4</F></Faces></Definition></Surface></Surfaces>"));
        QVERIFY(tin.ok());
        QCOMPARE(tin->surfaces[0].faces.size(), std::size_t(1));
        QCOMPARE(tin->surfaces[0].elevMax, 2.0);
        QVERIFY(!tin->warnings.empty());
    }
};

QTEST_GUILESS_MAIN(TestLandXml)
#include "test_landxml.moc"
