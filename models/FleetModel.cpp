#include "models/FleetModel.h"

#include "models/DisplayText.h"
#include "models/FleetBridge.h"

#include <QDateTime>
#include <algorithm>

namespace ocu {

// The link state in the operator's language (toText() stays the stable English key).
static QString linkText(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return FleetModel::tr("up");
    case LinkState::Degraded:
        return FleetModel::tr("degraded");
    case LinkState::Down:
        return FleetModel::tr("down");
    case LinkState::Unknown:
        break;
    }
    return FleetModel::tr("unknown");
}

FleetModel::FleetModel(QObject* parent) : QAbstractTableModel(parent) {
    connect(&m_timer, &QTimer::timeout, this, &FleetModel::refresh);
    m_timer.start(500);
}

void FleetModel::addBridge(FleetBridge* bridge) {
    connect(bridge, &FleetBridge::machinesUpdated, this, &FleetModel::upsert);
    connect(bridge, &FleetBridge::machinesRemoved, this, &FleetModel::remove);
}

void FleetModel::setRefreshIntervalMs(int ms) {
    if (ms <= 0)
        m_timer.stop();
    else
        m_timer.start(ms);
}

void FleetModel::setStaleAfterMs(Protocol protocol, qint64 ms) {
    if (ms < 0)
        m_staleByProtocol.remove(int(protocol));
    else
        m_staleByProtocol.insert(int(protocol), ms);
}

int FleetModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int FleetModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString FleetModel::columnName(int column) {
    switch (column) {
    case ColName:
        return tr("Name");
    case ColType:
        return tr("Type");
    case ColProtocol:
        return tr("Protocol");
    case ColLink:
        return tr("Link / age");
    case ColEast:
        return tr("E (m)");
    case ColNorth:
        return tr("N (m)");
    case ColLatitude:
        return tr("Lat");
    case ColLongitude:
        return tr("Lon");
    case ColHeading:
        return tr("Heading");
    case ColSpeed:
        return tr("Speed");
    case ColMode:
        return tr("Mode / state");
    case ColStop:
        return tr("Stop");
    case ColController:
        return tr("Controller");
    case ColHealth:
        return tr("Health");
    case ColLastMessage:
        return tr("Last message");
    default:
        return {};
    }
}

QVariant FleetModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Horizontal && role == Qt::DisplayRole)
        return columnName(section);
    return {};
}

qint64 FleetModel::ageMsAt(int row) const {
    const qint64 t = m_rows[row].state.lastDataMs;
    return t > 0 ? std::max<qint64>(0, nowMs() - t) : -1;
}

static QString ageText(qint64 ms) {
    if (ms < 0)
        return QStringLiteral("–");
    if (ms < 10000)
        return QString::number(double(ms) / 1000.0, 'f', 1) + QStringLiteral(" s");
    if (ms < 120000)
        return QString::number(ms / 1000) + QStringLiteral(" s");
    return QString::number(ms / 60000) + QStringLiteral(" min");
}

static QString protocolLabel(Protocol p) {
    switch (p) {
    case Protocol::Jaus:
        return QStringLiteral("JAUS");
    case Protocol::Iso23725:
        return QStringLiteral("ISO 23725");
    case Protocol::Osyris:
        return QStringLiteral("OSYRIS");
    case Protocol::Other:
        break;
    }
    return QStringLiteral("other");
}

QVariant FleetModel::display(const Row& r, int column) const {
    const MachineState& m = r.state;
    const int row = m_index.value(m.id, -1);
    switch (column) {
    case ColName:
        return m.name.isEmpty() ? m.id : m.name;
    case ColType:
        return m.type;
    case ColProtocol:
        return protocolLabel(m.protocol);
    case ColLink:
        return QStringLiteral("%1 · %2").arg(linkText(m.link), ageText(row >= 0 ? ageMsAt(row) : -1));
    case ColEast:
        return m.hasPosition ? QString::number(m.e, 'f', 1) : QString();
    case ColNorth:
        return m.hasPosition ? QString::number(m.n, 'f', 1) : QString();
    case ColLatitude:
        return m.hasPosition ? QString::number(m.lat, 'f', 7) : QString();
    case ColLongitude:
        return m.hasPosition ? QString::number(m.lon, 'f', 7) : QString();
    case ColHeading:
        return m.hasPosition ? QString::number(m.headingDeg, 'f', 0) + QChar(0x00B0) : QString();
    case ColSpeed:
        // Displayed in km/h (anchors-features.md §8.2), stored in m/s.
        return QString::number(m.speed * 3.6, 'f', 1) + QStringLiteral(" km/h");
    case ColMode:
        return m.modeText.isEmpty() ? DisplayText::mode(m.mode) : m.modeText;
    case ColStop:
        if (m.stop == StopState::Stopped)
            return m.stopText.isEmpty() ? tr("STOPPED") : m.stopText.toUpper();
        return m.stop == StopState::None ? tr("running") : tr("unknown");
    case ColController:
        if (m.control == ControlState::ControlledByMe)
            return tr("this OCU");
        return m.controller.isEmpty()
                   ? (m.control == ControlState::None ? QString() : DisplayText::control(m.control))
                   : m.controller;
    case ColHealth:
        return m.healthText.isEmpty()
                   ? DisplayText::health(m.health)
                   : QStringLiteral("%1: %2").arg(DisplayText::health(m.health), m.healthText);
    case ColLastMessage:
        return m.lastMessageMs > 0 ? QDateTime::fromMSecsSinceEpoch(m.lastMessageMs, Qt::UTC)
                                         .toString(QStringLiteral("HH:mm:ss.zzz"))
                                   : QString();
    default:
        return {};
    }
}

QVariant FleetModel::raw(const Row& r, int column) const {
    const MachineState& m = r.state;
    switch (column) {
    case ColName:
        return m.name.isEmpty() ? m.id : m.name;
    case ColType:
        return m.type;
    case ColProtocol:
        return int(m.protocol);
    case ColLink:
        return m.lastDataMs;
    case ColEast:
        return m.e;
    case ColNorth:
        return m.n;
    case ColLatitude:
        return m.lat;
    case ColLongitude:
        return m.lon;
    case ColHeading:
        return m.headingDeg;
    case ColSpeed:
        return m.speed;
    case ColMode:
        return int(m.mode);
    case ColStop:
        return int(m.stop);
    case ColController:
        return m.controller;
    case ColHealth:
        return int(m.health);
    case ColLastMessage:
        return m.lastMessageMs;
    default:
        return {};
    }
}

QVariant FleetModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row& r = m_rows[index.row()];
    switch (role) {
    case Qt::DisplayRole:
        return display(r, index.column());
    case Qt::ToolTipRole:
        return QStringLiteral("%1 — %2").arg(r.state.id, DisplayText::status(statusOf(r.state, r.stale)));
    case Qt::DecorationRole:
        if (index.column() == ColName)
            return statusColor(statusOf(r.state, r.stale));
        return {};
    case IdRole:
        return r.state.id;
    case RawRole:
        return raw(r, index.column());
    case StateRole:
        return QVariant::fromValue(r.state);
    case StatusRole:
        return int(statusOf(r.state, r.stale));
    case StatusColorRole:
        return statusColor(statusOf(r.state, r.stale));
    case StaleRole:
        return r.stale;
    case AgeMsRole:
        return ageMsAt(index.row());
    case ProtocolRole:
        return int(r.state.protocol);
    default:
        return {};
    }
}

const MachineState* FleetModel::machine(const QString& id) const {
    const int row = rowOf(id);
    return row >= 0 ? &m_rows[row].state : nullptr;
}

bool FleetModel::isStale(const QString& id) const {
    const int row = rowOf(id);
    return row >= 0 && m_rows[row].stale;
}

QStringList FleetModel::ids() const {
    QStringList out;
    out.reserve(m_rows.size());
    for (const Row& r : m_rows)
        out.push_back(r.state.id);
    return out;
}

const QVector<MachineState>& FleetModel::machinesSnapshot() const {
    if (!m_snapshotValid) {
        m_snapshot.clear();
        m_snapshot.reserve(m_rows.size());
        for (const Row& r : m_rows)
            m_snapshot.push_back(r.state);
        m_snapshotValid = true;
    }
    return m_snapshot;
}

void FleetModel::upsert(const QVector<MachineState>& machines) {
    if (machines.isEmpty())
        return;
    const qint64 now = nowMs();
    int minRow = INT_MAX, maxRow = -1;
    QVector<MachineState> added;
    QStringList changed;
    changed.reserve(machines.size());
    for (const MachineState& in : machines) {
        if (in.id.isEmpty())
            continue;
        const int row = m_index.value(in.id, -1);
        if (row < 0) {
            added.push_back(in);
            if (added.back().lastDataMs == 0)
                added.back().lastDataMs = now;
            continue;
        }
        Row& r = m_rows[row];
        r.state = in;
        if (r.state.lastDataMs == 0)
            r.state.lastDataMs = now;
        const qint64 staleMs = staleAfterMs(r.state.protocol);
        const bool stale = staleMs > 0 && now - r.state.lastDataMs > staleMs;
        if (stale != r.stale) {
            r.stale = stale;
            emit machineStaleChanged(in.id, stale);
        }
        minRow = std::min(minRow, row);
        maxRow = std::max(maxRow, row);
        changed.push_back(in.id);
    }
    m_snapshotValid = false;
    if (maxRow >= 0)
        emit dataChanged(index(minRow, 0), index(maxRow, ColumnCount - 1));
    if (!added.isEmpty()) {
        // Duplicates inside one batch are impossible from a bridge (coalesced) but possible via direct calls.
        QVector<MachineState> unique;
        QHash<QString, int> seen;
        for (const MachineState& m : added) {
            auto it = seen.find(m.id);
            if (it != seen.end())
                unique[*it] = m;
            else {
                seen.insert(m.id, int(unique.size()));
                unique.push_back(m);
            }
        }
        const int first = int(m_rows.size());
        beginInsertRows({}, first, first + int(unique.size()) - 1);
        for (const MachineState& m : unique) {
            m_index.insert(m.id, int(m_rows.size()));
            const qint64 staleMs = staleAfterMs(m.protocol);
            m_rows.push_back(Row{m, staleMs > 0 && now - m.lastDataMs > staleMs});
        }
        endInsertRows();
        for (const MachineState& m : unique) {
            emit machineAdded(m.id);
            changed.push_back(m.id);
        }
    }
    if (!changed.isEmpty())
        emit machinesChanged(changed);
}

void FleetModel::rebuildIndex() {
    m_index.clear();
    for (int i = 0; i < m_rows.size(); ++i)
        m_index.insert(m_rows[i].state.id, i);
}

void FleetModel::remove(const QStringList& ids) {
    QVector<int> rows;
    for (const QString& id : ids) {
        const int row = rowOf(id);
        if (row >= 0)
            rows.push_back(row);
    }
    if (rows.isEmpty())
        return;
    std::sort(rows.begin(), rows.end(), std::greater<int>());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    QStringList removed;
    for (int row : rows) {
        removed.push_back(m_rows[row].state.id);
        beginRemoveRows({}, row, row);
        m_rows.remove(row);
        endRemoveRows();
    }
    rebuildIndex();
    m_snapshotValid = false;
    for (const QString& id : removed)
        emit machineRemoved(id);
}

void FleetModel::refresh() {
    const qint64 now = nowMs();
    QStringList expired;
    QStringList staleFlips;
    for (int i = 0; i < m_rows.size(); ++i) {
        Row& r = m_rows[i];
        const qint64 age = now - r.state.lastDataMs;
        if (m_removeAfterMs > 0 && age > m_removeAfterMs) {
            expired.push_back(r.state.id);
            continue;
        }
        const qint64 staleMs = staleAfterMs(r.state.protocol);
        const bool stale = staleMs > 0 && age > staleMs;
        if (stale != r.stale) {
            r.stale = stale;
            emit dataChanged(index(i, 0), index(i, ColumnCount - 1));
            emit machineStaleChanged(r.state.id, stale);
        }
    }
    if (!m_rows.isEmpty())
        emit dataChanged(index(0, ColLink), index(int(m_rows.size()) - 1, ColLink));
    if (!expired.isEmpty())
        remove(expired);
}

} // namespace ocu
