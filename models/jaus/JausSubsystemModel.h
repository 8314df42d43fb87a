#pragma once
// One row per discovered JAUS subsystem, fed by the JAUS bridge's vehicle views (GUI thread).
#include "models/ModelClock.h"
#include "models/jaus/JausVehicleBridge.h"

#include <QAbstractTableModel>
#include <QElapsedTimer>

namespace ocu {

class JausSubsystemModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Vehicle, Link, Access, Controller, Management, Health, Actions, ColumnCount };
    enum Roles { SubsystemRole = Qt::UserRole + 1, AccessStateRole, RowColourRole };
    // Row colours (anchors-features.md §2.1, FKIE access-control panel).
    enum class RowColour { None, OursOk, OursWarning, Other };

    explicit JausSubsystemModel(JausVehicleBridge* bridge, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    std::uint16_t subsystemAt(int row) const;
    int rowOf(std::uint16_t subsystem) const;
    const JausVehicle* vehicleAt(int row) const;
    static QString accessText(JausAccess s);
    // The link state in the operator's language (JausVehicle::linkText keeps the stack's English word).
    static QString linkText(JausLink s);
    RowColour rowColour(const JausVehicle& s) const;
    // The clock data ages are measured on, the bridge's (null: the system clock).
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }

private:
    void onVehicle(const JausVehicle& s);
    JausVehicleBridge* m_bridge;
    JausAddress m_ownId; // this console's component: our own ID in a report is not another controller
    QVector<JausVehicle> m_rows;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
};

} // namespace ocu
