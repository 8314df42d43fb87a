#include "models/AlarmModel.h"

#include "models/DisplayText.h"

#include "models/FleetBridge.h"
#include "models/FleetModel.h"

#include <QColor>
#include <QDateTime>
#include <QFile>
#include <QFont>
#include <QIODevice>
#include <QLocale>
#include <QTimer>

namespace ocu {

AlarmModel::AlarmModel(QObject* parent)
    : QAbstractTableModel(parent), m_operator(QStringLiteral("local")), m_timer(new QTimer(this)) {
    m_timer->setInterval(1000);
    connect(m_timer, &QTimer::timeout, this, [this] {
        expireShelving();
        pruneRate(true);
    });
}

int AlarmModel::rowOfKey(const QString& key) const {
    for (int i = int(m_rows.size()) - 1; i >= 0; --i)
        if (m_rows[i].key == key)
            return i;
    return -1;
}

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
    case ColPriority:
        return tr("Priority");
    case ColCount:
        return tr("Count");
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
            return DisplayText::severity(e.severity).toUpper(); // toText(): the stable key
        case ColKind:
            return DisplayText::kind(e.kind);
        case ColMachine:
            return e.machineId;
        case ColText:
            return e.text;
        case ColAck:
            if (!e.requiresAck)
                return QString();
            if (m_shelves.contains(r.key))
                return tr("shelved until %1")
                    .arg(QDateTime::fromMSecsSinceEpoch(m_shelves.value(r.key).untilMs, Qt::UTC)
                             .toString(QStringLiteral("HH:mm")));
            return r.acked ? tr("yes") : tr("NO");
        case ColPriority:
            return e.requiresAck ? DisplayText::priority(effectivePriority(e)) : QString();
        case ColCount:
            // Grouped items and repeats: "1,000" machines, "×3" raised three times while active.
            return (e.itemCount > 1 ? QLocale().toString(e.itemCount) : QString()) +
                   (r.occurrences > 1 ? QStringLiteral(" ×%1").arg(r.occurrences) : QString());
        default:
            return {};
        }
    case Qt::ToolTipRole:
        if (index.column() == ColText && !e.details.isEmpty())
            return e.details.mid(0, 20).join(QLatin1Char('\n')) +
                   (e.details.size() > 20 ? tr("\n… and %1 more").arg(e.details.size() - 20) : QString());
        // The full text of the columns that may be narrower than their content.
        if (index.column() == ColText)
            return e.text;
        if (index.column() == ColMachine)
            return e.machineId;
        if (index.column() == ColKind)
            return QStringLiteral("%1 (%2)").arg(DisplayText::kind(e.kind), toText(e.kind));
        return {};
    case Qt::DecorationRole:
        return index.column() == ColSeverity ? QVariant(severityColor(e.severity)) : QVariant();
    case Qt::FontRole:
        if (e.requiresAck && !r.acked && !m_shelves.contains(r.key)) {
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
    case KeyRole:
        return r.key;
    case PriorityRole:
        return int(effectivePriority(e));
    case OccurrencesRole:
        return r.occurrences;
    case ShelvedRole:
        return m_shelves.contains(r.key);
    case DetailsRole:
        return e.details;
    default:
        return {};
    }
}

void AlarmModel::add(const FleetEvent& event) {
    FleetEvent ev = event;
    const qint64 now = nowMs();
    if (ev.timeMs == 0)
        ev.timeMs = now;
    const QString key = alarmKey(ev);
    if (ev.requiresAck) {
        // A repeat of an active alarm updates it: one cause, one alarm (EEMUA 191 §A6: no floods of repeats).
        if (auto it = m_active.constFind(key); it != m_active.constEnd()) {
            const int row = it.value();
            Row& r = m_rows[row];
            ++r.occurrences;
            r.event.timeMs = ev.timeMs;
            r.event.text = ev.text;
            r.event.details = ev.details;
            r.event.itemCount = ev.itemCount;
            if (ev.severity > r.event.severity)
                r.event.severity = ev.severity;
            emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
            emit eventAdded(ev);
            return;
        }
    }
    const int row = int(m_rows.size());
    beginInsertRows({}, row, row);
    m_rows.push_back(Row{ev, !ev.requiresAck, 0, key, {}, 1, ev.timeMs});
    endInsertRows();
    if (ev.requiresAck) {
        m_active.insert(key, row);
        if (!m_shelves.contains(key)) {
            ++m_unacked;
            emit unacknowledgedCountChanged(m_unacked);
            m_annunciations.push_back(now);
            pruneRate(false);
            m_lastRate = int(m_annunciations.size());
            emit alarmRateChanged(m_lastRate, m_lastRate > kFloodThreshold);
            updateTimer();
        }
    }
    emit eventAdded(ev);
    trim();
}

void AlarmModel::restore(const QVector<RestoredRow>& rows) {
    beginResetModel();
    m_rows.clear();
    m_rows.reserve(rows.size());
    for (const RestoredRow& r : rows)
        m_rows.push_back(
            Row{r.event, r.acked, r.ackedMs, alarmKey(r.event), r.ackedBy, r.occurrences, r.firstMs});
    rebuildActive();
    endResetModel();
    recount();
}

void AlarmModel::trim() {
    if (m_maxEntries <= 0 || m_rows.size() <= m_maxEntries)
        return;
    // Drop the oldest acknowledged entries; never an unacknowledged alarm.
    int excess = int(m_rows.size()) - m_maxEntries;
    bool removed = false;
    for (int i = 0; i < m_rows.size() && excess > 0;) {
        if (m_rows[i].acked) {
            beginRemoveRows({}, i, i);
            m_rows.remove(i);
            endRemoveRows();
            --excess;
            removed = true;
        } else {
            ++i;
        }
    }
    if (removed)
        rebuildActive();
}

void AlarmModel::rebuildActive() {
    m_active.clear();
    for (int i = 0; i < m_rows.size(); ++i)
        if (!m_rows[i].acked)
            m_active.insert(m_rows[i].key, i);
}

void AlarmModel::recount() {
    int n = 0;
    for (const Row& r : std::as_const(m_rows))
        if (!r.acked && !m_shelves.contains(r.key))
            ++n;
    if (n != m_unacked) {
        m_unacked = n;
        emit unacknowledgedCountChanged(n);
    }
}

void AlarmModel::ackRow(int row, const QString& by, qint64 atMs, bool notify) {
    Row& r = m_rows[row];
    r.acked = true;
    r.ackedMs = atMs;
    r.ackedBy = by;
    if (m_active.value(r.key, -1) == row)
        m_active.remove(r.key);
    if (notify)
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

void AlarmModel::acknowledge(int row) {
    if (row < 0 || row >= m_rows.size() || m_rows[row].acked)
        return;
    const qint64 now = nowMs();
    const QString key = m_rows[row].key;
    ackRow(row, m_operator, now);
    recount();
    emit alarmAcknowledged(key, m_operator, now);
}

void AlarmModel::acknowledgeAll() {
    const qint64 now = nowMs();
    QStringList keys;
    for (int i = 0; i < m_rows.size(); ++i) {
        if (!m_rows[i].acked) {
            keys << m_rows[i].key;
            ackRow(i, m_operator, now, false);
        }
    }
    if (keys.isEmpty())
        return;
    emit dataChanged(index(0, 0),
                     index(int(m_rows.size()) - 1, ColumnCount - 1)); // one signal, not one per row
    recount();
    for (const QString& k : std::as_const(keys))
        emit alarmAcknowledged(k, m_operator, now);
}

bool AlarmModel::acknowledgeKey(const QString& key, const QString& by, qint64 atMs) {
    const auto it = m_active.constFind(key);
    if (it == m_active.constEnd())
        return false;
    const int row = it.value();
    // An acknowledgement covers what the operator saw: not an occurrence raised well after it.
    if (m_rows[row].firstMs > atMs + kAckSkewMs)
        return false;
    ackRow(row, by, atMs);
    recount();
    emit alarmAcknowledged(key, by, atMs);
    return true;
}

void AlarmModel::shelve(const QString& key, qint64 durationMs, const QString& reason) {
    if (key.isEmpty() || durationMs <= 0)
        return;
    const qint64 now = nowMs();
    const QString by =
        reason.isEmpty() ? m_operator : m_operator + QStringLiteral(" (") + reason + QLatin1Char(')');
    applyShelve(key, by, now, now + durationMs);
}

bool AlarmModel::applyShelve(const QString& key, const QString& by, qint64 atMs, qint64 untilMs) {
    if (key.isEmpty() || untilMs <= nowMs())
        return false;
    m_shelves.insert(key, Shelf{by, atMs, untilMs});
    recount();
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    updateTimer();
    emit alarmShelved(key, by, atMs, untilMs);
    return true;
}

bool AlarmModel::unshelve(const QString& key, const QString& by) {
    if (!m_shelves.remove(key))
        return false;
    recount();
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    updateTimer();
    emit alarmUnshelved(key, by.isEmpty() ? m_operator : by, nowMs());
    return true;
}

void AlarmModel::expireShelving() {
    const qint64 now = nowMs();
    QStringList expired;
    for (auto it = m_shelves.constBegin(); it != m_shelves.constEnd(); ++it)
        if (it->untilMs <= now)
            expired << it.key();
    for (const QString& k : std::as_const(expired))
        unshelve(k, QStringLiteral("expiry"));
}

void AlarmModel::pruneRate(bool notify) {
    const qint64 from = nowMs() - kRateWindowMs;
    while (!m_annunciations.empty() && m_annunciations.front() <= from)
        m_annunciations.pop_front();
    if (notify && int(m_annunciations.size()) != m_lastRate) {
        m_lastRate = int(m_annunciations.size());
        emit alarmRateChanged(m_lastRate, m_lastRate > kFloodThreshold);
    }
    if (notify)
        updateTimer();
}

int AlarmModel::alarmRate() const {
    const qint64 from = nowMs() - kRateWindowMs;
    int n = 0;
    for (auto it = m_annunciations.rbegin(); it != m_annunciations.rend() && *it > from; ++it)
        ++n;
    return n;
}

void AlarmModel::updateTimer() {
    const bool need = !m_shelves.isEmpty() || !m_annunciations.empty();
    if (need && !m_timer->isActive())
        m_timer->start();
    else if (!need && m_timer->isActive())
        m_timer->stop();
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

void AlarmFilterProxy::setShowShelved(bool on) {
    m_showShelved = on;
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
    if (!m_showShelved && e.requiresAck && alarms->isShelved(sourceRow))
        return false;
    if (m_text.isEmpty())
        return true;
    return e.text.contains(m_text, Qt::CaseInsensitive) ||
           e.machineId.contains(m_text, Qt::CaseInsensitive) ||
           toText(e.kind).contains(m_text, Qt::CaseInsensitive) ||
           DisplayText::kind(e.kind).contains(m_text, Qt::CaseInsensitive) ||
           e.source.contains(m_text, Qt::CaseInsensitive) ||
           e.details.filter(m_text, Qt::CaseInsensitive).size() > 0;
}

} // namespace ocu
