// Runs the real `ocu` executable the way a user or a script does.
#include "tests/support/BuiltProtocols.h"

#include <QImage>
#include <QProcess>
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
        QStringList views{"fleet", "map", "3d", "passcounts", "events"};
        if (ocutest::kWithJaus) // the JAUS module's panels
            views << "jaus"
                  << "teleop";
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
