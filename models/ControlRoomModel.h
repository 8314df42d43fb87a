#pragma once
// Who is where across the control room: the presence each console publishes into the shared history
// (operator, role, since when, locked, the addresses its stacks control machines with), as this console last
// read it. The control-room panel shows it; a table that names a machine's controller by its protocol address
// asks consoleControllingWith() to name the person and the console instead (docs/recording.md, "Who is
// where").
#include <QAbstractTableModel>
#include <QMetaType>
#include <QStringList>
#include <QVector>

#include <optional>

namespace ocu {

struct ConsolePresence {
    QString console;
    QString operatorName;
    QString role;       // the role's key ("dispatcher", "ugv_operator")
    qint64 sinceMs = 0; // when this operator signed in (the console's clock)
    bool locked = false;
    // "<protocol>:<address>" the console's stacks control machines with, e.g. "jaus:3.1.1".
    QStringList controllerAddresses;
    qint64 heartbeatMs = 0; // the last heartbeat (the database's clock)
    bool stale = false;     // no heartbeat for longer than the stale timeout: crashed or cut off
    bool operator==(const ConsolePresence&) const = default;
};

class ControlRoomModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Console, Operator, Role, Since, State, ColumnCount };

    explicit ControlRoomModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    // The room as read (ordered by console); this console's own row is marked.
    void setRoom(const QVector<ConsolePresence>& room);
    const QVector<ConsolePresence>& room() const { return m_room; }
    void setThisConsole(const QString& console);
    // The console whose stacks control with `address` ("jaus:3.1.1"), if one in the room does.
    std::optional<ConsolePresence> consoleControllingWith(const QString& address) const;
    // "alice at dispatch-1": a controller named for people.
    static QString personAtConsole(const ConsolePresence& p);
    // The row's state in words: "signed in", "locked", "not seen since 14:02".
    static QString stateText(const ConsolePresence& p);

signals:
    void roomChanged();

private:
    QVector<ConsolePresence> m_room;
    QString m_thisConsole;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::ConsolePresence)
