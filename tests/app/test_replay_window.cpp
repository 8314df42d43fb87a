// The replay window - REPLAY banner, commands disabled, the timeline (markers that jump, exact
// time entry, slider) and the keys (Space, + / -, arrows, Home / End) driving the replay controller.
#include "app/MainWindow.h"
#include "app/ProtocolModule.h"
#include "app/ReplayRuntime.h"
#include "models/AlarmModel.h"
#include "models/FleetModel.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "tests/support/RecordedUgvs.h"
#include "widgets/EventLogWidget.h"
#include "widgets/PassCountPanel.h"
#include "widgets/ReplayTimeline.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace ocu;
using namespace ocu::recording;

class TestReplayWindow : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_file;
    const qint64 m_t0 = 1'700'000'000'000;

private slots:
    void initTestCase() {
        // 60 s of two machines at 10 Hz; an alarm at +20 s, a command at +40 s.
        m_file = m_dir.filePath(QStringLiteral("w.sqlite"));
        auto clock = std::make_shared<ManualModelClock>(m_t0);
        Recorder rec;
        RecorderOptions o;
        o.path = m_file;
        o.clock = clock;
        QVERIFY(rec.start(o).isEmpty());
        // Pass counts (OSYRIS): one cell passed once at the start, a strip of 5 cells twice at +20 s, a
        // second grid (finer, after a re-layout) at +40 s.
        GridPassCountLayer grid(QPointF(0, 0), 1.0, 20, 20);
        grid.setCount(3, 3, 1);
        rec.watchPassCounts(&grid);
        GridPassCountLayer finer(QPointF(-10, -10), 0.5, 40, 40);
        recordtest::recordTwoUgvs(rec, *clock, m_t0, 600, [&](int step) {
            if (step == 200) {
                rec.recordEvent(recordtest::controlLostAlarm(clock->nowMs()));
                for (int col = 0; col < 5; ++col)
                    grid.setCount(col, 7, 2);
                rec.recordPassCountsNow();
            }
            if (step == 250)
                rec.recordPassCountsNow(); // nothing changed: nothing recorded
            if (step == 400) {
                finer.fillRect(QRect(0, 0, 4, 4), 3);
                rec.watchPassCounts(&finer);
                rec.recordCommand(
                    QStringLiteral(R"({"origin":"gui","action":"stop","target":"jaus:101","ok":true})"));
            }
        });
        rec.stop();
    }

    // At T the map's overlay and the pass-count panel's histogram show the counts of T, seeking either way.
    void passCountsFollowTheReplayTime() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        QVERIFY(rec->hasPassCounts());
        int rows = 0;
        rec->passCounts(std::numeric_limits<qint64>::min(), rec->endMs(),
                        [&](qint64, const PassCountChange&) { ++rows; });
        QCOMPARE(rows, 3); // start, +20 s, the new grid; not the unchanged +25 s
        FleetModel fleet;
        ReplayController c(rec.get(), &fleet);
        c.seek(rec->startMs());
        MainWindow window;
        populateReplayWindow(window, &c);
        auto* panel = qobject_cast<PassCountPanel*>(window.panelWidget(Panel::PassCounts));
        QVERIFY(panel);
        auto histogram = [&] {
            QTest::qWait(0);
            return summarize(*c.passCounts(), panel->target()).histogram;
        };
        auto check = [&](qint64 t, qint64 ones, qint64 twos, qint64 threes) {
            c.seek(t);
            QVERIFY(c.passCounts());
            const auto h = histogram();
            QCOMPARE(h.value(1), ones);
            QCOMPARE(h.value(2), twos);
            QCOMPARE(h.value(3), threes);
            // The panel shows the replayed layer's figures.
            QTRY_COMPARE(panel->summary().coveredCells, ones + twos + threes);
        };
        check(m_t0 + 10'000, 1, 0, 0);
        check(m_t0 + 30'000, 1, 5, 0);
        QCOMPARE(c.passCounts()->count(4, 7), 2);
        QCOMPARE(c.passCounts()->cellSize(), 1.0);
        check(m_t0 + 50'000, 0, 0, 16);
        QCOMPARE(c.passCounts()->cellSize(), 0.5);
        check(m_t0 + 10'000, 1, 0, 0); // backwards
        QCOMPARE(c.passCounts()->count(4, 7), 0);
        // Playing forward (no seek) reaches the same counts.
        for (qint64 t = m_t0 + 10'000; t <= m_t0 + 30'000; t += 500)
            c.moveTo(t);
        QCOMPARE(summarize(*c.passCounts(), panel->target()).histogram.value(2), qint64(5));
        QTRY_COMPARE(panel->summary().coveredCells, qint64(6));
    }

    void windowDrivesTheReplay() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        FleetModel fleet;
        ReplayController c(rec.get(), &fleet);
        c.seek(rec->startMs());
        MainWindow window;
        populateReplayWindow(window, &c);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        // Banner and disabled commands.
        auto* banner = window.findChild<QLabel*>(QStringLiteral("replayBannerLabel"));
        QVERIFY(banner && banner->isVisible());
        QVERIFY(banner->text().startsWith(QStringLiteral("REPLAY")));
        QVERIFY(!window.stopAllAction()->isEnabled());
        auto* log = qobject_cast<EventLogWidget*>(window.panelWidget(Panel::EventLog));
        QVERIFY(log && !log->ackAllButton()->isEnabled());
        // Every panel shows what the replay has for it or says why not; none stays on the window's
        // placeholder ("Starting…", the Dispatch panel did for the whole replay).
        auto labelOf = [&window](const QString& key) {
            QWidget* w = window.panelWidget(key);
            auto* l = qobject_cast<QLabel*>(w);
            return l ? l : (w ? w->findChild<QLabel*>() : nullptr);
        };
        for (const QString& p : window.panelKeys()) {
            const QLabel* l = labelOf(p);
            QVERIFY2(!l || l->text() != MainWindow::tr("Starting…"), qPrintable(p));
        }
        // The protocol modules' panels are there, as live, and say commands are off.
        for (const auto& m : makeProtocolModules())
            for (const PanelSpec& p : m->panels())
                QVERIFY2(labelOf(p.key) && labelOf(p.key)->text().startsWith(QStringLiteral("Replay:")),
                         qPrintable(p.key));

        auto* timeline = window.findChild<ReplayTimeline*>(QStringLiteral("replayTimeline"));
        QVERIFY(timeline);
        QCOMPARE(fleet.rowCount(), 2);

        // Markers: an alarm at +20 s and a command at +40 s; clicking one jumps there.
        TimelineMarkerStrip* strip = timeline->markerStrip();
        QCOMPARE(strip->markers().size(), 2);
        QTest::mouseClick(strip, Qt::LeftButton, {}, QPoint(strip->xOf(m_t0 + 40'000), strip->height() / 2));
        QCOMPARE(c.position(), m_t0 + 40'000);
        QCOMPARE(fleet.machine(QStringLiteral("jaus:100"))->e, 200.0);
        // The alarm of +20 s is in the event log now; going back before it removes it.
        QCOMPARE(c.alarms()->rowCount(), 1);

        // Exact time entry: seconds after the start, and a clock time.
        QLineEdit* time = timeline->timeEdit();
        time->setFocus();
        time->setText(QStringLiteral("12.5"));
        QTest::keyClick(time, Qt::Key_Return);
        QCOMPARE(c.position(), m_t0 + 12'500);
        QCOMPARE(c.alarms()->rowCount(), 0);
        log = qobject_cast<EventLogWidget*>(window.panelWidget(Panel::EventLog));
        QVERIFY(log && !log->ackAllButton()->isEnabled()); // the replaced log is read-only too
        time->setText(QStringLiteral("not a time"));
        QTest::keyClick(time, Qt::Key_Return);
        QCOMPARE(c.position(), m_t0 + 12'500);

        // The slider seeks.
        timeline->slider()->setValue(300); // 100 ms steps: +30 s
        QCOMPARE(c.position(), m_t0 + 30'000);
        QCOMPARE(timeline->position(), m_t0 + 30'000);

        // Keys on the window.
        window.activateWindow();
        window.setFocus();
        QTest::keyClick(&window, Qt::Key_Right);
        QCOMPARE(c.position(), m_t0 + 31'000);
        QTest::keyClick(&window, Qt::Key_Left);
        QTest::keyClick(&window, Qt::Key_Left);
        QCOMPARE(c.position(), m_t0 + 29'000);
        QTest::keyClick(&window, Qt::Key_Right, Qt::ShiftModifier);
        QCOMPARE(c.position(), m_t0 + 39'000);
        QTest::keyClick(&window, Qt::Key_Plus);
        QCOMPARE(c.speed(), 2.0);
        QCOMPARE(timeline->speedBox()->currentData().toDouble(), 2.0);
        QTest::keyClick(&window, Qt::Key_Minus);
        QTest::keyClick(&window, Qt::Key_Minus);
        QCOMPARE(c.speed(), 0.5);
        QTest::keyClick(&window, Qt::Key_Home);
        QCOMPARE(c.position(), rec->startMs());
        QTest::keyClick(&window, Qt::Key_End);
        QCOMPARE(c.position(), rec->endMs());
        QTest::keyClick(&window, Qt::Key_Home);
        QTest::keyClick(&window, Qt::Key_Space);
        QVERIFY(c.playing());
        QTRY_VERIFY(c.position() > rec->startMs());
        QTest::keyClick(&window, Qt::Key_Space);
        QVERIFY(!c.playing());

        // The timeline's buttons: step forward / back (1 s, pausing), the speed box from 0.1x to 16x, play
        // backwards, play / pause.
        c.seek(m_t0 + 30'000);
        QTest::mouseClick(timeline->stepForwardButton(), Qt::LeftButton);
        QCOMPARE(c.position(), m_t0 + 31'000);
        QCOMPARE(fleet.machine(QStringLiteral("jaus:100"))->e, 155.0);
        QTest::mouseClick(timeline->stepBackButton(), Qt::LeftButton);
        QTest::mouseClick(timeline->stepBackButton(), Qt::LeftButton);
        QCOMPARE(c.position(), m_t0 + 29'000);
        QCOMPARE(fleet.machine(QStringLiteral("jaus:100"))->e, 145.0);
        QComboBox* speed = timeline->speedBox();
        QCOMPARE(speed->count(), 8);
        QCOMPARE(speed->itemData(0).toDouble(), 0.1);
        QCOMPARE(speed->itemData(speed->count() - 1).toDouble(), 16.0);
        speed->activated(0);
        QCOMPARE(c.speed(), 0.1);
        speed->activated(speed->count() - 1);
        QCOMPARE(c.speed(), 16.0);
        QTest::mouseClick(timeline->reverseButton(), Qt::LeftButton);
        QVERIFY(c.reverse());
        QTest::mouseClick(timeline->playButton(), Qt::LeftButton);
        QVERIFY(c.playing());
        QTRY_VERIFY(c.position() < m_t0 + 29'000); // backwards, at 16x
        QTest::mouseClick(timeline->playButton(), Qt::LeftButton);
        QVERIFY(!c.playing());
        const qint64 back = c.position();
        QCOMPARE(timeline->position(), back);
        QTest::mouseClick(timeline->reverseButton(), Qt::LeftButton);
        QVERIFY(!c.reverse());
        QTest::mouseClick(timeline->playButton(), Qt::LeftButton);
        QTRY_VERIFY(c.position() > back); // forwards again
        QTest::mouseClick(timeline->playButton(), Qt::LeftButton);
        QVERIFY(!c.playing());
    }
};

QTEST_MAIN(TestReplayWindow)
#include "test_replay_window.moc"
