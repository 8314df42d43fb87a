#pragma once
// The replay's alarm list at any time of a recording without adding every event since its start: one walk
// over the recorded events and acknowledgements, taken as the live console's AlarmModel took them (repeats of
// an active alarm grouped into its row, acknowledgements by key, the oldest acknowledged rows dropped beyond
// the list's cap), keeps for every row when it appeared, when it was acknowledged, when the cap dropped it
// and its repeats. The list at T is then the rows alive at T, read back from the file by row id: its cost
// follows the length of the list (bounded by the cap), not the length of the recording.
#include "models/AlarmModel.h"
#include "models/recording/Recording.h"

#include <QString>
#include <QVector>

#include <cstdint>
#include <limits>
#include <vector>

namespace ocu::recording {

// Events and acknowledgements in the order the console took them: by time, the events of one millisecond
// before its acknowledgements (the file keeps no order across the two tables; an operator's acknowledgement
// in the same millisecond as a new event is taken after it). Both the replay's forward play and its seek use
// this order, so both give the same list.
template <typename OnEvent, typename OnAck>
void forEachInOrder(const QVector<RecordedEvent>& events, const QVector<RecordedAck>& acks, OnEvent onEvent,
                    OnAck onAck) {
    qsizetype i = 0, j = 0;
    while (i < events.size() || j < acks.size()) {
        if (j >= acks.size() || (i < events.size() && events[i].t <= acks[j].t))
            onEvent(events[i++]);
        else
            onAck(acks[j++]);
    }
}

class AlarmHistory {
public:
    // Walks the whole recording once. maxEntries: the list's cap (AlarmModel::setMaxEntries; 0 = none).
    AlarmHistory(const Recording* recording, int maxEntries);

    int maxEntries() const { return m_maxEntries; }
    // The rows of the list after every event and acknowledgement recorded at or before t.
    QVector<AlarmModel::RestoredRow> rowsAt(qint64 t) const;

private:
    static constexpr qint64 kNever = std::numeric_limits<qint64>::max();
    struct Repeat {
        qint64 t = 0;
        qint64 id = 0;
        std::uint8_t severity = 0;
    };
    struct Row {
        qint64 firstId = 0;
        qint64 createdT = 0;
        qint64 firstMs = 0;       // its first event's own time (what acknowledgeKey compares)
        qint64 droppedT = kNever; // dropped by the cap when an event at this time was added
        qint64 ackT = kNever;     // acknowledged (recorded time); events without acknowledgement: never
        QString ackedBy;
        bool requiresAck = false;
        std::vector<Repeat> repeats; // in time order
    };
    const Recording* m_rec;
    int m_maxEntries;
    std::vector<Row> m_rows; // in the order they appeared
};

} // namespace ocu::recording
