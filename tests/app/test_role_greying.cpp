// Panels grey out what the operator's role may not do: in the whole console on the built-in site, a monitor
// finds JAUS "Control", the dispatcher's "Assign" and the teleop's "Hold to clear emergency" disabled, each
// tooltip naming the role needed, while the E-STOP stays enabled; a switch to the supervisor enables them
// again. The same for every other panel's commands: the mission buttons, the platform services, the lights,
// automatic dispatch and the crew messages' Send. The gate's table decides (app/modules/*Module.cpp,
// CommandPermissions).
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "models/OperatorSession.h"
#include "models/commands/CommandPermissions.h"
#include "models/jaus/JausSubsystemModel.h"
#include "widgets/jaus/JausControlPanel.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/TeleopPanel.h"

#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <memory>

using namespace ocu;
using R = OperatorRole;

namespace {

struct Console {
    QTemporaryDir recordings;
    std::unique_ptr<SiteRuntime> runtime;
    std::unique_ptr<MainWindow> window;
    bool open() {
        auto site = loadSite(QString());
        if (!site.ok() || !recordings.isValid())
            return false;
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = recordings.path().toStdString();
        runtime = std::make_unique<SiteRuntime>(cfg);
        runtime->start();
        window = std::make_unique<MainWindow>();
        runtime->populate(*window);
        window->setWorkspace(Workspace::All);
        window->resize(1920, 1080);
        window->show();
        return QTest::qWaitForWindowExposed(window.get());
    }
    void signIn(R role) {
        runtime->operatorSession()->setOperator({QStringLiteral("tester"), role, QStringLiteral("ocu-test")});
    }
    ~Console() {
        window.reset(); // before the runtime whose models it shows
        runtime.reset();
    }
};

} // namespace

class TestRoleGreying : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void monitorSeesCommandsGreyedWithTheRoleNeeded() {
        Console c;
        QVERIFY(c.open());
        c.signIn(R::Supervisor);
        MainWindow& w = *c.window;
        auto* jaus = w.findChild<JausControlPanel*>();
        auto* teleop = w.findChild<TeleopPanel*>();
        QVERIFY(jaus && teleop);
        QTRY_VERIFY_WITH_TIMEOUT(jaus->model()->rowCount() > 0, 20000);
        const std::uint16_t sub = jaus->model()->subsystemAt(0);
        QTRY_VERIFY_WITH_TIMEOUT(jaus->controlButton(sub) && jaus->controlButton(sub)->isEnabled(), 20000);
        QPushButton* control = jaus->controlButton(sub);
        QPushButton* releaseAll = jaus->findChild<QPushButton*>(QStringLiteral("button-release-all"));
        QVERIFY(releaseAll && releaseAll->isEnabled());

        // A truck selected in the dispatch table: Assign is enabled for the supervisor.
        auto* assign = w.findChild<QPushButton*>(QStringLiteral("button-assign"));
        auto* trucks = w.findChild<QTableView*>(QStringLiteral("dispatch-table"));
        QVERIFY(assign && trucks);
        QTRY_VERIFY_WITH_TIMEOUT(trucks->model()->rowCount() > 0, 20000);
        trucks->setCurrentIndex(trucks->model()->index(0, 0));
        QTRY_VERIFY_WITH_TIMEOUT(assign->isEnabled(), 20000);

        // The teleop's vehicle in emergency (its E-STOP): clearing it is enabled for the supervisor.
        auto* estop = teleop->findChild<QPushButton*>(QStringLiteral("button-estop"));
        auto* clear = teleop->findChild<QWidget*>(QStringLiteral("button-clear-emergency"));
        QVERIFY(estop && clear);
        QTRY_VERIFY_WITH_TIMEOUT(estop->isEnabled(), 20000);
        estop->click();
        QTRY_VERIFY_WITH_TIMEOUT(clear->isEnabled(), 20000);
        const QString assignTip = assign->toolTip();
        QVERIFY(!assignTip.contains(QStringLiteral("Needs")));

        // The monitor: greyed, each tooltip naming the role needed; the stop stays.
        c.signIn(R::Monitor);
        QVERIFY(!control->isEnabled());
        QVERIFY(!releaseAll->isEnabled());
        QVERIFY(!assign->isEnabled());
        QVERIFY(!clear->isEnabled());
        QVERIFY(estop->isEnabled());
        const QString you = QStringLiteral("(you are %1)").arg(roleDisplayName(R::Monitor));
        for (const auto& [widget, role] : {std::pair<QWidget*, R>{control, R::UgvOperator},
                                           {releaseAll, R::UgvOperator},
                                           {assign, R::Dispatcher},
                                           {clear, R::Dispatcher}}) {
            const QString tip = widget->toolTip();
            QVERIFY2(tip.contains(roleDisplayName(role)) && tip.contains(you), qPrintable(tip));
        }
        QVERIFY2(assign->toolTip().startsWith(assignTip),
                 qPrintable(assign->toolTip())); // its own text stays

        // A role that may: enabled again, the refusal gone from the tooltips.
        c.signIn(R::Supervisor);
        QVERIFY(control->isEnabled());
        QVERIFY(releaseAll->isEnabled());
        QVERIFY(assign->isEnabled());
        QVERIFY(clear->isEnabled());
        for (QWidget* widget : {static_cast<QWidget*>(control), static_cast<QWidget*>(releaseAll),
                                static_cast<QWidget*>(assign), clear})
            QVERIFY2(!widget->toolTip().contains(you), qPrintable(widget->toolTip()));
        QCOMPARE(assign->toolTip(), assignTip);

        // The UGV operator may take control and clear, not assign.
        c.signIn(R::UgvOperator);
        QVERIFY(control->isEnabled());
        QVERIFY(clear->isEnabled());
        QVERIFY(!assign->isEnabled());
    }

    void everyPanelGreysItsCommands() {
        Console c;
        QVERIFY(c.open());
        c.signIn(R::Supervisor);
        MainWindow& w = *c.window;
        auto* jaus = w.findChild<JausControlPanel*>();
        auto* mission = w.findChild<MissionPanel*>();
        QVERIFY(jaus && mission);
        QTRY_VERIFY_WITH_TIMEOUT(jaus->model()->rowCount() > 0, 20000);
        // A vehicle chosen: the platform services, the mission panel and the teleop's lights show it.
        auto* table = jaus->findChild<QTableView*>();
        QVERIFY(table);
        table->setCurrentIndex(jaus->model()->index(0, 0));

        QList<std::pair<QWidget*, R>> controls;
        using A = MissionPanel::Action;
        for (A a : {A::Upload, A::Start, A::Pause, A::Resume, A::Abort})
            controls.append({mission->button(a), R::UgvOperator});
        for (const char* name :
             {"platform-set-mode", "platform-set-state", "platform-emergency", "platform-reset-trip"})
            controls.append({w.findChild<QPushButton*>(QLatin1String(name)), R::UgvOperator});
        int lights = 0;
        for (QToolButton* b : w.findChildren<QToolButton*>())
            if (b->objectName().startsWith(QLatin1String("light-")) && ++lights)
                controls.append({b, R::UgvOperator});
        QVERIFY(lights > 0);
        auto* autoDispatch = w.findChild<QPushButton*>(QStringLiteral("button-auto-dispatch"));
        auto* send = w.findChild<QPushButton*>(QStringLiteral("crew-send"));
        controls.append({autoDispatch, R::Dispatcher});
        controls.append({send, R::SiteManager});
        for (const auto& [widget, role] : controls)
            QVERIFY2(widget != nullptr, qPrintable(roleDisplayName(role)));
        // Send needs a text, automatic dispatch nothing else: both enabled for the supervisor.
        auto* entry = send->parentWidget()->findChild<QLineEdit*>();
        QVERIFY(entry);
        entry->setText(QStringLiteral("next lift at 14:00"));
        QVERIFY(send->isEnabled());
        QVERIFY(autoDispatch->isEnabled());

        const QString you = QStringLiteral("(you are %1)").arg(roleDisplayName(R::Monitor));
        c.signIn(R::Monitor);
        for (const auto& [widget, role] : controls) {
            const QString tip = widget->toolTip();
            QVERIFY2(!widget->isEnabled(), qPrintable(widget->objectName() + QLatin1Char(' ') + tip));
            QVERIFY2(tip.contains(roleDisplayName(role)) && tip.contains(you),
                     qPrintable(widget->objectName() + QLatin1Char(' ') + tip));
        }
        c.signIn(R::Supervisor);
        for (const auto& [widget, role] : controls)
            QVERIFY2(!widget->toolTip().contains(you), qPrintable(widget->toolTip()));
        QVERIFY(send->isEnabled());
        QVERIFY(autoDispatch->isEnabled());
    }
};

QTEST_MAIN(TestRoleGreying)
#include "test_role_greying.moc"
