#pragma once
// The headless console's command socket: a local (UNIX domain) stream socket carrying the same JSON lines
// as stdin, for a console that runs as a service with no terminal (the systemd unit ocu-monitor@.service,
// docs/packaging.md). Each line a client sends is one command for the monitor's command table
// (HeadlessMonitor::handleLine: no second parser); each client receives every line the monitor writes from
// its connection on (machines, links, events and the result lines, whose "req" tells a client its own).
// The socket file is mode 0660: its owner and the members of its group (the service's group) may command.
#include <QByteArray>
#include <QHash>
#include <QObject>
#include <QString>

class QLocalServer;
class QLocalSocket;

namespace ocu {

class HeadlessMonitor;

class HeadlessCommandSocket : public QObject {
    Q_OBJECT
public:
    explicit HeadlessCommandSocket(HeadlessMonitor* monitor, QObject* parent = nullptr);
    ~HeadlessCommandSocket() override;

    // Listens on path (a left-over socket file of an ended run is replaced; one a running console still
    // answers on is not). False with the reason in error.
    bool listen(const QString& path, QString& error);
    QString path() const { return m_path; }
    int clientCount() const { return int(m_buffers.size()); }

private:
    void onNewConnection();
    void onReadyRead(QLocalSocket* client);

    HeadlessMonitor* m_monitor;
    QLocalServer* m_server;
    QString m_path;
    QHash<QLocalSocket*, QByteArray> m_buffers; // each client's unfinished line
};

} // namespace ocu
