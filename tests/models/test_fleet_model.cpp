// FleetModel, TelemetryCoalescer, FleetBridge, FleetFilterProxy and FleetSelection with a fake bridge.
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/TelemetryCoalescer.h"
#include "models/testing/FakeFleetBridge.h"

#include <QSignalSpy>
#include <QTest>
#include <atomic>
#include <thread>

using namespace ocu;

namespace {
MachineState machine(const QString& id, double e = 0, double n = 0) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = id.section(QLatin1Char(':'), 1);
    m.type = QStringLiteral("UGV");
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.n = n;
    m.stop = StopState::None;
    m.health = HealthLevel::Ok;
    m.mode = ModeCategory::Manual;
    return m;
}
} // namespace

class TestFleetModel : public QObject {
    Q_OBJECT
private slots:
    void coalescerDeliversLatestValuePerKeyInOneDrain() {
        QObject ctx;
        std::vector<std::pair<int, int>> got;
        int drains = 0;
        TelemetryCoalescer<int, int> c(&ctx, [&](auto&& batch) {
            ++drains;
            got.insert(got.end(), batch.begin(), batch.end());
        });
        // A worker thread pushes a burst of 10,000 values for 1,000 keys.
        std::thread worker([&] {
            for (int round = 0; round < 10; ++round)
                for (int k = 0; k < 1000; ++k)
                    c.push(k, round * 10000 + k);
        });
        worker.join();
        QCOMPARE(c.pending(), size_t(1000));
        QCoreApplication::processEvents();
        QCOMPARE(drains, 1);
        QCOMPARE(got.size(), size_t(1000));
        for (int k = 0; k < 1000; ++k) {
            QCOMPARE(got[size_t(k)].first, k);              // first-push order
            QCOMPARE(got[size_t(k)].second, 9 * 10000 + k); // latest value wins
        }
        const auto st = c.stats();
        QCOMPARE(st.pushed, quint64(10000));
        QCOMPARE(st.delivered, quint64(1000));
        // Nothing more is queued: another event loop pass delivers nothing.
        QCoreApplication::processEvents();
        QCOMPARE(drains, 1);
        // A later push schedules again.
        c.push(5, 42);
        QCoreApplication::processEvents();
        QCOMPARE(drains, 2);
        QCOMPARE(got.back().second, 42);
    }

    void coalescerOutlivedByQueuedDrainIsSafe() {
        QObject ctx;
        int calls = 0;
        {
            TelemetryCoalescer<int, int> c(&ctx, [&](auto&&) { ++calls; });
            c.push(1, 1);
        } // destroyed with a drain queued
        QCoreApplication::processEvents();
        QCOMPARE(calls, 0);
    }

    void bridgeBurstBecomesOneModelUpdatePerMachine() {
        FakeFleetBridge bridge(Protocol::Jaus);
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.addBridge(&bridge);
        QSignalSpy changed(&model, &FleetModel::machinesChanged);
        std::thread worker([&] {
            for (int round = 0; round < 10; ++round)
                for (int k = 0; k < 1000; ++k)
                    bridge.publishMachine(machine(QStringLiteral("jaus:%1").arg(k), round, k));
        });
        worker.join();
        QCoreApplication::processEvents();
        QCOMPARE(model.rowCount(), 1000);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.at(0).at(0).toStringList().size(), 1000);
        QCOMPARE(model.machine(QStringLiteral("jaus:7"))->e, 9.0);
    }

    void machineAppearsUpdatesGoesStaleAndDisappears() {
        auto clock = std::make_shared<ManualModelClock>(1'000'000);
        FakeFleetBridge bridge(Protocol::Iso23725);
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.setClock(clock);
        model.setStaleAfterMs(3000);
        model.setRemoveAfterMs(20000);
        model.addBridge(&bridge);
        QSignalSpy added(&model, &FleetModel::machineAdded);
        QSignalSpy removed(&model, &FleetModel::machineRemoved);
        QSignalSpy stale(&model, &FleetModel::machineStaleChanged);

        MachineState m = machine(QStringLiteral("iso23725:HT-01"), 10, 20);
        m.lastDataMs = clock->nowMs();
        bridge.publishMachine(m);
        QCoreApplication::processEvents();
        QCOMPARE(added.count(), 1);
        QCOMPARE(model.rowCount(), 1);
        const QModelIndex east = model.index(0, FleetModel::ColEast);
        QCOMPARE(east.data(FleetModel::RawRole).toDouble(), 10.0);
        QCOMPARE(east.data().toString(), QStringLiteral("10.0"));
        QCOMPARE(model.index(0, FleetModel::ColProtocol).data().toString(), QStringLiteral("ISO 23725"));

        // Update
        clock->advance(1000);
        m.e = 15;
        m.lastDataMs = clock->nowMs();
        bridge.publishMachine(m);
        QCoreApplication::processEvents();
        QCOMPARE(model.rowCount(), 1);
        QCOMPARE(model.machine(m.id)->e, 15.0);
        QCOMPARE(model.data(model.index(0, 0), FleetModel::StatusRole).toInt(), int(StatusCategory::Ok));

        // Goes stale after 3 s without data
        clock->advance(2500);
        model.refresh();
        QVERIFY(!model.isStale(m.id));
        clock->advance(1000);
        model.refresh();
        QVERIFY(model.isStale(m.id));
        QCOMPARE(stale.count(), 1);
        QCOMPARE(model.data(model.index(0, 0), FleetModel::StatusRole).toInt(), int(StatusCategory::Stale));
        QCOMPARE(model.data(model.index(0, 0), FleetModel::AgeMsRole).toLongLong(), qint64(3500));

        // Fresh data un-stales it
        m.lastDataMs = clock->nowMs();
        bridge.publishMachine(m);
        QCoreApplication::processEvents();
        QVERIFY(!model.isStale(m.id));
        QCOMPARE(stale.count(), 2);

        // Disappears after the configured time without data
        clock->advance(19000);
        model.refresh();
        QCOMPARE(model.rowCount(), 1);
        clock->advance(2000);
        model.refresh();
        QCOMPARE(model.rowCount(), 0);
        QCOMPARE(removed.count(), 1);
        QCOMPARE(model.rowOf(m.id), -1);
    }

    void staleThresholdPerProtocol() {
        auto clock = std::make_shared<ManualModelClock>(2'000'000);
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.setClock(clock);
        model.setStaleAfterMs(5000);
        model.setStaleAfterMs(Protocol::Osyris, 1000);
        MachineState a = machine(QStringLiteral("jaus:1"));
        MachineState b = machine(QStringLiteral("osyris:1"));
        a.lastDataMs = b.lastDataMs = clock->nowMs();
        model.upsert({a, b});
        clock->advance(2000);
        model.refresh();
        QVERIFY(!model.isStale(a.id));
        QVERIFY(model.isStale(b.id));
        model.setStaleAfterMs(Protocol::Osyris, -1); // back to the default
        model.refresh();
        QVERIFY(!model.isStale(b.id));
    }

    void explicitRemovalThroughTheBridge() {
        FakeFleetBridge bridge(Protocol::Osyris);
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.addBridge(&bridge);
        bridge.setMachine(machine(QStringLiteral("osyris:1")));
        bridge.setMachine(machine(QStringLiteral("osyris:2")));
        QCoreApplication::processEvents();
        QCOMPARE(model.rowCount(), 2);
        bridge.removeMachine(QStringLiteral("osyris:1"));
        QCoreApplication::processEvents();
        QCOMPARE(model.rowCount(), 1);
        QCOMPARE(model.machineAt(0).id, QStringLiteral("osyris:2"));
        QCOMPARE(model.rowOf(QStringLiteral("osyris:2")), 0);
    }

    void statusColoursFollowTheConvention() {
        MachineState m = machine(QStringLiteral("jaus:1"));
        QCOMPARE(statusOf(m, false), StatusCategory::Ok);
        m.mode = ModeCategory::Autonomous;
        QCOMPARE(statusOf(m, false), StatusCategory::Autonomous);
        m.health = HealthLevel::Warning;
        QCOMPARE(statusOf(m, false), StatusCategory::Warning);
        m.stop = StopState::Stopped;
        QCOMPARE(statusOf(m, false), StatusCategory::FaultOrStopped);
        QCOMPARE(statusOf(m, true), StatusCategory::Stale);
        m.link = LinkState::Down;
        QCOMPARE(statusOf(m, false), StatusCategory::Stale);
    }

    void proxyFiltersAndSortsByRawValue() {
        FleetModel model;
        model.setRefreshIntervalMs(0);
        MachineState a = machine(QStringLiteral("jaus:1"), 100);
        MachineState b = machine(QStringLiteral("iso23725:T2"), 9);
        MachineState c = machine(QStringLiteral("osyris:3"), 20);
        c.stop = StopState::Stopped;
        model.upsert({a, b, c});
        FleetFilterProxy proxy;
        proxy.setSourceModel(&model);
        proxy.sort(FleetModel::ColEast, Qt::AscendingOrder);
        QCOMPARE(proxy.rowCount(), 3);
        // Numeric sort: 9 < 20 < 100 (a text sort would give 100 < 20 < 9)
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), b.id);
        QCOMPARE(proxy.index(2, 0).data(FleetModel::IdRole).toString(), a.id);
        proxy.setProtocols({Protocol::Jaus, Protocol::Osyris});
        QCOMPARE(proxy.rowCount(), 2);
        proxy.setStatuses({StatusCategory::FaultOrStopped});
        QCOMPARE(proxy.rowCount(), 1);
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), c.id);
        proxy.setProtocols({});
        proxy.setStatuses({});
        proxy.setText(QStringLiteral("t2"));
        QCOMPARE(proxy.rowCount(), 1);
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), b.id);
    }

    // With a change interval, bursts of source changes reach the sort and the view as one merged
    // dataChanged; the order follows the data once the merged change is handed over; rows pass at once.
    void proxyThrottlesDataChangesIntoOneMergedBatch() {
        FleetModel model;
        model.setRefreshIntervalMs(0);
        QVector<MachineState> ms;
        for (int i = 0; i < 50; ++i)
            ms.push_back(machine(QStringLiteral("iso23725:T%1").arg(i), i));
        model.upsert(ms);
        FleetFilterProxy proxy;
        proxy.setChangeIntervalMs(3600 * 1000); // never by the timer in this test: flushChanges() hands over
        proxy.setSourceModel(&model);
        proxy.sort(FleetModel::ColEast, Qt::DescendingOrder);
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), QStringLiteral("iso23725:T49"));
        QSignalSpy changed(&proxy, &QAbstractItemModel::dataChanged);
        QSignalSpy layout(&proxy, &QAbstractItemModel::layoutChanged);
        // 20 bursts of position updates: nothing reaches the view yet.
        for (int round = 1; round <= 20; ++round) {
            for (int i = 0; i < ms.size(); ++i)
                ms[i].e = i + round * (i == 3 ? 100 : 1); // T3 overtakes everyone
            model.upsert(ms);
        }
        QCOMPARE(changed.count(), 0);
        QCOMPARE(layout.count(), 0);
        QCOMPARE(proxy.changeBatches(), 0);
        // A new machine is a row: it passes at once (and the pending rows are kept).
        model.upsert({machine(QStringLiteral("jaus:7"), -5)});
        QCOMPARE(proxy.rowCount(), 51);
        proxy.flushChanges();
        QCOMPARE(proxy.changeBatches(), 1);
        QVERIFY(changed.count() + layout.count() >= 1);
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), QStringLiteral("iso23725:T3"));
        QCOMPARE(proxy.index(0, FleetModel::ColEast).data(FleetModel::RawRole).toDouble(), 2003.0);
        // Filtering on a state that changed while throttled sees the current data.
        ms[10].stop = StopState::Stopped;
        model.upsert({ms[10]});
        proxy.flushChanges();
        proxy.setStatuses({StatusCategory::FaultOrStopped});
        QCOMPARE(proxy.rowCount(), 1);
        // Without an interval every change passes at once again.
        proxy.setStatuses({});
        proxy.setChangeIntervalMs(0);
        const int before = changed.count() + layout.count();
        ms[0].e = 5000;
        model.upsert({ms[0]});
        QVERIFY(changed.count() + layout.count() > before);
        QCOMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), QStringLiteral("iso23725:T0"));
        // And the timer hands over by itself (no flushChanges call).
        proxy.setChangeIntervalMs(20);
        proxy.setSourceModel(&model);
        proxy.sort(FleetModel::ColEast, Qt::DescendingOrder);
        ms[1].e = 9000;
        model.upsert({ms[1]});
        QTRY_COMPARE(proxy.index(0, 0).data(FleetModel::IdRole).toString(), QStringLiteral("iso23725:T1"));
    }

    void selectionIsSharedAndKeyedById() {
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.upsert({machine(QStringLiteral("jaus:1")), machine(QStringLiteral("jaus:2")),
                      machine(QStringLiteral("jaus:3"))});
        FleetSelection sel(&model);
        QSignalSpy current(&sel, &FleetSelection::currentMachineChanged);
        QSignalSpy changed(&sel, &FleetSelection::selectionChanged);
        sel.setCurrent(QStringLiteral("jaus:2"));
        QCOMPARE(sel.currentId(), QStringLiteral("jaus:2"));
        QCOMPARE(sel.selectedIds(), QStringList{QStringLiteral("jaus:2")});
        QCOMPARE(current.count(), 1);
        QCOMPARE(changed.count(), 1);
        sel.toggle(QStringLiteral("jaus:3"));
        QCOMPARE(sel.selectedIds().size(), 2);
        QVERIFY(sel.isSelected(QStringLiteral("jaus:3")));
        QCOMPARE(sel.currentId(), QStringLiteral("jaus:3"));
        // Removing a row keeps the selection of the others (by id)
        model.remove({QStringLiteral("jaus:1")});
        QVERIFY(sel.isSelected(QStringLiteral("jaus:2")));
        QVERIFY(sel.isSelected(QStringLiteral("jaus:3")));
        model.remove({QStringLiteral("jaus:3")});
        QCOMPARE(sel.currentId(), QString());
        QCOMPARE(sel.selectedIds(), QStringList{QStringLiteral("jaus:2")});
        sel.clear();
        QVERIFY(sel.selectedIds().isEmpty());

        // Mapping through a proxy chain.
        model.upsert({machine(QStringLiteral("jaus:7"), 5), machine(QStringLiteral("jaus:8"), 1)});
        FleetFilterProxy proxy;
        proxy.setSourceModel(&model);
        proxy.sort(FleetModel::ColEast);
        FleetFilterProxy outer;
        outer.setSourceModel(&proxy);
        const QModelIndex p = sel.indexFor(QStringLiteral("jaus:8"), &proxy);
        QCOMPARE(p.model(), &proxy);
        QCOMPARE(FleetSelection::idAt(p), QStringLiteral("jaus:8"));
        QCOMPARE(FleetSelection::idAt(sel.indexFor(QStringLiteral("jaus:7"), &outer)),
                 QStringLiteral("jaus:7"));
        QVERIFY(!sel.indexFor(QStringLiteral("nope"), &proxy).isValid());
    }
};

QTEST_GUILESS_MAIN(TestFleetModel)
#include "test_fleet_model.moc"
