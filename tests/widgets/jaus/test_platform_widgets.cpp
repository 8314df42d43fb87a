// The platform services' widgets against a fake JAUS bridge: the lights bar (toggles showing the vehicle's
// report, a click sending SetLights through the gate, lights the vehicle lacks disabled, no visible-light
// switch, a vehicle without the service), the control panel's platform widget (mode and state as reported,
// the emergency state at once, other states only after confirming, trip reset, the comms-lost service and
// its version) and the details tree's platform rows.
#include "models/FleetContext.h"
#include "models/jaus/JausVehicleBridge.h"
#include "tests/widgets/jaus/FakeJausBridge.h"
#include "widgets/jaus/IlluminationBar.h"
#include "widgets/jaus/PlatformServicesWidget.h"
#include "widgets/jaus/VehicleDetailsWidget.h"

#include <QComboBox>
#include <QLabel>
#include <QMap>
#include <QPushButton>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

using namespace ocu;

namespace {

using ocu::testing::FakeJausBridge;

JausOfferedService offered(const char* uri, int minor) {
    return JausOfferedService{true, QString::fromLatin1(uri), 1, minor};
}

JausVehicle ugv() {
    JausVehicle v;
    v.subsystem = 126;
    v.callSign = QStringLiteral("UGV-126");
    v.link = JausLink::Up;
    JausPlatformServices& p = v.platformServices;
    p.modeService = offered("urn:jaus:jss:iop:PlatformMode", 1);
    p.stateService = offered("urn:jaus:jss:iop:PlatformState", 1);
    p.illuminationService = offered("urn:jaus:jss:ugv:IlluminationService", 0);
    p.odometryService = offered("urn:jaus:jss:ugv:OdometryService", 0);
    p.mode = 0;
    p.state = 1;
    p.supportedModes = {0, 1};
    p.lights = bitOf(JausLight::Headlights);
    p.lightsSupported = bitOf(JausLight::Headlights) | bitOf(JausLight::LeftTurnSignal) |
                        bitOf(JausLight::RightTurnSignal) | bitOf(JausLight::IrSource);
    p.odometerM = 1234;
    p.tripM = 56;
    return v;
}

struct Rig {
    FakeJausBridge bridge;
    FleetContext ctx;
    Rig() {
        ctx.addBridge(&bridge);
        bridge.report(ugv());
    }
};

} // namespace

class TestPlatformWidgets : public QObject {
    Q_OBJECT
private slots:
    void lightsShowTheReportAndSendThroughTheGate() {
        Rig r;
        IlluminationBar bar(&r.bridge, r.ctx.gate(), [] { return quint16(126); });
        QToolButton* head = bar.toggle(JausLight::Headlights);
        QToolButton* left = bar.toggle(JausLight::LeftTurnSignal);
        QVERIFY(head && left);
        QVERIFY(head->isChecked());
        QVERIFY(!left->isChecked());
        QVERIFY(!bar.toggle(JausLight::BrakeLights)->isEnabled()); // the vehicle has none
        QVERIFY(bar.findChild<QToolButton*>("light-visible_light") == nullptr);
        left->click();
        QTRY_COMPARE(r.bridge.commands.size(), 1);
        QCOMPARE(std::get<SetLights>(r.bridge.commands[0]),
                 (SetLights{"jaus:126", bitOf(JausLight::LeftTurnSignal), bitOf(JausLight::LeftTurnSignal)}));
        QVERIFY(!left->isChecked()); // not before the vehicle reports it
        JausVehicle v = ugv();
        v.platformServices.lights = bitOf(JausLight::Headlights) | bitOf(JausLight::LeftTurnSignal);
        r.bridge.report(v);
        QVERIFY(left->isChecked());
        head->click(); // on -> off
        QTRY_COMPARE(r.bridge.commands.size(), 2);
        QCOMPARE(std::get<SetLights>(r.bridge.commands[1]).on, 0u);
        // A vehicle without the Illumination service: no toggles, the label says so.
        v.platformServices.illuminationService = {};
        r.bridge.report(v);
        QVERIFY(!head->isVisibleTo(&bar));
        QVERIFY(bar.findChild<QLabel*>()->text().contains("not offered"));
    }

    void modeStateAndTrip() {
        Rig r;
        PlatformServicesWidget w(&r.bridge, r.ctx.gate());
        QStringList asked;
        bool answer = false;
        w.setConfirm([&](const QString& q) {
            asked << q;
            return answer;
        });
        w.setVehicle(126);
        QCOMPARE(w.modeLabel()->text(), QStringLiteral("standard"));
        QCOMPARE(w.stateLabel()->text(), QStringLiteral("operational"));
        QVERIFY(w.odometerLabel()->text().contains("1234 m"));
        QVERIFY(w.odometerLabel()->text().contains("56 m"));
        QVERIFY(w.commsLostLabel()->text().contains("not offered"));
        // Mode: training (maintenance is not among the supported modes: not selectable).
        w.modeChoice()->setCurrentIndex(1);
        w.setModeButton()->click();
        QTRY_COMPARE(r.bridge.commands.size(), 1);
        QCOMPARE(std::get<SetPlatformMode>(r.bridge.commands[0]).mode, 1);
        // The emergency state goes at once; shutdown only once confirmed.
        w.emergencyButton()->click();
        QTRY_COMPARE(r.bridge.commands.size(), 2);
        QCOMPARE(std::get<SetPlatformState>(r.bridge.commands[1]).state, 4);
        QVERIFY(asked.isEmpty());
        w.stateChoice()->setCurrentIndex(w.stateChoice()->findData(2));
        w.setStateButton()->click();
        QCOMPARE(asked.size(), 1);
        QVERIFY(asked[0].contains("shutdown"));
        QCOMPARE(r.bridge.commands.size(), 2); // declined: nothing sent
        answer = true;
        w.setStateButton()->click();
        QTRY_COMPARE(r.bridge.commands.size(), 3);
        QCOMPARE(std::get<SetPlatformState>(r.bridge.commands[2]).state, 2);
        w.resetTripButton()->click();
        QTRY_COMPARE(r.bridge.commands.size(), 4);
        QCOMPARE(std::get<Odometry>(r.bridge.commands[3]), (Odometry{"jaus:126", true}));
        // What the vehicle reports, with its refusal and its comms-lost service.
        JausVehicle v = ugv();
        v.platformServices.state = 4;
        v.platformServices.stateRefusal = QStringLiteral("the vehicle refused platform state shutdown");
        v.platformServices.commsLostService = offered("urn:jaus:jss:iop:CommsLostPolicyManager", 1);
        r.bridge.report(v);
        QVERIFY(w.stateLabel()->text().startsWith("emergency"));
        QVERIFY(w.stateLabel()->text().contains("refused"));
        QVERIFY(!w.emergencyButton()->isEnabled());
        QVERIFY(w.commsLostLabel()->text().contains("CommsLostPolicyManager 1.1"));
        QVERIFY(w.commsLostLabel()->text().contains("published"));
        // Without the services: every command disabled.
        v.platformServices = {};
        r.bridge.report(v);
        QCOMPARE(w.stateLabel()->text(), QStringLiteral("not offered"));
        QVERIFY(!w.emergencyButton()->isEnabled() && !w.setModeButton()->isEnabled() &&
                !w.resetTripButton()->isEnabled());
    }

    void detailsTreeRows() {
        Rig r;
        VehicleDetailsWidget d(&r.bridge);
        d.showSubsystem(126);
        auto find = [&](const QString& key) {
            const auto items = d.tree()->findItems(key, Qt::MatchExactly | Qt::MatchRecursive);
            return items.isEmpty() ? QString() : items.first()->text(1);
        };
        QCOMPARE(find("Platform state"), QStringLiteral("operational"));
        QCOMPARE(find("Lights"), QStringLiteral("headlights"));
        QCOMPARE(find("Odometer"), QStringLiteral("1234 m"));
        QCOMPARE(find("Comms-lost policy service"), QStringLiteral("not offered"));
    }
};

QTEST_MAIN(TestPlatformWidgets)
#include "test_platform_widgets.moc"
