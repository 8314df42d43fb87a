#include "models/jaus/JausSubsystemModel.h"

#include "models/ControlRoomModel.h"
#include "models/DisplayText.h"

#include <QBrush>
#include <QColor>
#include <QTimer>

namespace ocu {

JausSubsystemModel::JausSubsystemModel(JausVehicleBridge* bridge, QObject* parent)
    : QAbstractTableModel(parent), m_bridge(bridge), m_ownId(bridge->identity().ownId) {
    for (std::uint16_t id : bridge->subsystems())
        if (auto s = bridge->subsystem(id))
            m_rows.push_back(*s);
    connect(bridge, &JausVehicleBridge::subsystemUpdated, this, &JausSubsystemModel::onVehicle);
    // Data ages change with time even without messages.
    auto* t = new QTimer(this);
    connect(t, &QTimer::timeout, this, [this] {
        if (!m_rows.isEmpty())
            emit dataChanged(index(0, Link), index(rowCount() - 1, Link), {Qt::DisplayRole});
    });
    t->start(1000);
}

int JausSubsystemModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}
int JausSubsystemModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

std::uint16_t JausSubsystemModel::subsystemAt(int row) const {
    return row >= 0 && row < m_rows.size() ? m_rows[row].subsystem : 0;
}

const JausVehicle* JausSubsystemModel::vehicleAt(int row) const {
    return row >= 0 && row < m_rows.size() ? &m_rows[row] : nullptr;
}

int JausSubsystemModel::rowOf(std::uint16_t subsystem) const {
    for (int i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].subsystem == subsystem)
            return i;
    return -1;
}

void JausSubsystemModel::onVehicle(const JausVehicle& s) {
    const int row = rowOf(s.subsystem);
    if (row >= 0) {
        // Only the cells that show something new: a pose report changes no cell here, and each
        // dataChanged makes the table re-measure every row for its ResizeToContents columns.
        const JausVehicle& o = m_rows[row];
        const bool colour = rowColour(o) != rowColour(s);
        bool changed[ColumnCount] = {};
        changed[Vehicle] = o.callSign != s.callSign;
        changed[Link] = o.linkText != s.linkText || o.link != s.link ||
                        (o.lastMessageUnixMs > 0) != (s.lastMessageUnixMs > 0);
        changed[Access] = o.access != s.access;
        changed[Controller] = o.controlledByUs != s.controlledByUs || !(o.controller == s.controller) ||
                              o.controllerAuthority != s.controllerAuthority;
        changed[Management] = o.management != s.management || o.managementText != s.managementText ||
                              o.emergency != s.emergency;
        changed[Health] = o.health.has_value() != s.health.has_value() ||
                          (o.health && s.health && o.health->severity != s.health->severity);
        // The row's buttons (JausControlPanel::refreshButtons) follow the link, control and mobility
        // component.
        changed[Actions] = o.link != s.link || o.controlledByUs != s.controlledByUs ||
                           !(o.mobilityComponent == s.mobilityComponent);
        m_rows[row] = s;
        int first = colour ? 0 : -1, last = colour ? ColumnCount - 1 : -1;
        for (int c = 0; c < ColumnCount && !colour; ++c)
            if (changed[c]) {
                first = first < 0 ? c : first;
                last = c;
            }
        if (first >= 0)
            emit dataChanged(index(row, first), index(row, last));
        return;
    }
    int at = 0;
    while (at < m_rows.size() && m_rows[at].subsystem < s.subsystem)
        ++at;
    beginInsertRows({}, at, at);
    m_rows.insert(at, s);
    endInsertRows();
}

QString JausSubsystemModel::linkText(JausLink s) {
    return DisplayText::link(s == JausLink::Up         ? LinkState::Up
                             : s == JausLink::Degraded ? LinkState::Degraded
                                                       : LinkState::Down);
}

QString JausSubsystemModel::accessText(JausAccess s) {
    // The vocabulary operators know from the FKIE IOP panels.
    switch (s) {
    case JausAccess::NotAvailable:
        return QStringLiteral("NOT_AVAILABLE");
    case JausAccess::NotControlled:
        return QStringLiteral("NOT_CONTROLLED");
    case JausAccess::Monitoring:
        return QStringLiteral("MONITORING");
    case JausAccess::ControlAccepted:
        return QStringLiteral("CONTROL_ACCEPTED");
    case JausAccess::ControlReleased:
        return QStringLiteral("CONTROL_RELEASED");
    case JausAccess::Timeout:
        return QStringLiteral("TIMEOUT");
    case JausAccess::InsufficientAuthority:
        return QStringLiteral("INSUFFICIENT_AUTHORITY");
    case JausAccess::Preempted:
        return QStringLiteral("PREEMPTED");
    }
    return {};
}

JausSubsystemModel::RowColour JausSubsystemModel::rowColour(const JausVehicle& s) const {
    if (s.controlledByUs) {
        // Standby and Ready are normal while controlled; anything else needs the operator's attention.
        const bool normalState = !s.management || *s.management == JausManagement::Ready ||
                                 *s.management == JausManagement::Standby;
        const bool warn =
            s.emergency || s.link != JausLink::Up || (s.health && s.health->severity >= 2) || !normalState;
        return warn ? RowColour::OursWarning : RowColour::OursOk;
    }
    // Our own ID in a report after we released is a stale report, not another console.
    if (s.controller.subsystem != 0 && !(s.controller == m_ownId))
        return RowColour::Other;
    return RowColour::None;
}

QVariant JausSubsystemModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const JausVehicle& s = m_rows[index.row()];
    if (role == SubsystemRole)
        return s.subsystem;
    if (role == AccessStateRole)
        return static_cast<int>(s.access);
    if (role == RowColourRole)
        return static_cast<int>(rowColour(s));
    if (role == Qt::BackgroundRole) {
        switch (rowColour(s)) {
        case RowColour::OursOk:
            return QBrush(QColor(150, 215, 150));
        case RowColour::OursWarning:
            return QBrush(QColor(245, 185, 100));
        case RowColour::Other:
            return QBrush(QColor(180, 180, 180));
        case RowColour::None:
            return {};
        }
    }
    if (role == Qt::ForegroundRole && rowColour(s) != RowColour::None)
        return QBrush(Qt::black);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case Vehicle:
        return QStringLiteral("%1 [%2]")
            .arg(s.callSign.isEmpty() ? tr("unnamed") : s.callSign)
            .arg(s.subsystem);
    case Link: {
        const QString state = linkText(s.link);
        if (s.lastMessageUnixMs <= 0)
            return state;
        const qint64 age = std::max<qint64>(0, m_clock->nowMs() - s.lastMessageUnixMs);
        return tr("%1 · %2 s").arg(state).arg(age / 1000.0, 0, 'f', 1);
    }
    case Access:
        return accessText(s.access);
    case Controller:
        return controllerText(s, role == Qt::ToolTipRole);
    case Management: {
        QString t = s.management ? s.managementText : tr("unknown");
        if (s.emergency)
            t += tr(" · EMERGENCY");
        return t;
    }
    case Health: {
        if (!s.health)
            return tr("unknown");
        static const char* names[] = {"NONE", "INFO", "WARNING", "ERROR", "FAILURE"};
        return QString::fromLatin1(names[std::min<int>(s.health->severity, 4)]);
    }
    default:
        return {};
    }
}

void JausSubsystemModel::setControlRoom(ControlRoomModel* room) {
    if (m_room)
        disconnect(m_room, nullptr, this, nullptr);
    m_room = room;
    if (room)
        connect(room, &ControlRoomModel::roomChanged, this, [this] {
            if (!m_rows.isEmpty())
                emit dataChanged(index(0, Controller), index(rowCount() - 1, Controller));
        });
}

QString JausSubsystemModel::roomAddress(const JausAddress& a) {
    return QStringLiteral("jaus:%1.%2.%3").arg(a.subsystem).arg(a.node).arg(a.component);
}

QString JausSubsystemModel::controllerText(const JausVehicle& s, bool tooltip) const {
    if (s.controlledByUs)
        return tr("this console (%1)").arg(s.controllerAuthority);
    if (s.controller.subsystem == 0 || s.controller == m_ownId)
        return tr("nobody");
    const QString id = tr("%1.%2.%3 (%4)")
                           .arg(s.controller.subsystem)
                           .arg(s.controller.node)
                           .arg(s.controller.component)
                           .arg(s.controllerAuthority);
    // Another console of the room: its person and name; the JAUS ID stays in the tooltip.
    const auto console = m_room ? m_room->consoleControllingWith(roomAddress(s.controller)) : std::nullopt;
    if (!console)
        return id;
    const QString person = tr("%1 (%2)", "operator at console (JAUS authority)")
                               .arg(ControlRoomModel::personAtConsole(*console))
                               .arg(s.controllerAuthority);
    return tooltip ? tr("%1, JAUS %2", "operator at console, JAUS ID of its component").arg(person, id)
                   : person;
}

QVariant JausSubsystemModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Vehicle:
        return tr("Vehicle [ID]");
    case Link:
        return tr("Link");
    case Access:
        return tr("Access");
    case Controller:
        return tr("Controlled by");
    case Management:
        return tr("Management");
    case Health:
        return tr("Health");
    case Actions:
        return tr("Actions");
    }
    return {};
}

} // namespace ocu
