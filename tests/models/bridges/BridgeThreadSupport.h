#pragma once
// Helpers of the bridges' thread tests: waiting while the GUI thread stays busy (no event processed), a
// receiver on a thread of its own, and a record of the thread each signal was emitted on.
#include "models/AlarmModel.h"
#include "models/FleetBridge.h"

#include <QThread>
#include <QtTest>

#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

namespace bridgetest {

// Polls `pred` without processing any event: the GUI thread is "busy" meanwhile, so the bridge's queued
// deliveries pile up. Returns false after `seconds` (generous: the machine may be loaded).
inline bool waitBusy(const std::function<bool()>& pred, double seconds = 30) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (pred())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return pred();
}

// A receiver living on its own thread: the bridge's machinesUpdated reaches it queued, on that thread.
class ThreadProbe : public QObject {
    Q_OBJECT
public:
    std::atomic<QThread*> ranOn{nullptr};
    std::atomic<int> calls{0};
public slots:
    void onMachines(const QVector<ocu::MachineState>& machines) {
        if (!machines.isEmpty()) {
            ranOn = QThread::currentThread();
            ++calls;
        }
    }
};

class ProbeThread {
public:
    explicit ProbeThread(ocu::FleetBridge* bridge) {
        m_probe.moveToThread(&m_thread);
        QObject::connect(bridge, &ocu::FleetBridge::machinesUpdated, &m_probe, &ThreadProbe::onMachines);
        m_thread.start();
    }
    ~ProbeThread() {
        m_thread.quit();
        m_thread.wait();
    }
    QThread* thread() { return &m_thread; }
    ThreadProbe& probe() { return m_probe; }

private:
    QThread m_thread;
    ThreadProbe m_probe;
};

// Every machinesUpdated batch, recorded with the thread it was emitted on (direct connection).
struct Deliveries {
    explicit Deliveries(ocu::FleetBridge* bridge) {
        QObject::connect(
            bridge, &ocu::FleetBridge::machinesUpdated, bridge,
            [this](const QVector<ocu::MachineState>& batch) {
                std::lock_guard lock(mutex);
                batches.push_back(batch);
                threads.push_back(QThread::currentThread());
            },
            Qt::DirectConnection);
    }
    int count() {
        std::lock_guard lock(mutex);
        return int(batches.size());
    }
    // The latest delivered state of one machine.
    std::optional<ocu::MachineState> latest(const QString& id) {
        std::lock_guard lock(mutex);
        for (auto b = batches.rbegin(); b != batches.rend(); ++b)
            for (const auto& m : *b)
                if (m.id == id)
                    return m;
        return std::nullopt;
    }
    bool allOn(QThread* t) {
        std::lock_guard lock(mutex);
        return std::all_of(threads.begin(), threads.end(), [t](QThread* x) { return x == t; });
    }
    void clear() {
        std::lock_guard lock(mutex);
        batches.clear();
        threads.clear();
    }
    std::mutex mutex;
    QVector<QVector<ocu::MachineState>> batches;
    QVector<QThread*> threads;
};

// Blocks the bridge's io thread on purpose (a handler waiting on a latch, `post` runs it there)
// and expects the watchdog's alarm and `link` shown degraded, then, with the latch released, the thread
// turning again: an info event and the link as the stack reports it (`upAgain`). The handler gives up by
// itself after 120 s so a failing test still ends.
inline void expectWatchdog(ocu::FleetBridge& bridge, const QString& link,
                           const std::function<void(std::function<void()>)>& post) {
    using namespace ocu;
    AlarmModel alarms;
    alarms.addBridge(&bridge);
    QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(link) && bridge.linkStatus(link)->state == LinkState::Up,
                             20000);
    QVERIFY(!bridge.ioStalled());
    auto latch = std::make_shared<std::promise<void>>();
    std::shared_future<void> released = latch->get_future().share();
    auto entered = std::make_shared<std::atomic<bool>>(false);
    post([released, entered] {
        *entered = true;
        released.wait_for(std::chrono::seconds(120));
    });
    QTRY_VERIFY_WITH_TIMEOUT(entered->load(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(bridge.ioStalled(), 20000);
    QVERIFY(bridge.ioStalledFor() > std::chrono::milliseconds(1000));
    // The link as shown (indicators, headless link lines) is degraded and says why.
    const auto shown = bridge.linkStatus(link);
    QVERIFY(shown);
    QCOMPARE(shown->state, LinkState::Degraded);
    QVERIFY2(shown->detail.contains(QStringLiteral("io thread not turning")), qPrintable(shown->detail));
    // One unacknowledged alarm in the alarm model.
    auto alarmRows = [&] {
        int n = 0;
        for (int r = 0; r < alarms.rowCount(); ++r)
            if (alarms.eventAt(r).severity == EventSeverity::Alarm &&
                alarms.eventAt(r).text.contains(QStringLiteral("watchdog")))
                ++n;
        return n;
    };
    QTRY_COMPARE_WITH_TIMEOUT(alarmRows(), 1, 10000);
    QVERIFY(alarms.unacknowledgedCount() >= 1);

    latch->set_value();
    QTRY_VERIFY_WITH_TIMEOUT(!bridge.ioStalled(), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(link) && bridge.linkStatus(link)->state == LinkState::Up,
                             20000);
    QVERIFY(!bridge.linkStatus(link)->detail.contains(QStringLiteral("io thread not turning")));
    auto cleared = [&] {
        for (int r = 0; r < alarms.rowCount(); ++r)
            if (alarms.eventAt(r).severity == EventSeverity::Info &&
                alarms.eventAt(r).text.contains(QStringLiteral("turns again")))
                return true;
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(cleared(), 10000);
    QCOMPARE(alarmRows(), 1); // raised once for the whole stall
}

} // namespace bridgetest
