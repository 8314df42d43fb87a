// The platform services in the JAUS panels against a simulated UGV on loopback, through the real bridge and
// the command gate: the teleop panel's lights toggle and the vehicle's report changes it, the control
// panel's platform widget reads the mode, state and odometer, resets the trip, and the emergency platform
// state refuses the teleop drive session with its reason. With OCU_SCREENSHOT_DIR set, the window is saved
// there at 1366x768 (docs/screenshots).
#include "models/CommandGate.h"
#include "models/FleetContext.h"
#include "models/FleetSelection.h"
#include "models/bridges/JausBridge.h"
#include "sim/jaus/JausDemo.h"
#include "widgets/jaus/IlluminationBar.h"
#include "widgets/jaus/JausControlPanel.h"
#include "widgets/jaus/PlatformServicesWidget.h"
#include "widgets/jaus/TeleopPanel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QToolButton>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Site {
    Site() : demo(options()) {
        JausConfig c;
        c.subsystemId = 200;
        c.callSign = "OCU-TEST";
        c.authority = 205;
        c.statusPollHz = 5;
        demo.configure(c);
        bridge = std::make_unique<JausBridge>(c, GeoFrame(options().origin));
        ctx.addBridge(bridge.get());
        const QString e = bridge->start();
        if (!e.isEmpty())
            qFatal("%s", qPrintable(e));
    }
    static sim::JausDemoOptions options() {
        sim::JausDemoOptions o;
        o.count = 1;
        return o;
    }
    JausPlatformServices platform() {
        auto v = bridge->subsystem(126);
        return v ? v->platformServices : JausPlatformServices{};
    }
    sim::JausDemo demo;
    FleetContext ctx;
    std::unique_ptr<JausBridge> bridge;
};

} // namespace

class TestPlatformPanels : public QObject {
    Q_OBJECT
private slots:
    void lightsModeStateOdometerOnTheSimulatedUgv() {
        Site s;
        QWidget w;
        auto* control = new JausControlPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection());
        auto* teleop = new TeleopPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection(), nullptr);
        auto* split = new QSplitter(&w);
        split->addWidget(teleop);
        split->addWidget(control);
        split->setSizes({820, 546});
        (new QHBoxLayout(&w))->addWidget(split);
        w.resize(1366, 768);
        w.show();
        QTRY_VERIFY_WITH_TIMEOUT(s.platform().state && s.platform().lights && s.platform().odometerM, 15000);
        s.ctx.selection()->setCurrent(QStringLiteral("jaus:126"));
        PlatformServicesWidget* platform = control->platformServices();
        QTRY_COMPARE(platform->stateLabel()->text(), QStringLiteral("operational"));
        QCOMPARE(platform->modeLabel()->text(), QStringLiteral("standard"));

        // Lights from the teleop panel: the vehicle's report turns the toggles (control is requested first).
        auto* bar = teleop->findChild<IlluminationBar*>();
        QVERIFY(bar);
        QTRY_VERIFY(bar->toggle(JausLight::RunningLights)->isChecked()); // on from the start
        QTRY_VERIFY(bar->toggle(JausLight::Headlights)->isEnabled());
        bar->toggle(JausLight::Headlights)->click();
        QTRY_VERIFY_WITH_TIMEOUT(bar->toggle(JausLight::Headlights)->isChecked(), 10000);
        bar->toggle(JausLight::LeftTurnSignal)->click();
        QTRY_VERIFY_WITH_TIMEOUT(bar->toggle(JausLight::LeftTurnSignal)->isChecked(), 10000);
        QVERIFY(s.bridge->subsystem(126)->controlledByUs);
        QCOMPARE(*s.platform().lights, bitOf(JausLight::Headlights) | bitOf(JausLight::RunningLights) |
                                           bitOf(JausLight::LeftTurnSignal));

        // Trip reset from the control panel.
        platform->resetTripButton()->click();
        QTRY_VERIFY(s.platform().tripM == 0u);
        QTRY_VERIFY(platform->odometerLabel()->text().contains(QStringLiteral("trip 0 m")));

        if (const QByteArray dir = qgetenv("OCU_SCREENSHOT_DIR"); !dir.isEmpty()) {
            QTest::qWait(500);
            QVERIFY(w.grab().save(QString::fromLocal8Bit(dir) +
                                  QStringLiteral("/jaus-platform-lights-1366x768.png")));
        }

        // The emergency platform state: reported, and the teleop drive session is refused with its reason.
        platform->emergencyButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(s.platform().emergencyState(), 10000);
        QTRY_VERIFY(platform->stateLabel()->text().startsWith(QStringLiteral("emergency")));
        CommandResult refused;
        bool answered = false;
        s.ctx.gate()->command(DriveStart{QStringLiteral("jaus:126"), QStringLiteral("test")},
                              QStringLiteral("gui"), [&](const CommandResult& r) {
                                  refused = r;
                                  answered = true;
                              });
        QTRY_VERIFY(answered);
        QVERIFY(!refused.ok);
        QVERIFY2(QString::fromStdString(refused.targets.value(0).reason)
                     .contains(QStringLiteral("emergency platform state")),
                 qPrintable(refused.message));
    }
};

QTEST_MAIN(TestPlatformPanels)
#include "test_platform_panels.moc"
