#pragma once
// The mission panel's table of waypoints over a MissionPlan: number, latitude, longitude, speed, tolerance,
// the last four editable (each edit one undo step of the plan).
#include "models/jaus/MissionPlan.h"

#include <QAbstractTableModel>
#include <QPointer>

namespace ocu {

class MissionPlan;

class MissionPlanTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, Latitude, Longitude, Speed, Tolerance, ColumnCount };
    explicit MissionPlanTableModel(QObject* parent = nullptr);

    void setPlan(MissionPlan* plan); // not owned; nullptr: empty
    MissionPlan* plan() const { return m_plan; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    void planChanged(int index);
    QPointer<MissionPlan> m_plan;
    QMetaObject::Connection m_connection;
};

} // namespace ocu
