#pragma once
// Drives the console's models from a recording: the fleet model (machines, staleness by the
// replay clock), an alarm model (events and acknowledgements as they were at the replay time), the links and
// the site map. Play, pause, speed 0.1x-16x, reverse, step and seek; seeking anywhere rebuilds the picture
// from the newest keyframe before the target plus the records after it (Recording::statesAtIdx) and the alarm
// list from the rows alive at the target (AlarmHistory), and playing forward continues from the current
// picture and list without a new seek.
#include "models/FleetModel.h"
#include "models/ModelClock.h"
#include "models/recording/AlarmHistory.h"
#include "models/recording/Recording.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <limits>
#include <memory>

namespace ocu {

class AlarmModel;

namespace recording {

class ReplayController : public QObject {
    Q_OBJECT
public:
    // `fleet` is driven (its clock becomes the replay clock, its own refresh timer and expiry are turned
    // off). The replay clock is shared, so the fleet may outlive the controller.
    ReplayController(const Recording* recording, FleetModel* fleet, QObject* parent = nullptr);

    const Recording* recording() const { return m_rec; }
    FleetModel* fleet() const { return m_fleet; }
    // The alarm model of the current picture; replaced (alarmsReplaced) when seeking backwards.
    AlarmModel* alarms() const { return m_alarms; }
    // The alarm list's cap, the live console's (AlarmModel::kDefaultMaxEntries) unless set: the replayed list
    // drops the rows the live one dropped. 0 = none. Setting it rebuilds the list at the current position.
    void setMaxAlarmEntries(int n);
    int maxAlarmEntries() const { return m_alarmCap; }
    QHash<QString, MachineState> links() const;
    // The OSYRIS pass counts at the replay time (nullptr before the first recorded grid).
    const PassCountLayer* passCounts() const { return m_pass.layer(); }

    qint64 startMs() const { return m_rec->startMs(); }
    qint64 endMs() const { return m_rec->endMs(); }
    qint64 position() const { return m_t; }
    // The clock that reads the replay cursor, for any model that measures ages on replayed time.
    std::shared_ptr<const ModelClock> clock() const { return m_clock; }
    bool playing() const { return m_timer.isActive(); }
    double speed() const { return m_speed; }
    bool reverse() const { return m_reverse; }
    // How long the last seek took to rebuild the picture (ms, wall time).
    double lastSeekMs() const { return m_lastSeekMs; }

    static QVector<double> speeds(); // 0.1 0.25 0.5 1 2 4 8 16

public slots:
    // Rebuilds the picture at t (clamped to the recording).
    void seek(qint64 t);
    // Moves to t: forward by continuing (or seeking when far), backwards by seeking.
    void moveTo(qint64 t);
    void play();
    void pause();
    void togglePlay();
    void setSpeed(double speed); // clamped to 0.1..16
    void faster();
    void slower();
    void setReverse(bool reverse);
    // One step (default 1 s) forward (+1) or back (-1); pauses.
    void step(int direction);
    void setStepMs(qint64 ms) { m_stepMs = std::max<qint64>(1, ms); }
    // Wall-clock interval of the play timer (default 40 ms).
    void setTickIntervalMs(int ms) { m_timer.setInterval(std::max(1, ms)); }

signals:
    void positionChanged(qint64 t);
    void playingChanged(bool playing);
    void speedChanged(double speed);
    void reverseChanged(bool reverse);
    void alarmsReplaced(ocu::AlarmModel* alarms);
    void linkChanged(const ocu::recording::RecordedLink& link);
    void linksReset(const QVector<ocu::recording::RecordedLink>& links);
    void siteMapChanged(const ocu::SiteMapData& map);
    // The pass counts of the replay time changed (the layer is replaced when the recorded grid changed).
    void passCountsChanged(const ocu::PassCountLayer* layer);
    void finished(); // playing reached an end

private:
    void tick();
    void advanceTo(qint64 t);
    void applyAlarms(qint64 fromExclusive, qint64 toInclusive);
    void restoreAlarms(qint64 t, bool backwards);
    void updateSiteMap(qint64 t);
    void updatePassCounts(qint64 t);

    const Recording* m_rec;
    QPointer<FleetModel> m_fleet;
    AlarmModel* m_alarms = nullptr;
    int m_alarmCap;
    std::unique_ptr<AlarmHistory> m_history;
    Recording::StateMap m_states;
    qint64 m_t = 0;
    std::shared_ptr<ManualModelClock> m_clock; // follows m_t
    bool m_loaded = false;
    double m_speed = 1.0;
    bool m_reverse = false;
    qint64 m_stepMs = 1000;
    double m_lastSeekMs = 0;
    QString m_mapStamp;
    ReplayPassCounts m_pass;
    qint64 m_passT = std::numeric_limits<qint64>::min();
    QTimer m_timer;
    QElapsedTimer m_wall;
    double m_carryMs = 0;
};

} // namespace recording
} // namespace ocu
