#include "models/AlarmModel.h"

#include "models/FleetBridge.h"
#include "models/FleetModel.h"

#include <QColor>
#include <QDateTime>
#include <QFile>
#include <QFont>
#include <QIODevice>

namespace ocu {

AlarmModel::AlarmModel(QObject* parent) : QAbstractTableModel(parent) {}

void AlarmModel::addBridge(FleetBridge* bridge) {
    connect(bridge, &FleetBridge::eventRaised, this, &AlarmModel::add);
    connect(bridge, &FleetBridge::linkChanged, this, &AlarmModel::onLink);
}

void AlarmModel::onLink(const LinkStatus& status) {
    const bool down = status.state == LinkState::Down;
    const bool wasDown = m_linkDown.contains(status.link);
    if (down && !wasDown) {
        m_linkDown.insert(status.link, 1);
        FleetEvent ev = makeEvent(
            EventSeverity::Alarm, EventKind::LinkLoss, {},
            tr("link %1 lost%2")
                .arg(status.link, status.detail.isEmpty() ? QString() : QStringLiteral(": ") + status.detail),
            status.link);
        add(ev);
    } else if (!down && wasDown && status.state == LinkState::Up) {
        m_linkDown.remove(status.link);
        add(makeEvent(EventSeverity::Info, EventKind::LinkLoss, {}, tr("link %1 restored").arg(status.link),
                      status.link));
    }
}

void AlarmModel::watchFleet(FleetModel* fleet) {
    connect(fleet, &FleetModel::machineStaleChanged, this, [this](const QString& id, bool stale) {
        if (stale)
            add(makeEvent(EventSeverity::Warning, EventKind::Timeout, id, tr("no data from %1").arg(id)));
    });
    connect(fleet, &FleetModel::machinesChanged, this, [this, fleet](const QStringList& ids) {
        for (const QString& id : ids) {
            const MachineState* m = fleet->machine(id);
            if (!m)
                continue;
            const int level = int(m->health);
            const int prev = m_health.value(id, int(HealthLevel::Unknown));
            if (level != prev) {
                m_health.insert(id, level);
                if (m->health == HealthLevel::Fault)
                    add(makeEvent(EventSeverity::Alarm, EventKind::HealthFault, id,
                                  m->healthText.isEmpty() ? tr("health fault") : m->healthText,
                                  toText(m->protocol)));
            }
        }
    });
    connect(fleet, &FleetModel::machineRemoved, this, [this](const QString& id) { m_health.remove(id); });
}

int AlarmModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}
int AlarmModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant AlarmModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case ColTime:
        return tr("Time (UTC)");
    case ColSeverity:
        return tr("Severity");
    case ColKind:
        return tr("Kind");
    case ColMachine:
        return tr("Machine");
    case ColText:
        return tr("Message");
    case ColAck:
        return tr("Ack");
    default:
        return {};
    }
}

static QColor severityColor(EventSeverity s) {
    switch (s) {
    case EventSeverity::Info:
        return QColor(0x1e, 0x6f, 0xe8);
    case EventSeverity::Warning:
        return QColor(0xfe, 0x9a, 0x2e);
    case EventSeverity::Alarm:
    case EventSeverity::Critical:
        return QColor(0xe0, 0x20, 0x20);
    }
    return Qt::black;
}

QVariant AlarmModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row& r = m_rows[index.row()];
    const FleetEvent& e = r.event;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case ColTime:
            return QDateTime::fromMSecsSinceEpoch(e.timeMs, Qt::UTC)
                .toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
        case ColSeverity:
            return toText(e.severity).toUpper();
        case ColKind:
            return toText(e.kind);
        case ColMachine:
            return e.machineId;
        case ColText:
            return e.text;
        case ColAck:
            return !e.requiresAck ? QString() : (r.acked ? tr("yes") : tr("NO"));
        default:
            return {};
        }
    case Qt::DecorationRole:
        return index.column() == ColSeverity ? QVariant(severityColor(e.severity)) : QVariant();
    case Qt::FontRole:
        if (e.requiresAck && !r.acked) {
            QFont f;
            f.setBold(true);
            return f;
        }
        return {};
    case SeverityRole:
        return int(e.severity);
    case KindRole:
        return int(e.kind);
    case AckedRole:
        return r.acked;
    case RequiresAckRole:
        return e.requiresAck;
    case TimeRole:
        return e.timeMs;
    case MachineRole:
        return e.machineId;
    default:
        return {};
    }
}

void AlarmModel::add(const FleetEvent& event) {
    FleetEvent ev = event;
    if (ev.timeMs == 0)
        ev.timeMs = QDateTime::currentMSecsSinceEpoch();
    const int row = int(m_rows.size());
    beginInsertRows({}, row, row);
    m_rows.push_back(Row{ev, !ev.requiresAck, 0});
    endInsertRows();
    if (ev.requiresAck) {
        ++m_unacked;
        emit unacknowledgedCountChanged(m_unacked);
    }
    emit eventAdded(ev);
    trim();
}

void AlarmModel::trim() {
    if (m_maxEntries <= 0 || m_rows.size() <= m_maxEntries)
        return;
    // Drop the oldest acknowledged entries; never an unacknowledged alarm.
    int excess = int(m_rows.size()) - m_maxEntries;
    for (int i = 0; i < m_rows.size() && excess > 0;) {
        if (m_rows[i].acked) {
            beginRemoveRows({}, i, i);
            m_rows.remove(i);
            endRemoveRows();
            --excess;
        } else {
            ++i;
        }
    }
}

// The alarm's stable text for alarmAcknowledged (same as recording::alarmKey).
static QString ackKey(const FleetEvent& e) {
    return QStringLiteral("%1|%2|%3|%4").arg(QString::number(e.timeMs), toText(e.kind), e.machineId, e.text);
}

void AlarmModel::acknowledge(int row) {
    if (row < 0 || row >= m_rows.size() || m_rows[row].acked)
        return;
    m_rows[row].acked = true;
    m_rows[row].ackedMs = QDateTime::currentMSecsSinceEpoch();
    --m_unacked;
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    emit unacknowledgedCountChanged(m_unacked);
    emit alarmAcknowledged(ackKey(m_rows[row].event), qEnvironmentVariable("USER"), m_rows[row].ackedMs);
}

void AlarmModel::acknowledgeAll() {
    if (m_unacked == 0)
        return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QStringList keys;
    for (Row& r : m_rows) {
        if (!r.acked) {
            r.acked = true;
            r.ackedMs = now;
            keys << ackKey(r.event);
        }
    }
    m_unacked = 0;
    emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
    emit unacknowledgedCountChanged(0);
    for (const QString& key : std::as_const(keys))
        emit alarmAcknowledged(key, qEnvironmentVariable("USER"), now);
}

static QByteArray csvField(const QString& s) {
    QString v = s;
    if (v.contains(QLatin1Char('"')) || v.contains(QLatin1Char(',')) || v.contains(QLatin1Char('\n')) ||
        v.contains(QLatin1Char('\r'))) {
        v.replace(QLatin1String("\""), QLatin1String("\"\""));
        v = QLatin1Char('"') + v + QLatin1Char('"');
    }
    return v.toUtf8();
}

bool AlarmModel::exportCsv(QIODevice* out, const QVector<int>& rows) const {
    if (!out || !out->isWritable())
        return false;
    QByteArray buf("time,severity,kind,machine,source,text,acknowledged\r\n");
    auto emitRow = [&](int i) {
        const Row& r = m_rows[i];
        const FleetEvent& e = r.event;
        buf += csvField(QDateTime::fromMSecsSinceEpoch(e.timeMs, Qt::UTC).toString(Qt::ISODateWithMs)) + ',' +
               csvField(toText(e.severity)) + ',' + csvField(toText(e.kind)) + ',' + csvField(e.machineId) +
               ',' + csvField(e.source) + ',' + csvField(e.text) + ',' +
               (e.requiresAck ? (r.acked ? "yes" : "no") : "n/a") + "\r\n";
    };
    if (rows.isEmpty()) {
        for (int i = 0; i < m_rows.size(); ++i)
            emitRow(i);
    } else {
        for (int i : rows)
            if (i >= 0 && i < m_rows.size())
                emitRow(i);
    }
    return out->write(buf) == buf.size();
}

bool AlarmModel::exportCsv(const QString& path) const {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    return exportCsv(&f);
}

AlarmFilterProxy::AlarmFilterProxy(QObject* parent) : QSortFilterProxyModel(parent) {
    setDynamicSortFilter(true);
}

void AlarmFilterProxy::setText(const QString& text) {
    m_text = text.trimmed();
    invalidateFilter();
}

void AlarmFilterProxy::setMinimumSeverity(EventSeverity s) {
    m_minSeverity = s;
    invalidateFilter();
}

void AlarmFilterProxy::setUnacknowledgedOnly(bool on) {
    m_unackedOnly = on;
    invalidateFilter();
}

bool AlarmFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const {
    auto* alarms = qobject_cast<AlarmModel*>(sourceModel());
    if (!alarms || sourceParent.isValid())
        return true;
    const FleetEvent& e = alarms->eventAt(sourceRow);
    if (e.severity < m_minSeverity)
        return false;
    if (m_unackedOnly && alarms->isAcknowledged(sourceRow))
        return false;
    if (m_text.isEmpty())
        return true;
    return e.text.contains(m_text, Qt::CaseInsensitive) ||
           e.machineId.contains(m_text, Qt::CaseInsensitive) ||
           toText(e.kind).contains(m_text, Qt::CaseInsensitive) ||
           e.source.contains(m_text, Qt::CaseInsensitive);
}

} // namespace ocu
