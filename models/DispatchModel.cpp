#include "models/DispatchModel.h"

#include "models/FleetModel.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>

#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
// Rows in truck-name order (ids break ties), as the dispatcher reads them.
bool before(const DispatchTruck& a, const DispatchTruck& b) {
    return a.name != b.name ? a.name < b.name : a.id < b.id;
}
QString orDash(const QString& s) {
    return s.isEmpty() ? QStringLiteral("—") : s;
}
QString duration(qint64 seconds) {
    if (seconds < 0)
        return QStringLiteral("—");
    if (seconds < 3600)
        return QStringLiteral("%1:%2").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1 h %2").arg(seconds / 3600).arg((seconds % 3600) / 60, 2, 10, QLatin1Char('0'));
}
} // namespace

DispatchModel::DispatchModel(QObject* parent) : QAbstractTableModel(parent) {
    m_clockTimer.setInterval(1000);
    connect(&m_clockTimer, &QTimer::timeout, this, &DispatchModel::refreshTimes);
    m_clockTimer.start();
}

void DispatchModel::setSource(DispatchSource* source) {
    if (m_source)
        disconnect(m_source, nullptr, this, nullptr);
    m_source = source;
    if (source) {
        connect(source, &DispatchSource::trucksChanged, this, &DispatchModel::updateTrucks);
        connect(source, &DispatchSource::areasChanged, this, [this] {
            for (auto& r : m_rows)
                r.routeValid = false;
        });
    }
    reload();
}

void DispatchModel::setFleet(FleetModel* fleet) {
    m_fleet = fleet;
}

void DispatchModel::reload() {
    beginResetModel();
    m_rows.clear();
    m_index.clear();
    if (m_source)
        for (auto& t : m_source->trucks()) {
            m_rows.push_back(Row{std::move(t), false, {}, {}});
            formatRow(m_rows.back());
        }
    // Truck-name order, the same as insertSorted keeps (it was id order here, name order on inserts).
    std::sort(m_rows.begin(), m_rows.end(),
              [](const Row& a, const Row& b) { return before(a.truck, b.truck); });
    reindex(0);
    endResetModel();
    emit trucksUpdated({});
}

void DispatchModel::reindex(int from) {
    for (int i = from; i < m_rows.size(); ++i)
        m_index.insert(m_rows[i].truck.id, i);
}

void DispatchModel::updateTrucks(const QStringList& ids) {
    if (!m_source)
        return;
    struct Change {
        int row;
        uint mask;
        QString id;
    };
    QVector<Change> updated; // rows changed in place (their row numbers are looked up after inserts/removals)
    for (const QString& id : ids) {
        std::optional<DispatchTruck> t = m_source->truck(id);
        const int row = m_index.value(id, -1);
        if (!t) {
            if (row >= 0)
                removeRowAt(row);
            continue;
        }
        if (row < 0) {
            insertSorted(std::move(*t));
            continue;
        }
        if (m_rows[row].truck.name != t->name) { // renamed: its place changes
            removeRowAt(row);
            insertSorted(std::move(*t));
            continue;
        }
        Row& r = m_rows[row];
        uint mask = 0; // the columns whose cells change
        if (r.truck.wayId != t->wayId || r.truck.destinationId != t->destinationId ||
            r.truck.assignmentId != t->assignmentId || r.truck.assignmentStatus != t->assignmentStatus) {
            r.routeValid = false;
            mask |= 1u << ColEta;
        }
        if (r.truck.productionSinceMs != t->productionSinceMs)
            mask |= 1u << ColInState;
        const bool cueChanged = r.truck.needsAssignment != t->needsAssignment ||
                                r.truck.custodian != t->custodian || r.truck.lastResponse != t->lastResponse;
        const std::array<QString, ColumnCount> previous = std::move(r.text);
        r.truck = std::move(*t);
        formatRow(r);
        for (int c = 0; c < ColumnCount; ++c)
            if (r.text[c] != previous[c])
                mask |= 1u << c;
        if (cueChanged) // the colours of the row or of its assignment/custodian cell
            mask = (1u << ColumnCount) - 1;
        if (mask)
            updated.push_back({0, mask, id});
    }
    // Row numbers after the inserts and removals; one dataChanged per run of consecutive rows with the same
    // changed columns and per run of consecutive changed columns.
    for (auto& u : updated)
        u.row = m_index.value(u.id, -1);
    std::sort(updated.begin(), updated.end(), [](const Change& a, const Change& b) { return a.row < b.row; });
    for (qsizetype i = 0; i < updated.size();) {
        if (updated[i].row < 0) {
            ++i;
            continue;
        }
        qsizetype j = i + 1;
        while (j < updated.size() && updated[j].row == updated[j - 1].row + 1 &&
               updated[j].mask == updated[i].mask)
            ++j;
        const uint mask = updated[i].mask;
        for (int c = 0; c < ColumnCount;) {
            if (!(mask & (1u << c))) {
                ++c;
                continue;
            }
            int d = c;
            while (d + 1 < ColumnCount && (mask & (1u << (d + 1))))
                ++d;
            emit dataChanged(index(updated[i].row, c), index(updated[j - 1].row, d));
            c = d + 1;
        }
        i = j;
    }
    emit trucksUpdated(ids);
}

void DispatchModel::removeRowAt(int row) {
    beginRemoveRows({}, row, row);
    m_index.remove(m_rows[row].truck.id);
    m_rows.remove(row);
    reindex(row);
    endRemoveRows();
}

void DispatchModel::insertSorted(DispatchTruck&& t) {
    const auto at = std::lower_bound(m_rows.begin(), m_rows.end(), t,
                                     [](const Row& r, const DispatchTruck& k) { return before(r.truck, k); });
    const int pos = int(at - m_rows.begin());
    beginInsertRows({}, pos, pos);
    m_rows.insert(pos, Row{std::move(t), false, {}, {}});
    formatRow(m_rows[pos]);
    reindex(pos);
    endInsertRows();
}

void DispatchModel::formatRow(Row& r) const {
    const DispatchTruck& t = r.truck;
    r.text[ColTruck] = t.name;
    r.text[ColCustodian] = t.stateKnown ? orDash(t.custodian) : tr("link down");
    r.text[ColMode] = orDash(t.autonomyMode);
    r.text[ColAssignment] = assignmentText(t);
    r.text[ColTask] = orDash(t.task);
    r.text[ColDestination] = !t.destinationId              ? QStringLiteral("—")
                             : t.destinationName.isEmpty() ? tr("way %1").arg(*t.destinationId)
                                                           : t.destinationName;
    r.text[ColProduction] = orDash(t.productionState);
    r.text[ColPayload] =
        t.payloadTonnes ? QStringLiteral("%1 t").arg(*t.payloadTonnes, 0, 'f', 0) : QStringLiteral("—");
}

void DispatchModel::refreshTimes() {
    if (m_rows.isEmpty())
        return;
    // A view repaints only the visible cells of these columns.
    emit dataChanged(index(0, ColInState), index(int(m_rows.size()) - 1, ColInState), {Qt::DisplayRole});
    emit dataChanged(index(0, ColEta), index(int(m_rows.size()) - 1, ColEta), {Qt::DisplayRole});
}

int DispatchModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DispatchModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

int DispatchModel::rowOf(const QString& id) const {
    return m_index.value(id, -1);
}

const QVector<DispatchTruck> DispatchModel::trucks() const {
    QVector<DispatchTruck> out;
    out.reserve(m_rows.size());
    for (const auto& r : m_rows)
        out << r.truck;
    return out;
}

int DispatchModel::needsAssignmentCount() const {
    return int(
        std::count_if(m_rows.begin(), m_rows.end(), [](const Row& r) { return r.truck.needsAssignment; }));
}

const DispatchRoute& DispatchModel::routeOf(int row) const {
    const Row& r = m_rows[row];
    if (!r.routeValid) {
        r.route = m_source ? m_source->route(r.truck.id) : DispatchRoute{};
        r.routeValid = true;
    }
    return r.route;
}

double DispatchModel::etaSeconds(int row, bool* nominal) const {
    if (nominal)
        *nominal = false;
    const DispatchRoute& route = routeOf(row);
    if (route.ways.isEmpty())
        return -1;
    double speed = 0;
    if (m_fleet)
        if (const MachineState* m = m_fleet->machine(m_rows[row].truck.id))
            speed = m->speed;
    if (!(speed >= 1.0)) {
        speed = kNominalSpeedMs;
        if (nominal)
            *nominal = true;
    }
    return route.lengthM / speed;
}

QString DispatchModel::etaText(int row) const {
    bool nominal = false;
    const double s = etaSeconds(row, &nominal);
    if (s < 0)
        return QStringLiteral("—");
    return (nominal ? QStringLiteral("~") : QString()) + duration(qint64(std::llround(s)));
}

QString DispatchModel::assignmentText(const DispatchTruck& t) const {
    if (t.needsAssignment)
        return tr("NEEDS ASSIGNMENT");
    QString s = t.assignmentStatus;
    // The answer to this console's newest request, when it is not what the truck reports as its assignment.
    if (!t.lastResponse.isEmpty() && t.requestedAssignmentId != t.assignmentId)
        s = s.isEmpty() ? t.lastResponse : s + QStringLiteral(" · ") + t.lastResponse;
    else if (t.lastResponse == QLatin1String("Rejected"))
        s += QStringLiteral(" · Rejected");
    return orDash(s);
}

QVariant DispatchModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const DispatchTruck& t = m_rows[index.row()].truck;
    const int col = index.column();
    if (role == IdRole)
        return t.id;
    if (role == NeedsAssignmentRole)
        return t.needsAssignment;
    if (role == EtaSecondsRole)
        return etaSeconds(index.row());
    if (role == Qt::DisplayRole) {
        switch (col) {
        case ColEta:
            return etaText(index.row());
        case ColInState:
            return t.productionSinceMs > 0
                       ? duration(std::max<qint64>(0, (m_clock->nowMs() - t.productionSinceMs) / 1000))
                       : QStringLiteral("—");
        default:
            return m_rows[index.row()].text[col]; // formatted when the report came (formatRow)
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (col) {
        case ColAssignment: {
            QString tip = tr("Reported assignment: %1").arg(orDash(t.assignmentStatus));
            if (!t.assignmentId.isEmpty())
                tip += QStringLiteral(" (%1)").arg(t.assignmentId);
            if (!t.requestedTask.isEmpty())
                tip += QLatin1Char('\n') +
                       tr("Last request from this console: %1 to way %2 — %3")
                           .arg(t.requestedTask)
                           .arg(t.requestedDestination.value_or(0))
                           .arg(t.lastResponse.isEmpty() ? tr("no answer yet") : t.lastResponse);
            if (!t.lastResponseDetail.isEmpty())
                tip += QLatin1Char('\n') + tr("Detail: %1").arg(t.lastResponseDetail);
            if (t.needsAssignment)
                tip += QLatin1Char('\n') + tr("The truck asks for work (or was handed back to the FMS).");
            return tip;
        }
        case ColEta: {
            const DispatchRoute& r = routeOf(index.row());
            if (r.ways.isEmpty())
                return tr("No route: %1").arg(orDash(r.error));
            bool nominal = false;
            etaSeconds(index.row(), &nominal);
            return tr("%1 m over %n way(s) (%2); %3", "", int(r.ways.size()))
                .arg(r.lengthM, 0, 'f', 0)
                .arg(r.fromAssignment ? tr("route of the assignment") : tr("shortest path"))
                .arg(nominal ? tr("nominal 25 km/h (the truck is slower than 1 m/s)")
                             : tr("at the reported speed"));
        }
        case ColCustodian:
            return tr("DispatchingCustodian: who dispatches this truck (only FMS trucks can be assigned)");
        default:
            return {};
        }
    }
    if (role == Qt::BackgroundRole) {
        if (t.needsAssignment)
            return QBrush(QColor(0xff, 0xd5, 0x4f)); // amber: the dispatcher has to act
        if (col == ColAssignment && t.lastResponse == QLatin1String("Rejected"))
            return QBrush(QColor(0xf4, 0xa0, 0xa0));
        if (col == ColCustodian && t.custodian == QLatin1String("AHS"))
            return QBrush(QColor(0xd8, 0xd8, 0xd8));
    }
    if (role == Qt::ForegroundRole &&
        (t.needsAssignment || (col == ColAssignment && t.lastResponse == QLatin1String("Rejected"))))
        return QBrush(Qt::black); // readable on the cue colours in the night palette too
    if (role == Qt::TextAlignmentRole && (col == ColEta || col == ColPayload || col == ColInState))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant DispatchModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case ColTruck:
        return tr("Truck");
    case ColCustodian:
        return tr("Custodian");
    case ColMode:
        return tr("Mode");
    case ColAssignment:
        return tr("Assignment");
    case ColTask:
        return tr("Task");
    case ColDestination:
        return tr("Destination");
    case ColEta:
        return tr("ETA");
    case ColProduction:
        return tr("Production");
    case ColPayload:
        return tr("Payload");
    case ColInState:
        return tr("In state");
    }
    return {};
}

// ---- queues ----

DispatchQueueModel::DispatchQueueModel(DispatchModel* trucks, QObject* parent)
    : QAbstractTableModel(parent), m_trucks(trucks) {
    connect(trucks, &DispatchModel::trucksUpdated, this, &DispatchQueueModel::rebuild);
    connect(trucks, &QAbstractItemModel::modelReset, this, &DispatchQueueModel::rebuild);
    rebuild();
}

namespace {
// At most `shown` names, then "+N": a cell shows a handful anyway (the tooltip has them all), and a long
// joined string would be laid out again at every repaint.
QString names(const QStringList& list, int shown) {
    if (list.size() <= shown)
        return list.join(QStringLiteral(", "));
    return QStringList(list.mid(0, shown)).join(QStringLiteral(", ")) +
           QStringLiteral(" +%1").arg(list.size() - shown);
}
} // namespace

QString DispatchQueueModel::trucksText(const Queue& q, int shown) {
    QStringList parts;
    if (!q.atArea.isEmpty())
        parts << tr("at: %1").arg(names(q.atArea, shown));
    if (!q.enRoute.isEmpty())
        parts << tr("coming: %1").arg(names(q.enRoute, shown));
    return parts.join(QStringLiteral("; "));
}

bool DispatchQueueModel::isQueueArea(const DispatchArea& a) {
    return a.defaultTask == QLatin1String("Load") || a.defaultTask == QLatin1String("Offload");
}

void DispatchQueueModel::rebuild() {
    QVector<Queue> next;
    // By way id, the link compared only on a hit: 1,000 trucks per update, and hashing the link's string
    // for each of them showed on the GUI thread.
    QMultiHash<qint64, int> byWay;
    if (DispatchSource* src = m_trucks->source())
        for (const DispatchArea& a : src->areas())
            if (isQueueArea(a)) {
                byWay.insert(a.wayId, int(next.size()));
                next.push_back(Queue{a, {}, {}});
            }
    const auto queueAt = [&](const QString& link, qint64 way) {
        for (auto it = byWay.constFind(way); it != byWay.constEnd() && it.key() == way; ++it)
            if (next[*it].area.link == link)
                return *it;
        return -1;
    };
    for (int row = 0; row < m_trucks->rowCount(); ++row) {
        const DispatchTruck& t = m_trucks->truckAt(row);
        if (t.wayId)
            if (const int i = queueAt(t.link, *t.wayId); i >= 0) {
                next[i].atArea << t.name;
                continue;
            }
        if (const auto dest = t.activeDestination())
            if (const int i = queueAt(t.link, *dest); i >= 0)
                next[i].enRoute << t.name;
    }
    const bool sameAreas =
        next.size() == m_queues.size() &&
        std::equal(next.begin(), next.end(), m_queues.begin(), [](const Queue& a, const Queue& b) {
            return a.area.link == b.area.link && a.area.wayId == b.area.wayId && a.area.name == b.area.name;
        });
    if (!sameAreas) {
        beginResetModel();
        m_queues = std::move(next);
        endResetModel();
        return;
    }
    // Only the queues whose trucks changed are repainted.
    QVector<int> changed;
    for (int i = 0; i < next.size(); ++i)
        if (next[i].enRoute != m_queues[i].enRoute || next[i].atArea != m_queues[i].atArea)
            changed << i;
    m_queues = std::move(next);
    for (int i = 0; i < changed.size();) {
        int j = i + 1;
        while (j < changed.size() && changed[j] == changed[j - 1] + 1)
            ++j;
        emit dataChanged(index(changed[i], ColEnRoute), index(changed[j - 1], ColTrucks));
        i = j;
    }
}

const DispatchQueueModel::Queue* DispatchQueueModel::queueOf(const QString& link, qint64 wayId) const {
    for (const auto& q : m_queues)
        if (q.area.link == link && q.area.wayId == wayId)
            return &q;
    return nullptr;
}

int DispatchQueueModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_queues.size());
}

int DispatchQueueModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant DispatchQueueModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_queues.size())
        return {};
    const Queue& q = m_queues[index.row()];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case ColArea:
            return q.area.name.isEmpty() ? tr("way %1").arg(q.area.wayId) : q.area.name;
        case ColKind:
            return q.area.defaultTask == QLatin1String("Load") ? tr("Shovel (load)") : tr("Dump (offload)");
        case ColEnRoute:
            return int(q.enRoute.size());
        case ColAtArea:
            return int(q.atArea.size());
        case ColTrucks:
            return trucksText(q, kShownNames);
        }
    }
    if (role == Qt::ToolTipRole)
        return tr("Way %1 on %2. Coming: assigned (Pending/Active) and not yet there; at: the truck reports "
                  "this "
                  "area as its way (queued, spotting, loading or dumping).")
                   .arg(q.area.wayId)
                   .arg(q.area.link) +
               (index.column() == ColTrucks ? QStringLiteral("\n") + trucksText(q, 1000) : QString());
    if (role == Qt::TextAlignmentRole && (index.column() == ColEnRoute || index.column() == ColAtArea))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant DispatchQueueModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case ColArea:
        return tr("Area");
    case ColKind:
        return tr("Kind");
    case ColEnRoute:
        return tr("Coming");
    case ColAtArea:
        return tr("At area");
    case ColTrucks:
        return tr("Trucks");
    }
    return {};
}

} // namespace ocu
