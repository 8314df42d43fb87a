#pragma once
// Latest-value-per-key buffer between a protocol io thread and the GUI thread.
// push() is thread-safe and cheap; the first push after a drain posts exactly one queued invocation
// to the context object's thread, which hands everything pending (latest value per key, in first-push
// order) to the sink. A burst of 10,000 positions for 1,000 machines is therefore one sink call with
// 1,000 entries, and the GUI event queue never holds more than one drain per coalescer.
#include <QHash>
#include <QMetaObject>
#include <QObject>
#include <QPointer>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace ocu {

template <class Key, class Value> class TelemetryCoalescer {
public:
    using Batch = std::vector<std::pair<Key, Value>>;
    using Sink = std::function<void(Batch&&)>;

    struct Stats {
        quint64 pushed = 0;    // values accepted
        quint64 delivered = 0; // values handed to the sink (pushed - delivered - pending = overwritten)
        quint64 drains = 0;    // sink calls
        quint64 handovers = 0; // producer calls (push or a batch push), one lock each
    };

    // `context` decides the draining thread (its thread affinity); the sink runs there.
    TelemetryCoalescer(QObject* context, Sink sink) : m_state(std::make_shared<State>()) {
        m_state->context = context;
        m_state->sink = std::move(sink);
    }
    ~TelemetryCoalescer() {
        // A drain may still be queued; it holds a weak reference and becomes a no-op.
        std::lock_guard lock(m_state->mutex);
        m_state->sink = nullptr;
    }
    TelemetryCoalescer(const TelemetryCoalescer&) = delete;
    TelemetryCoalescer& operator=(const TelemetryCoalescer&) = delete;

    // Any thread.
    void push(const Key& key, Value value) {
        bool schedule = false;
        {
            std::lock_guard lock(m_state->mutex);
            put(key, std::move(value));
            ++m_state->stats.handovers;
            schedule = markScheduled();
        }
        if (schedule)
            scheduleDrain(m_state);
    }
    // Any thread: many values in one hand-over (one lock), in order; the latest value per key still wins.
    void push(Batch&& values) {
        if (values.empty())
            return;
        bool schedule = false;
        {
            std::lock_guard lock(m_state->mutex);
            for (auto& [key, value] : values)
                put(key, std::move(value));
            ++m_state->stats.handovers;
            schedule = markScheduled();
        }
        if (schedule)
            scheduleDrain(m_state);
    }

    // Context thread: deliver now (e.g. before a screenshot, in tests).
    void drainNow() { drain(m_state); }

    size_t pending() const {
        std::lock_guard lock(m_state->mutex);
        return m_state->pending.size();
    }
    Stats stats() const {
        std::lock_guard lock(m_state->mutex);
        return m_state->stats;
    }

private:
    struct State {
        mutable std::mutex mutex;
        QPointer<QObject> context;
        Sink sink;
        Batch pending;
        QHash<Key, int> index;
        bool scheduled = false;
        Stats stats;
    };

    // With the lock held.
    void put(const Key& key, Value&& value) {
        auto it = m_state->index.find(key);
        if (it != m_state->index.end()) {
            m_state->pending[size_t(*it)].second = std::move(value);
        } else {
            m_state->index.insert(key, int(m_state->pending.size()));
            m_state->pending.emplace_back(key, std::move(value));
        }
        ++m_state->stats.pushed;
    }
    bool markScheduled() {
        if (m_state->scheduled)
            return false;
        m_state->scheduled = true;
        return true;
    }

    static void scheduleDrain(const std::shared_ptr<State>& state) {
        QObject* ctx = state->context.data();
        if (!ctx)
            return;
        std::weak_ptr<State> weak = state;
        QMetaObject::invokeMethod(
            ctx,
            [weak] {
                if (auto s = weak.lock())
                    drain(s);
            },
            Qt::QueuedConnection);
    }

    static void drain(const std::shared_ptr<State>& state) {
        Batch batch;
        Sink sink;
        {
            std::lock_guard lock(state->mutex);
            state->scheduled = false;
            batch.swap(state->pending);
            state->index.clear();
            if (batch.empty() || !state->sink)
                return;
            state->stats.delivered += batch.size();
            ++state->stats.drains;
            sink = state->sink; // call outside the lock: the sink may push again
        }
        sink(std::move(batch));
    }

    std::shared_ptr<State> m_state;
};

} // namespace ocu
