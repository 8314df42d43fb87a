#pragma once
// The UGVs of a replay as the mission panel and its map layer see them: each mission rebuilt from the flight
// recorder's records (MissionJson, kind missionRecordKind()) as it was at the replay time, with its states
// and the path the vehicle drove; the call sign, link and position from the replayed fleet. Every command is
// refused: a replay acts on nothing.
#include "models/jaus/JausVehicleBridge.h"

#include <QHash>
#include <QPointer>
#include <QVector>

#include <limits>

namespace ocu {

class FleetModel;

class MissionReplayBridge final : public JausVehicleBridge {
    Q_OBJECT
public:
    struct Record {
        qint64 t = 0;
        QString machine; // "jaus:<subsystem>"
        QByteArray data;
    };
    // `records` in time order (Recording::details); `fleet` is the replayed fleet (may be null).
    MissionReplayBridge(QVector<Record> records, const FleetModel* fleet, QObject* parent = nullptr);

    // The missions after every record <= t (forwards from the last time without starting over); emits
    // subsystemUpdated for each vehicle whose mission changed, and forwards also for each change of state
    // on the way (not only the last).
    void setTime(qint64 t);
    qint64 time() const { return m_t; }
    // Records that did not decode (skipped).
    int malformed() const { return m_malformed; }

    JausConsoleIdentity identity() const override;
    QList<quint16> subsystems() const override;
    std::optional<JausVehicle> subsystem(quint16 id) const override;
    CommandResult drive(quint16 subsystem, const JausDrive& command) override;
    CommandResult stopDriving(quint16 subsystem) override;
    void stopAll(OutcomeCallback done) override;
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;

private:
    QVector<Record> m_records;
    QPointer<const FleetModel> m_fleet;
    QHash<quint16, JausMission> m_missions;
    qsizetype m_next = 0; // the first record after m_t
    qint64 m_t = std::numeric_limits<qint64>::min();
    int m_malformed = 0;
};

} // namespace ocu
