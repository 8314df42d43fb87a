// Fuzz harness: headless command lines (app/HeadlessMonitor, `ocu --headless`: one JSON command a line on
// stdin) over the real Qt models, command gate and three fake bridges with a machine each. Invariants: every
// line the monitor writes is one JSON object; every answer handleLine returns at once is a result line.
#include "app/HeadlessMonitor.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/testing/FakeFleetBridge.h"
#include "tests/fuzz/FuzzSupport.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

using namespace ocu;

namespace {

MachineState machine(const QString& id, double e) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = QStringLiteral("M-") + id;
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.lat = 48.1;
    m.lon = 11.5;
    m.stop = StopState::None;
    return m;
}

bool isJsonObject(const QByteArray& line) {
    QJsonParseError err{};
    QJsonDocument d = QJsonDocument::fromJson(line, &err);
    return err.error == QJsonParseError::NoError && d.isObject();
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    static int qtArgc = 1;
    static char* qtArgv[] = {(*argv)[0], nullptr};
    (void)argc;
    new QCoreApplication(qtArgc, qtArgv); // lives for the whole run
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    HeadlessMonitor monitor{&fleet, &alarms, &gate};
    FakeFleetBridge jaus{Protocol::Jaus}, iso{Protocol::Iso23725}, osy{Protocol::Osyris};
    QBuffer out;
    out.open(QIODevice::ReadWrite);
    monitor.setOutput(&out);
    monitor.setRateLimitMs(0);
    for (const char* name : {"request_control", "release_control", "drive"})
        monitor.commands().addGateCommand(QLatin1String(name));
    fleet.setRefreshIntervalMs(0);
    for (FakeFleetBridge* b : {&jaus, &iso, &osy}) {
        fleet.addBridge(b);
        alarms.addBridge(b);
        gate.addBridge(b);
        monitor.addBridge(b);
    }
    jaus.setMachine(machine(QStringLiteral("jaus:126"), 1));
    iso.setMachine(machine(QStringLiteral("iso23725:ahs/c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78"), 2));
    osy.setMachine(machine(QStringLiteral("osyris:7"), 3));
    QCoreApplication::processEvents();

    fuzz::Lines lines(data, size);
    std::string_view line;
    for (int n = 0; n < 64 && lines.next(line); ++n) {
        QByteArray answer = monitor.handleLine(QByteArray(line.data(), qsizetype(line.size())));
        if (!answer.isEmpty()) {
            OCU_FUZZ_CHECK(isJsonObject(answer));
            OCU_FUZZ_CHECK(QJsonDocument::fromJson(answer).object().value(QStringLiteral("type")) ==
                           QStringLiteral("result"));
        }
        QCoreApplication::processEvents();
    }
    for (const QByteArray& l : out.data().split('\n'))
        if (!l.trimmed().isEmpty())
            OCU_FUZZ_CHECK(isJsonObject(l));
    return 0;
}
