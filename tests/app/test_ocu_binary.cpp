// Runs the real `ocu` executable the way a user or a script does.
#include "tests/support/BuiltProtocols.h"

#include <QElapsedTimer>
#include <QImage>
#include <QLocalSocket>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

class TestOcuBinary : public QObject {
    Q_OBJECT

    struct Run {
        int exitCode = -1;
        QString out, err;
    };
    Run run(const QStringList& args, int timeoutMs = 60000) {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY"); // headless: no X server at all
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("XDG_CONFIG_HOME", m_dir.path()); // never touch the user's saved layout
        env.insert("XDG_CACHE_HOME", m_dir.path());  // the map tile cache too
        p.setProcessEnvironment(env);
        p.start(OCU_BINARY, args);
        Run r;
        if (!p.waitForFinished(timeoutMs)) {
            p.kill();
            p.waitForFinished();
            r.err = "timed out";
            return r;
        }
        r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
        r.out = QString::fromUtf8(p.readAllStandardOutput());
        r.err = QString::fromUtf8(p.readAllStandardError());
        return r;
    }
    QString writeFile(const QString& name, const QByteArray& text) {
        QString path = m_dir.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return path;
    }
    QTemporaryDir m_dir;

private slots:
    void help() {
        Run r = run({"--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--screenshot"));
        QVERIFY(r.out.contains("--headless"));
    }
    // The version from the repository (git describe at configure time), the one the package carries.
    void version() {
        const Run r = run({"--version"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.trimmed(), QString("ocu " OCU_EXPECTED_VERSION));
        QVERIFY2(QRegularExpression("^\\d+\\.\\d+\\.\\d+").match(OCU_EXPECTED_VERSION).hasMatch(),
                 OCU_EXPECTED_VERSION);
    }
    // --check-config: file:line errors and exit 1 for a bad file, exit 0 for a good one; nothing starts (no
    // window, no stacks: it returns at once even without --duration).
    void checkConfig() {
        const QString bad = writeFile("bad.json", "{\n  \"site\": {\n    \"origin\": {\"latitude\": 48, "
                                                  "\"longitude\": 11},\n    \"nmae\": \"Quarry\"\n  }\n}\n");
        QElapsedTimer t;
        t.start();
        Run r = run({"--check-config", bad}, 20000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(bad + ":4: site.nmae: unknown key"), qPrintable(r.err));
        const QString good = OCU_SOURCE_DIR "/resources/sites/simulated-site.json";
        r = run({"--check-config", good}, 20000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(good + ": the site configuration is valid"), qPrintable(r.out));
        r = run({"--check-config", m_dir.filePath("missing.json")}, 20000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("cannot open"), qPrintable(r.err));
        QVERIFY2(t.elapsed() < 15000, qPrintable(QString::number(t.elapsed())));
    }
    // As the service runs it: stdin at its end (/dev/null), commands on the socket; `list` answered there,
    // and SIGTERM ends it within 2 s, the socket file gone.
    void commandSocketAsAService() {
        const QString sock = m_dir.filePath("ocu.sock");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.insert("XDG_CONFIG_HOME", m_dir.path());
        env.insert("XDG_CACHE_HOME", m_dir.path());
        p.setProcessEnvironment(env);
        p.setStandardInputFile(QProcess::nullDevice());
        p.start(OCU_BINARY, {"--headless", "--no-record", "--command-socket", sock});
        QVERIFY(p.waitForStarted());
        QLocalSocket client;
        QElapsedTimer t;
        t.start();
        while (client.state() != QLocalSocket::ConnectedState && t.elapsed() < 30000) {
            client.connectToServer(sock);
            if (!client.waitForConnected(200))
                QTest::qWait(200);
        }
        QVERIFY2(client.state() == QLocalSocket::ConnectedState, qPrintable(p.readAllStandardError()));
        QCOMPARE(p.state(), QProcess::Running); // the end of stdin did not end it
        client.write("{\"cmd\":\"list\",\"req\":42}\n");
        QByteArray got;
        t.restart();
        while (!got.contains("\"req\":42") && t.elapsed() < 10000)
            if (client.waitForReadyRead(200))
                got += client.readAll();
        const QByteArray line =
            got.mid(got.lastIndexOf('\n', got.indexOf("\"req\":42")) + 1).split('\n').first();
        QVERIFY2(line.contains("\"type\":\"result\"") && line.contains("\"ok\":true"), line.constData());
        t.restart();
        p.terminate(); // SIGTERM, as systemctl stop sends it
        QVERIFY(p.waitForFinished(5000));
        QVERIFY2(t.elapsed() < 2000, qPrintable(QString::number(t.elapsed())));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(!QFile::exists(sock));
    }
    void misspelledKeyIsRefused() {
        QString path = writeFile("typo.json",
                                 "{\n  \"site\": {\n    \"origin\": {\"latitude\": 48, \"longitude\": 11},\n"
                                 "    \"nmae\": \"Quarry\"\n  }\n}\n");
        Run r = run({"--config", path, "--screenshot", m_dir.filePath("never.png"), "--settle", "0"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(path + ":4: site.nmae: unknown key \"nmae\" (did you mean \"name\"?)"),
                 qPrintable(r.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")));
    }
    void latitudeOutOfRangeIsRefused() {
        QString path = writeFile("lat.json", "{\n  \"site\": {\n    \"origin\": {\n      \"latitude\": 123,\n"
                                             "      \"longitude\": 11\n    }\n  }\n}\n");
        Run r = run({"--config", path, "--headless", "--duration", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(path + ":4: site.origin.latitude: 123 is out of range [-90, 90]"),
                 qPrintable(r.err));
    }
    void headlessScreenshotOfWholeWindow() {
        const QString png = m_dir.filePath("all.png");
        Run r = run({"--screenshot", png, "--view", "all", "--size", "1280x800", "--settle", "1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QImage img(png);
        QVERIFY(!img.isNull());
        QCOMPARE(img.size(), QSize(1280, 800));
        // Not blank: many distinct colours, and the red STOP ALL button in the top-left corner.
        QSet<QRgb> colours;
        int red = 0;
        for (int y = 0; y < img.height(); y += 2)
            for (int x = 0; x < img.width(); x += 2) {
                QRgb c = img.pixel(x, y);
                colours.insert(c);
                if (y < 80 && x < 250 && qRed(c) > 180 && qGreen(c) < 60 && qBlue(c) < 60)
                    ++red;
            }
        QVERIFY2(colours.size() > 20, qPrintable(QString::number(colours.size())));
        QVERIFY2(red > 200, qPrintable(QString::number(red)));
    }
    void headlessScreenshotOfEachPanel() {
        // No settling time: the screenshot itself waits for the panel's first paint (and for the 3D view's
        // first frame, a video view's first frame), which is what makes a panel's screenshot.
        QStringList views{"fleet", "map", "3d", "events"};
        if (ocutest::kWithOsyris) // the OSYRIS module's panel
            views << "passcounts";
        if (ocutest::kWithJaus) // the JAUS module's panels
            views << "jaus"
                  << "teleop"
                  << "video";
        for (const QString& view : views) {
            const QString png = m_dir.filePath(QString("%1.png").arg(view));
            Run r = run({"--screenshot", png, "--view", view, "--settle", "0"});
            QVERIFY2(r.exitCode == 0, qPrintable(view + ": " + r.err));
            QImage img(png);
            QVERIFY2(!img.isNull() && img.width() > 100 && img.height() > 100, qPrintable(view));
        }
    }
    // The shift report from the command line, written when a headless run ends (the built-in
    // site), and said so on stderr; the CSV has its header and the shift row.
    void headlessShiftReportFromTheCommandLine() {
        const QString pdf = m_dir.filePath("shift.pdf"), csv = m_dir.filePath("shift.csv");
        // A second of site is a shift like any other: the report is written when the run ends.
        const Run r =
            run({"--headless", "--duration", "1", "--shift-report", pdf, "--shift-csv", csv}, 120000);
        QCOMPARE(r.exitCode, 0);
        if (ocutest::kWithIso23725) {
            QVERIFY2(r.err.contains("shift report written"), qPrintable(r.err.right(2000)));
            QVERIFY(QFileInfo(pdf).size() > 1000);
            QFile f(csv);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(f.readAll());
            QVERIFY(text.contains("section,key,name,loads,tonnes"));
            QVERIFY(text.contains("\nshift,shift,"));
        } else { // production comes from the ISO 23725 links: none here, and it says so
            QVERIFY2(r.err.contains("no production model"), qPrintable(r.err.right(2000)));
            QVERIFY(!QFileInfo::exists(pdf) && !QFileInfo::exists(csv));
        }
        // Without --headless it is refused with the reason.
        const Run bad = run({"--shift-report", pdf});
        QVERIFY(bad.exitCode != 0);
        QVERIFY2(bad.err.contains("--headless"), qPrintable(bad.err));
    }

    void noQt5Linked() {
        QProcess p;
        p.start("ldd", {OCU_BINARY});
        QVERIFY(p.waitForFinished(30000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY(out.contains("libQt6Widgets"));
        QVERIFY2(!out.contains("libQt5"), qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestOcuBinary)
#include "test_ocu_binary.moc"
