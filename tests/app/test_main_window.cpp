#include "app/MainWindow.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

using namespace ocu;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // QSettings go to a test location
        QCoreApplication::setOrganizationName("OCU-test");
        QCoreApplication::setApplicationName("test_main_window");
    }
    void everyPanelIsADock() {
        MainWindow w;
        QCOMPARE(MainWindow::panels().size(), 7);
        QStringList titles;
        for (Panel p : MainWindow::panels()) {
            QDockWidget* d = w.dock(p);
            QVERIFY(d);
            QVERIFY(d->features() & QDockWidget::DockWidgetClosable);
            QVERIFY(d->features() & QDockWidget::DockWidgetMovable);
            titles << d->windowTitle();
        }
        QCOMPARE(titles, QStringList({"Fleet", "Site map (2D)", "Site 3D", "JAUS control", "Teleop",
                                      "Pass counts", "Event log"}));
    }
    void stopAllAlwaysVisibleWithShortcut() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.stopAllButton());
        QVERIFY(w.stopAllButton()->isVisible());
        QCOMPARE(w.stopAllAction()->shortcut(), QKeySequence(Qt::Key_F12));
        QCOMPARE(w.stopAllAction()->shortcutContext(), Qt::ApplicationShortcut);
        // The safety toolbar cannot be hidden, moved off or floated.
        auto* tb = w.findChild<QToolBar*>("toolbar-safety");
        QVERIFY(tb);
        QVERIFY(!tb->isMovable());
        QVERIFY(!tb->toggleViewAction()->isVisible());
        QSignalSpy spy(&w, &MainWindow::stopAllRequested);
        QTest::keyClick(&w, Qt::Key_F12);
        QCOMPARE(spy.count(), 1);
        QTest::mouseClick(w.stopAllButton(), Qt::LeftButton);
        QCOMPARE(spy.count(), 2);
        // Keyboard: focus the button and press Space.
        w.stopAllButton()->setFocus();
        QTest::keyClick(w.stopAllButton(), Qt::Key_Space);
        QCOMPARE(spy.count(), 3);
    }
    void closeAndReopenPanel() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QDockWidget* d = w.dock(Panel::EventLog);
        QVERIFY(d->isVisible());
        d->close();
        QVERIFY(!d->isVisible());
        d->toggleViewAction()->trigger(); // View menu entry
        QVERIFY(d->isVisible());
    }
    void layoutIsSavedAndRestored() {
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.dock(Panel::PassCounts)->close();
            w.dock(Panel::Fleet)->setFloating(true);
            w.saveLayout();
        }
        MainWindow w2;
        QVERIFY(w2.restoreLayout());
        w2.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w2));
        QVERIFY(!w2.dock(Panel::PassCounts)->isVisible());
        QVERIFY(w2.dock(Panel::Fleet)->isFloating());
        w2.resetLayout();
        QVERIFY(w2.dock(Panel::PassCounts)->isVisible());
        QVERIFY(!w2.dock(Panel::Fleet)->isFloating());
    }
    void nightPalette() {
        MainWindow w;
        const QColor day = qApp->palette().color(QPalette::Window);
        w.setNightMode(true);
        const QColor night = qApp->palette().color(QPalette::Window);
        QVERIFY(night.lightness() < 80);
        QVERIFY(day != night);
        w.setNightMode(false);
        QVERIFY(qApp->palette().color(QPalette::Window).lightness() > 150);
    }
    void linkIndicatorsAndAlarms() {
        MainWindow w;
        // The runtime adds one indicator per protocol module.
        QVERIFY(!w.linkIndicator("JAUS"));
        for (const char* p : {"JAUS", "ISO 23725", "OSYRIS"}) {
            LinkIndicator* added = w.addLinkIndicator(p);
            QVERIFY(added);
            QCOMPARE(w.linkIndicator(p), added);
        }
        LinkIndicator* j = w.linkIndicator("JAUS");
        j->setState(LinkIndicator::State::Up);
        j->setDataAgeMs(1500);
        QVERIFY2(j->text().startsWith("JAUS up · 1.5 s"), qPrintable(j->text()));
        j->setState(LinkIndicator::State::Down);
        QVERIFY(j->text().startsWith("JAUS down"));
        w.setUnacknowledgedAlarms(3);
        auto* label = w.findChild<QLabel*>("label-alarms");
        QVERIFY(label->text().contains("3"));
        w.setUnacknowledgedAlarms(0);
        QCOMPARE(label->text(), QString("No unacknowledged alarms"));
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
