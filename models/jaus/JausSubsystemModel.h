#pragma once
// One row per discovered JAUS subsystem, fed by the JAUS bridge's vehicle views (GUI thread).
#include "models/ModelClock.h"
#include "models/jaus/JausVehicleBridge.h"

#include <QAbstractTableModel>
#include <QElapsedTimer>
#include <QPointer>

namespace ocu {

class ControlRoomModel;

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
    // Who is where across the control room: a controller that is another console of the room is named by its
    // operator and console instead of its JAUS ID (the tooltip keeps the ID). nullptr: IDs only.
    void setControlRoom(ControlRoomModel* room);
    // "jaus:3.1.1": a controller's address as consoles publish it in the room (models/ControlRoomModel.h).
    static QString roomAddress(const JausAddress& a);
    // The clock data ages are measured on, the bridge's (null: the system clock).
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }

private:
    void onVehicle(const JausVehicle& s);
    JausVehicleBridge* m_bridge;
    QString controllerText(const JausVehicle& s, bool tooltip) const;
    JausAddress m_ownId; // this console's component: our own ID in a report is not another controller
    QVector<JausVehicle> m_rows;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    QPointer<ControlRoomModel> m_room;
};

} // namespace ocu
