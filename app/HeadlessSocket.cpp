#include "app/HeadlessSocket.h"

#include "app/HeadlessMonitor.h"

#include <QCoreApplication>
#include <QFile>
#include <QLocalServer>
#include <QLocalSocket>

#include <sys/stat.h>

namespace ocu {

namespace {
constexpr int kMaxLine = 1 << 20; // as on stdin: a runaway line without newline is dropped
}

HeadlessCommandSocket::HeadlessCommandSocket(HeadlessMonitor* monitor, QObject* parent)
    : QObject(parent), m_monitor(monitor), m_server(new QLocalServer(this)) {
    connect(m_server, &QLocalServer::newConnection, this, &HeadlessCommandSocket::onNewConnection);
}

HeadlessCommandSocket::~HeadlessCommandSocket() {
    m_server->close(); // removes the socket file
}

bool HeadlessCommandSocket::listen(const QString& path, QString& error) {
    if (QFile::exists(path)) {
        QLocalSocket probe;
        probe.connectToServer(path);
        if (probe.waitForConnected(500)) {
            error =
                QCoreApplication::translate("HeadlessSocket", "%1: another console answers on this command "
                                                              "socket")
                    .arg(path);
            return false;
        }
        QLocalServer::removeServer(path); // left by a run that ended without closing it
    }
    // Owner and group read and write: 0660 (the group is the service's, docs/packaging.md).
    m_server->setSocketOptions(QLocalServer::UserAccessOption | QLocalServer::GroupAccessOption);
    if (!m_server->listen(path)) {
        error = QCoreApplication::translate("HeadlessSocket", "%1: cannot open the command socket: %2")
                    .arg(path, m_server->errorString());
        return false;
    }
    // Qt sets the mode from the options; made exact here, whatever the umask left.
    if (::chmod(QFile::encodeName(path).constData(), 0660) != 0) {
        error = QCoreApplication::translate("HeadlessSocket", "%1: cannot set the command socket's mode")
                    .arg(path);
        m_server->close();
        return false;
    }
    m_path = path;
    return true;
}

void HeadlessCommandSocket::onNewConnection() {
    while (QLocalSocket* client = m_server->nextPendingConnection()) {
        m_buffers.insert(client, {});
        m_monitor->addOutput(client);
        connect(client, &QLocalSocket::readyRead, this, [this, client] { onReadyRead(client); });
        connect(client, &QLocalSocket::disconnected, this, [this, client] {
            m_monitor->removeOutput(client);
            m_buffers.remove(client);
            client->deleteLater();
        });
    }
}

void HeadlessCommandSocket::onReadyRead(QLocalSocket* client) {
    QByteArray& buf = m_buffers[client];
    buf += client->readAll();
    qsizetype nl;
    while ((nl = buf.indexOf('\n')) >= 0) {
        const QByteArray line = buf.left(nl);
        buf.remove(0, nl + 1);
        m_monitor->handleLine(line);
    }
    if (buf.size() > kMaxLine) {
        buf.clear();
        m_monitor->commands().refuse({}, QStringLiteral("input line too long (over 1 MiB), dropped"));
    }
}

} // namespace ocu
