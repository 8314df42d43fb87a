#pragma once
// One status-bar indicator per protocol link: a coloured lamp, the state in words and the data age; its
// details (tooltip) add each link's rejected peer input by reason.
#include "models/FleetBridge.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QVector>
#include <QWidget>

class QLabel;

namespace ocu {

class LinkIndicator : public QWidget {
    Q_OBJECT
public:
    enum class State { NotConfigured, Up, Degraded, Down };
    Q_ENUM(State)

    explicit LinkIndicator(const QString& protocolName, QWidget* parent = nullptr);

    State state() const { return m_state; }
    QString text() const;
    // Data age is counted from the last call to dataReceived() (or given explicitly).
    void setState(State state, const QString& detail = {});
    void dataReceived();
    void setDataAgeMs(qint64 ageMs);
    qint64 dataAgeMs() const;
    // The reject counters per link, shown in the details; watchBridge() takes them from the bridge every
    // second (and at once).
    void setLinkCounters(const QVector<LinkCounters>& counters);
    void watchBridge(FleetBridge* bridge);
    // What the tooltip shows: the state, the link's detail and the reject counters.
    QString details() const { return toolTip(); }
    // A standing condition of the stack shown beside the lamp until cleared (FleetBridge::statusNote, e.g.
    // "JAUS: no group socket (3794 held by another process)"); empty hides it.
    void setNote(const QString& note);
    QString note() const { return m_noteText; }

private:
    void refresh();
    QString m_protocol;
    State m_state = State::NotConfigured;
    QString m_detail;
    QVector<LinkCounters> m_counters;
    QPointer<FleetBridge> m_bridge;
    QElapsedTimer m_sinceData;
    qint64 m_ageOffsetMs = -1;
    QString m_noteText;
    QLabel* m_lamp;
    QLabel* m_label;
    QLabel* m_note;
};

} // namespace ocu
