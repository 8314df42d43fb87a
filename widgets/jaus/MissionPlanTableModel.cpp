#include "widgets/jaus/MissionPlanTableModel.h"

#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionPlan.h"

#include <cmath>

namespace ocu {

MissionPlanTableModel::MissionPlanTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void MissionPlanTableModel::setPlan(MissionPlan* plan) {
    beginResetModel();
    disconnect(m_connection);
    m_plan = plan;
    if (plan)
        m_connection = connect(plan, &MissionPlan::changed, this, &MissionPlanTableModel::planChanged);
    endResetModel();
}

void MissionPlanTableModel::planChanged(int index) {
    if (index >= 0 && index < rowCount()) {
        emit dataChanged(this->index(index, 0), this->index(index, ColumnCount - 1));
        return;
    }
    beginResetModel(); // rows added or removed
    endResetModel();
}

int MissionPlanTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !m_plan ? 0 : m_plan->size();
}

int MissionPlanTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MissionPlanTableModel::data(const QModelIndex& index, int role) const {
    if (!m_plan || !index.isValid() || index.row() >= m_plan->size())
        return {};
    const MissionWaypoint& w = m_plan->at(index.row());
    if (role == Qt::TextAlignmentRole)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::EditRole)
        return {};
    const bool edit = role == Qt::EditRole;
    switch (index.column()) {
    case Number:
        return index.row() + 1;
    case Latitude: // 7 decimals: 1 cm
        return edit ? QVariant(w.lat) : QVariant(QString::number(w.lat, 'f', 7));
    case Longitude:
        return edit ? QVariant(w.lon) : QVariant(QString::number(w.lon, 'f', 7));
    case Speed:
        return edit ? QVariant(w.speed)
                    : QVariant(w.speed > 0 ? QString::number(w.speed, 'f', 2) : tr("vehicle"));
    case Tolerance:
        return edit ? QVariant(w.tolerance)
                    : QVariant(w.tolerance > 0 ? QString::number(w.tolerance, 'f', 2) : tr("vehicle"));
    default:
        return {};
    }
}

bool MissionPlanTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!m_plan || role != Qt::EditRole || !index.isValid() || index.row() >= m_plan->size())
        return false;
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return false;
    const int row = index.row();
    const MissionWaypoint& w = m_plan->at(row);
    switch (index.column()) {
    case Latitude:
        if (std::abs(v) > 90)
            return false;
        m_plan->move(row, v, w.lon);
        return true;
    case Longitude:
        if (std::abs(v) > 180)
            return false;
        m_plan->move(row, w.lat, v);
        return true;
    case Speed:
        if (v < 0)
            return false;
        m_plan->setSpeed(row, v);
        return true;
    case Tolerance:
        if (v < 0 || v > kMaxMissionToleranceM)
            return false;
        m_plan->setTolerance(row, v);
        return true;
    default:
        return false;
    }
}

Qt::ItemFlags MissionPlanTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() != Number)
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant MissionPlanTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Number:
        return tr("#");
    case Latitude:
        return tr("Latitude");
    case Longitude:
        return tr("Longitude");
    case Speed:
        return tr("Speed m/s");
    case Tolerance:
        return tr("Tolerance m");
    default:
        return {};
    }
}

} // namespace ocu
