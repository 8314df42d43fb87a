// The headless console's command socket: a client's JSON line answered through the socket by the monitor's
// command table, the socket file mode 0660, a left-over socket file replaced, a live one not taken over.
#include "app/HeadlessMonitor.h"
#include "app/HeadlessSocket.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/testing/FakeFleetBridge.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocalSocket>
#include <QTemporaryDir>
#include <QTest>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace ocu;

namespace {

struct Rig {
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    HeadlessMonitor monitor{&fleet, &alarms, &gate};
    FakeFleetBridge jaus{Protocol::Jaus};
    QBuffer out;
    Rig() {
        fleet.setRefreshIntervalMs(0);
        out.open(QIODevice::ReadWrite);
        monitor.setOutput(&out);
        fleet.addBridge(&jaus);
        alarms.addBridge(&jaus);
        gate.addBridge(&jaus);
        monitor.addBridge(&jaus);
        MachineState m;
        m.id = QStringLiteral("jaus:101");
        m.protocol = Protocol::Jaus;
        m.name = QStringLiteral("UGV 101");
        m.link = LinkState::Up;
        jaus.setMachine(m);
        QCoreApplication::processEvents();
    }
};

// Reads lines from the client until one is the result with this "req" (or the time is up).
QJsonObject resultFor(QLocalSocket& client, int req, int timeoutMs = 5000) {
    QElapsedTimer t;
    t.start();
    QByteArray buf;
    while (t.elapsed() < timeoutMs) {
        client.waitForReadyRead(100);
        QCoreApplication::processEvents();
        buf += client.readAll();
        qsizetype nl;
        while ((nl = buf.indexOf('\n')) >= 0) {
            const QJsonObject o = QJsonDocument::fromJson(buf.left(nl)).object();
            buf.remove(0, nl + 1);
            if (o.value("type").toString() == "result" && o.value("req").toInt() == req)
                return o;
        }
    }
    return {};
}

} // namespace

class TestHeadlessSocket : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void listAnsweredThroughTheSocket() {
        Rig rig;
        HeadlessCommandSocket socket(&rig.monitor);
        const QString path = m_dir.filePath("list.sock");
        QString error;
        QVERIFY2(socket.listen(path, error), qPrintable(error));
        // Only the owner and the group may connect (and so command).
        struct stat st {};
        QCOMPARE(::stat(QFile::encodeName(path).constData(), &st), 0);
        QVERIFY(S_ISSOCK(st.st_mode));
        QCOMPARE(st.st_mode & 07777, mode_t(0660));

        QLocalSocket client;
        client.connectToServer(path);
        QVERIFY(client.waitForConnected(2000));
        QTRY_COMPARE(socket.clientCount(), 1);
        client.write("{\"cmd\":\"list\",\"req\":7}\n");
        client.flush();
        const QJsonObject r = resultFor(client, 7);
        QVERIFY2(!r.isEmpty(), "no result line for req 7 on the socket");
        QCOMPARE(r.value("cmd").toString(), QString("list"));
        QVERIFY(r.value("ok").toBool());
        // The same answer the stdout stream has: the one command table.
        QVERIFY(rig.out.data().contains("\"req\":7"));
        // A line that is not JSON is refused on the socket too, and the connection stays usable.
        client.write("not json\n{\"cmd\":\"list\",\"req\":8}\n");
        client.flush();
        QVERIFY(!resultFor(client, 8).isEmpty());
        client.disconnectFromServer();
        QTRY_COMPARE(socket.clientCount(), 0);
    }
    void leftOverSocketFileIsReplaced() {
        const QString path = m_dir.filePath("stale.sock");
        // A socket file nobody listens on any more, as a killed run leaves it.
        const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        const QByteArray p = QFile::encodeName(path);
        std::memcpy(addr.sun_path, p.constData(), size_t(p.size()) + 1);
        QCOMPARE(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
        ::close(fd);
        QVERIFY(QFile::exists(path));
        Rig rig;
        HeadlessCommandSocket socket(&rig.monitor);
        QString error;
        QVERIFY2(socket.listen(path, error), qPrintable(error));
        // A second console on the same path is refused: the first one still answers there.
        HeadlessCommandSocket second(&rig.monitor);
        QVERIFY(!second.listen(path, error));
        QVERIFY2(error.contains("another console"), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestHeadlessSocket)
#include "test_headless_socket.moc"
