#pragma once
// Helpers of the bridges' thread tests: waiting while the GUI thread stays busy (no event processed), a
// receiver on a thread of its own, and a record of the thread each signal was emitted on.
#include "models/FleetBridge.h"

#include <QThread>

#include <atomic>
#include <chrono>
#include <functional>
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

} // namespace bridgetest
