// The simulated paving train on a long job: the built-in line/arc/line path, the shipped
// LandXML design converted from UTM to the worksite frame, machines following the centre line lift after lift
// (z rises by the lift thickness), the drivers' "lift n done" messages, and the pass counts of a simulated
// run falling into the job's lifts.
#include "protocols/osyris/PassCountGrid.h"
#include "sim/osyris/PavingJob.h"
#include "sim/osyris/SimulatedRoller.h"

#include <GeographicLib/UTMUPS.hpp>

#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::sim::osyris;

class TestPavingJob : public QObject {
    Q_OBJECT
private slots:
    void builtInPath() {
        const PavingJob j = builtInPavingJob();
        QVERIFY(std::abs(j.length() - 2600) < 0.5);
        double x, y, h;
        j.at(450, 0, x, y, h);
        QVERIFY(std::abs(x - 450) < 1e-9 && std::abs(y) < 1e-9 && std::abs(h) < 1e-9);
        j.at(450, 3, x, y, h); // 3 m to the left of eastward travel is north
        QVERIFY(std::abs(y - 3) < 1e-9);
        // 250 m into the arc (R 600 about (900, 600)): on the circle, heading turned left by 250/600 rad.
        j.at(1150, 0, x, y, h);
        QVERIFY2(std::abs(std::hypot(x - 900, y - 600) - 600) < 0.01,
                 qPrintable(QString::number(std::hypot(x - 900, y - 600))));
        QVERIFY(std::abs(h - 250.0 / 600) < 0.01);
        int lift = -1;
        double st = -1;
        j.liftOf(2600 * 1.5, lift, st);
        QCOMPARE(lift, 1);
        QVERIFY(std::abs(st - 1300) < 0.5);
        j.liftOf(2600 * 10, lift, st); // after the last lift: parked at the end of the last
        QCOMPARE(lift, 2);
        QVERIFY(std::abs(st - j.length()) < 1e-9);
    }

    void shippedLandXmlInTheSiteFrame() {
        // Origin = the alignment's first point: the job then starts at (0, 0) of the local frame.
        double lat = 0, lon = 0;
        GeographicLib::UTMUPS::Reverse(32, true, 683201.7615, 5342234.7012, lat, lon);
        auto r = pavingJobFromLandXml(OCU_SOURCE_DIR "/resources/designs/paving-job.xml", {lat, lon, 500});
        QVERIFY2(r, r ? "" : r.error().c_str());
        const PavingJob& j = r.value();
        QVERIFY2(std::abs(j.length() - 5400) < 3, qPrintable(QString::number(j.length())));
        QVERIFY(std::hypot(j.xs.front(), j.ys.front()) < 0.01);
        // The first element heads from 683201.76 E to 684101.30 E (900 m, nearly east).
        double x, y, h;
        j.at(900, 0, x, y, h);
        QVERIFY2(std::abs(std::hypot(x, y) - 900) < 1.0, qPrintable(QStringLiteral("%1 %2").arg(x).arg(y)));
        QVERIFY(!pavingJobFromLandXml("/nonexistent.xml", {lat, lon, 500}));
    }

    void machinesFollowTheLineLiftAfterLift() {
        auto job = std::make_shared<PavingJob>(builtInPavingJob());
        job->lifts = 2;
        job->liftThickness = 0.06;
        job->paverSpeed = 10.0; // fast, so a lift takes 260 s
        MachineSpec paver = paverSpec();
        paver.job = job;
        paver.paverStartX = 0;
        paver.paverSpeed = job->paverSpeed;
        const SimulatedMachine m(paver);
        const auto p1 = m.poseAt(115); // 1150 m: on the arc, lift 0
        QVERIFY(std::abs(std::hypot(p1.x - 900, p1.y - 600) - 600) < 0.05);
        QVERIFY(std::abs(p1.z - job->zOf(0)) < 1e-4);
        const auto p2 = m.poseAt(260 + 45); // lift 1, 450 m
        QVERIFY(std::abs(p2.x - 450) < 0.05 && std::abs(p2.y) < 0.05);
        QVERIFY(std::abs(p2.z - p1.z - 0.06) < 1e-4);
        QCOMPARE(m.crewMessage(259, 261).value_or(""), std::string("Paver: lift 1 done"));
    }

    void rollersCountIntoTheJobsLifts() {
        auto job = std::make_shared<PavingJob>(builtInPavingJob());
        job->lifts = 2;
        job->liftThickness = 0.05;
        job->paverSpeed = 0.2; // the rollers (1.2 m/s over 30 m) make ~5 passes while the paver moves on 30 m
        MachineSpec roller = rollerSpec("Roller 1", 0, 2.0, 0, 1);
        roller.job = job;
        roller.paverStartX = 0;
        roller.paverSpeed = job->paverSpeed;
        roller.vibrationOffEvery = 0;
        roller.mediumAccuracyRate = 0;
        const SimulatedMachine m(roller);
        osyris::PassCountSettings s;
        s.liftThickness = job->liftThickness;
        s.liftBase = job->baseZ;
        osyris::PassCountGrid g(s);
        std::uint32_t slot = 0;
        for (double t = 0; t < 2 * 2600 / 0.2 + 400; t += 0.5) {
            auto p = m.poseAt(t);
            p.slot = slot++;
            g.addPosition(1, p);
        }
        auto snap = g.snapshot();
        QCOMPARE(snap->liftCount(), 2);
        QVERIFY(std::abs(snap->liftBottom(1) - (job->baseZ + 0.05)) < 1e-9);
        // Both lifts were rolled over most of the line with several passes.
        QVERIFY(snap->summary(0).coveredAreaM2 > 2000 * 1.5);
        QVERIFY(snap->summary(1).coveredAreaM2 > 2000 * 1.5);
        QVERIFY2(snap->summary(0).percentWithin + snap->summary(0).percentAbove > 50,
                 qPrintable(QString::number(snap->summary(0).percentBelow)));
    }
};

QTEST_GUILESS_MAIN(TestPavingJob)
#include "test_paving_job.moc"
