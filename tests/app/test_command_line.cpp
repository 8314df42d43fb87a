#include "app/CommandLine.h"
#include "app/MainWindow.h"
#include "app/ProtocolModule.h"
#include "app/SiteRuntime.h"

#include <QtTest>

using namespace ocu;

class TestCommandLine : public QObject {
    Q_OBJECT
    bool parse(const QStringList& args, CommandLineOptions& o, QString& error) {
        QString help;
        return parseCommandLine(QStringList{QStringLiteral("ocu")} + args, o, error, help);
    }
private slots:
    void defaults() {
        CommandLineOptions o;
        QString e;
        QVERIFY(parse({}, o, e));
        QVERIFY(o.configFile.isEmpty()); // built-in simulated site
        QCOMPARE(o.view, QString("all"));
        QCOMPARE(o.size, QSize(1600, 1000));
        QCOMPARE(o.settleSeconds, 3.0);
        QVERIFY(!o.headless);
        QVERIFY(!o.noSim);
    }
    void everyOption() {
        CommandLineOptions o;
        QString e;
        QVERIFY2(parse({"--config", "site.json", "--no-sim", "--screenshot", "o.png", "--view", "map",
                        "--size", "800x600", "--settle", "1.5", "--lang", "de", "--log", "ocu.jaus,ocu.iso",
                        "--reset-layout"},
                       o, e),
                 qPrintable(e));
        QCOMPARE(o.configFile, QString("site.json"));
        QVERIFY(o.noSim);
        QCOMPARE(o.screenshotFile, QString("o.png"));
        QCOMPARE(o.view, QString("map"));
        QCOMPARE(o.size, QSize(800, 600));
        QCOMPARE(o.settleSeconds, 1.5);
        QCOMPARE(o.language, QString("de"));
        QCOMPARE(o.logCategories, QString("ocu.jaus,ocu.iso"));
        QVERIFY(o.resetLayout);
    }
    // The whole window with a tabbed panel in front (docs/teleop-video-*.png).
    void wholeWindowWithPanel() {
        CommandLineOptions o;
        QString e;
        QVERIFY2(parse({"--screenshot", "o.png", "--view", "all:3d"}, o, e), qPrintable(e));
        QCOMPARE(o.view, QString("all:3d"));
        QVERIFY(!parse({"--screenshot", "o.png", "--view", "all:radar"}, o, e));
        QVERIFY(e.contains("unknown view \"all:radar\""));
    }
    // Every panel can be captured: --view all:dispatch was refused (the list had no Dispatch panel).
    void everyPanelIsAView() {
        // The main panels, every protocol module's and the control room's, in the window's order.
        QList<PanelSpec> modulePanels;
        for (const auto& m : makeProtocolModules())
            modulePanels += m->panels();
        modulePanels << SiteRuntime::controlRoomPanel();
        const QStringList names = screenshotViewNames();
        QCOMPARE(names, MainWindow::panelKeysWith(modulePanels));
        QCOMPARE(names.mid(0, 3), QStringList({"fleet", "map", "3d"}));
        QVERIFY(names.contains("passcounts") && names.contains("events"));
        for (const PanelSpec& p : modulePanels) {
            QVERIFY2(names.contains(p.key), qPrintable(p.key));
            CommandLineOptions o;
            QString e;
            QVERIFY2(parse({"--screenshot", "o.png", "--view", "all:" + p.key}, o, e), qPrintable(e));
            QVERIFY2(parse({"--screenshot", "o.png", "--view", p.key}, o, e), qPrintable(e));
        }
        if (makeProtocolModules().size() == 3) // every protocol of today
            QCOMPARE(names,
                     QStringList({"fleet", "map", "3d", "jaus", "teleop", "passcounts", "events", "dispatch",
                                  "production", "video", "mission", "areas", "crew", "room"}));
    }
    void headless() {
        CommandLineOptions o;
        QString e;
        QVERIFY(parse({"--headless", "--duration", "15"}, o, e));
        QVERIFY(o.headless);
        QCOMPARE(o.durationSeconds, 15.0);
        QVERIFY(!parse({"--headless", "--screenshot", "x.png"}, o, e));
        QVERIFY(e.contains("cannot be combined"));
    }
    void shiftReport() {
        CommandLineOptions o;
        QString e;
        QVERIFY2(parse({"--headless", "--duration", "60", "--shift-report", "s.pdf", "--shift-csv", "s.csv"},
                       o, e),
                 qPrintable(e));
        QCOMPARE(o.shiftReportPdf, QString("s.pdf"));
        QCOMPARE(o.shiftReportCsv, QString("s.csv"));
        QVERIFY(!parse({"--shift-csv", "s.csv"}, o, e)); // needs --headless
        QVERIFY(e.contains("--headless"));
    }
    void rejections_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("view") << QStringList{"--view", "radar"} << "--view: unknown view \"radar\"";
        QTest::newRow("size") << QStringList{"--size", "big"} << "--size: expected WxH";
        QTest::newRow("tiny") << QStringList{"--size", "10x10"} << "outside 320x240";
        QTest::newRow("settle") << QStringList{"--settle", "-1"} << "--settle: expected seconds";
        QTest::newRow("lang") << QStringList{"--lang", "xx"} << "--lang: \"xx\" is not one of en, de, fr";
        QTest::newRow("duration") << QStringList{"--duration", "soon"} << "--duration: expected seconds";
        QTest::newRow("unknown") << QStringList{"--frobnicate"} << "Unknown option";
        QTest::newRow("positional") << QStringList{"extra"} << "Unexpected argument: extra";
    }
    void rejections() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        CommandLineOptions o;
        QString e;
        QVERIFY(!parse(args, o, e));
        QVERIFY2(e.contains(message), qPrintable(e));
    }
    void helpListsEveryOption() {
        CommandLineOptions o;
        QString e, help;
        QVERIFY(!parseCommandLine({"ocu", "--help"}, o, e, help));
        QVERIFY(e.isEmpty());
        for (const char* opt :
             {"--config", "--no-sim", "--screenshot", "--view", "--size", "--settle", "--lang", "--log",
              "--headless", "--duration", "--reset-layout", "--check-config", "--version"})
            QVERIFY2(help.contains(QLatin1String(opt)), opt);
    }
    // --check-config FILE: the file to validate (nothing else starts).
    void checkConfig() {
        CommandLineOptions o;
        QString e;
        QVERIFY2(parse({"--check-config", "/etc/ocu/quarry.json"}, o, e), qPrintable(e));
        QCOMPARE(o.checkConfigFile, QString("/etc/ocu/quarry.json"));
        QVERIFY(!parse({"--check-config"}, o, e)); // FILE is required
        QVERIFY2(e.contains("check-config"), qPrintable(e));
    }
    // Recording and replay options.
    void recordAndReplay() {
        CommandLineOptions o;
        QString e;
        QVERIFY2(parse({"--record", "/tmp/r", "--no-record"}, o, e), qPrintable(e));
        QCOMPARE(o.recordDir, QString("/tmp/r"));
        QVERIFY(o.noRecord);
        o = {};
        QVERIFY2(parse({"--replay", "run.sqlite", "--at", "30", "--speed", "4", "--export-csv", "o.csv",
                        "--from", "10", "--to", "20"},
                       o, e),
                 qPrintable(e));
        QCOMPARE(o.replayFile, QString("run.sqlite"));
        QCOMPARE(o.replayAt, QString("30"));
        QCOMPARE(o.replaySpeed, 4.0);
        QCOMPARE(o.exportCsv, QString("o.csv"));
        QCOMPARE(o.exportFrom, QString("10"));
        QCOMPARE(o.exportTo, QString("20"));
        o = {};
        QVERIFY(!parse({"--at", "30"}, o, e));
        QVERIFY(e.contains("--replay"));
        QVERIFY(!parse({"--replay", "r.sqlite", "--speed", "17"}, o, e));
        QVERIFY(!parse({"--replay", "r.sqlite", "--speed", "fast"}, o, e));
    }
};

QTEST_GUILESS_MAIN(TestCommandLine)
#include "test_command_line.moc"
