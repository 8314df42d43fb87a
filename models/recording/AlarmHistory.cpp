#include "models/recording/AlarmHistory.h"

#include <QHash>

#include <algorithm>
#include <set>

namespace ocu::recording {

AlarmHistory::AlarmHistory(const Recording* recording, int maxEntries)
    : m_rec(recording), m_maxEntries(std::max(0, maxEntries)) {
    const qint64 all = std::numeric_limits<qint64>::min(), end = std::numeric_limits<qint64>::max();
    const QVector<RecordedEvent> events = m_rec->events(all, end);
    const QVector<RecordedAck> acks = m_rec->acks(all, end);
    // What AlarmModel::add, acknowledgeKey and trim do, on row numbers instead of rows.
    QHash<QString, qsizetype> active; // key -> the row of its unacknowledged alarm
    std::set<qsizetype> acked;        // acknowledged rows still in the list, oldest first (what trim drops)
    qsizetype present = 0;
    auto onEvent = [&](const RecordedEvent& e) {
        const QString key = alarmKey(e.event);
        if (e.event.requiresAck) {
            if (const auto it = active.constFind(key); it != active.constEnd()) {
                m_rows[size_t(it.value())].repeats.push_back({e.t, e.id, std::uint8_t(e.event.severity)});
                return;
            }
        }
        const auto row = qsizetype(m_rows.size());
        Row r;
        r.firstId = e.id;
        r.createdT = e.t;
        r.firstMs = e.event.timeMs;
        r.requiresAck = e.event.requiresAck;
        m_rows.push_back(std::move(r));
        ++present;
        if (e.event.requiresAck)
            active.insert(key, row);
        else
            acked.insert(row); // an entry that needs no acknowledgement counts as acknowledged
        if (m_maxEntries > 0) {
            while (present > m_maxEntries && !acked.empty()) {
                m_rows[size_t(*acked.begin())].droppedT = e.t;
                acked.erase(acked.begin());
                --present;
            }
        }
    };
    auto onAck = [&](const RecordedAck& a) {
        const auto it = active.find(a.key);
        if (it == active.end())
            return;
        const qsizetype row = it.value();
        Row& r = m_rows[size_t(row)];
        if (r.firstMs > a.t + AlarmModel::kAckSkewMs)
            return; // raised after the acknowledgement: not what the operator saw
        r.ackT = a.t;
        r.ackedBy = a.by;
        active.erase(it);
        acked.insert(row);
    };
    forEachInOrder(events, acks, onEvent, onAck);
}

QVector<AlarmModel::RestoredRow> AlarmHistory::rowsAt(qint64 t) const {
    // The rows alive at t and, for each, how many of its repeats had come (the latest one gives the row's
    // time and text).
    struct Alive {
        const Row* row;
        size_t repeats;
    };
    std::vector<Alive> alive;
    QVector<qint64> ids;
    const auto last = std::upper_bound(m_rows.begin(), m_rows.end(), t,
                                       [](qint64 v, const Row& r) { return v < r.createdT; });
    for (auto it = m_rows.begin(); it != last; ++it) {
        if (it->droppedT <= t)
            continue;
        const auto n = size_t(std::upper_bound(it->repeats.begin(), it->repeats.end(), t,
                                               [](qint64 v, const Repeat& r) { return v < r.t; }) -
                              it->repeats.begin());
        alive.push_back({&*it, n});
        ids.push_back(it->firstId);
        if (n > 0)
            ids.push_back(it->repeats[n - 1].id);
    }
    const QVector<RecordedEvent> read = m_rec->eventsById(ids);
    QVector<AlarmModel::RestoredRow> out;
    out.reserve(qsizetype(alive.size()));
    qsizetype k = 0;
    for (const Alive& a : alive) {
        AlarmModel::RestoredRow r;
        r.event = read[k++].event;
        r.firstMs = r.event.timeMs;
        r.occurrences = int(1 + a.repeats);
        if (a.repeats > 0) {
            // A repeat of an active alarm updates its row as AlarmModel::add does.
            const FleetEvent& latest = read[k++].event;
            r.event.timeMs = latest.timeMs;
            r.event.text = latest.text;
            r.event.details = latest.details;
            r.event.itemCount = latest.itemCount;
            for (size_t i = 0; i < a.repeats; ++i)
                r.event.severity = std::max(r.event.severity, EventSeverity(a.row->repeats[i].severity));
        }
        if (!a.row->requiresAck) {
            r.acked = true;
        } else if (a.row->ackT <= t) {
            r.acked = true;
            r.ackedMs = a.row->ackT;
            r.ackedBy = a.row->ackedBy;
        }
        out.push_back(std::move(r));
    }
    return out;
}

} // namespace ocu::recording
