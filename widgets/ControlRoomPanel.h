#pragma once
// The "Control room" panel: who is at which console of the control room (console, operator, role, since when,
// signed in, locked, or not seen since a time), read from the shared history. Long names elide (the tooltip
// has them whole); the table never scrolls sideways. A line above it says when the history is out of reach
// and the table shows the room as last seen.
#include <QWidget>

class QLabel;
class QTableView;

namespace ocu {

class ControlRoomModel;

class ControlRoomPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlRoomPanel(ControlRoomModel* room, QWidget* parent = nullptr);

    QTableView* table() const { return m_table; }
    QLabel* notice() const { return m_notice; }
    // The history's connection: while it is away, the notice says the room is as last seen.
    void setConnected(bool connected, const QString& detail = {});

private:
    QTableView* m_table;
    QLabel* m_notice;
};

} // namespace ocu
