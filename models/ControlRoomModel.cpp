#include "models/ControlRoomModel.h"

#include "models/commands/CommandPermissions.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>
#include <QFont>

namespace ocu {

namespace {

QString roleText(const QString& key) {
    const auto role = roleFromName(key.toStdString());
    return role ? roleDisplayName(*role) : key;
}

// Today's times as a time of day, older ones with their date.
QString whenText(qint64 ms) {
    const QDateTime t = QDateTime::fromMSecsSinceEpoch(ms);
    return t.date() == QDate::currentDate() ? t.toString(QStringLiteral("HH:mm"))
                                            : t.toString(QStringLiteral("yyyy-MM-dd HH:mm"));
}

} // namespace

ControlRoomModel::ControlRoomModel(QObject* parent) : QAbstractTableModel(parent) {
    qRegisterMetaType<ocu::ConsolePresence>();
}

int ControlRoomModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_room.size());
}

int ControlRoomModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

void ControlRoomModel::setRoom(const QVector<ConsolePresence>& room) {
    if (room == m_room)
        return;
    beginResetModel();
    m_room = room;
    endResetModel();
    emit roomChanged();
}

void ControlRoomModel::setThisConsole(const QString& console) {
    m_thisConsole = console;
    if (!m_room.isEmpty())
        emit dataChanged(index(0, Console), index(rowCount() - 1, Console));
}

std::optional<ConsolePresence> ControlRoomModel::consoleControllingWith(const QString& address) const {
    for (const ConsolePresence& p : m_room)
        if (p.controllerAddresses.contains(address))
            return p;
    return std::nullopt;
}

QString ControlRoomModel::personAtConsole(const ConsolePresence& p) {
    return tr("%1 at %2").arg(p.operatorName, p.console);
}

QString ControlRoomModel::stateText(const ConsolePresence& p) {
    if (p.stale)
        return tr("not seen since %1").arg(whenText(p.heartbeatMs));
    return p.locked ? tr("locked") : tr("signed in");
}

QVariant ControlRoomModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_room.size())
        return {};
    const ConsolePresence& p = m_room[index.row()];
    const bool mine = p.console == m_thisConsole;
    if (role == Qt::FontRole && mine) {
        QFont f;
        f.setBold(true);
        return f;
    }
    if (role == Qt::ForegroundRole && p.stale)
        return QBrush(QColor(120, 120, 120));
    if (role == Qt::ToolTipRole && index.column() == State) {
        QString tip = stateText(p);
        if (!p.controllerAddresses.isEmpty())
            tip += QLatin1Char('\n') +
                   tr("controls machines as %1").arg(p.controllerAddresses.join(QStringLiteral(", ")));
        return tip;
    }
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case Console: // this console's row is bold; the tooltip says why
        return mine && role == Qt::ToolTipRole ? tr("%1 (this console)").arg(p.console) : p.console;
    case Operator:
        return p.operatorName;
    case Role:
        return roleText(p.role);
    case Since:
        return p.sinceMs > 0 ? whenText(p.sinceMs) : QString();
    case State:
        return stateText(p);
    default:
        return {};
    }
}

QVariant ControlRoomModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Console:
        return tr("Console");
    case Operator:
        return tr("Operator");
    case Role:
        return tr("Role");
    case Since:
        return tr("Since");
    case State:
        return tr("State");
    }
    return {};
}

} // namespace ocu
