#pragma once
// One row per discovered JAUS subsystem, fed by the JausBridge (GUI thread).
#include "models/bridges/JausBridge.h"

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

    explicit JausSubsystemModel(JausBridge* bridge, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    std::uint16_t subsystemAt(int row) const;
    int rowOf(std::uint16_t subsystem) const;
    const jaus::SubsystemSnapshot* snapshotAt(int row) const;
    static QString accessText(jaus::AccessState s);
    RowColour rowColour(const jaus::SubsystemSnapshot& s) const;

private:
    void onSnapshot(const jaus::SubsystemSnapshot& s);
    JausBridge* m_bridge;
    QVector<jaus::SubsystemSnapshot> m_rows;
};

} // namespace ocu
