// The shift report. The PDF's first page, rendered by poppler's pdftoppm (a reader that is not
// ours), is not blank: it carries text, the map snapshot and the charts' colours. The CSV read back gives the
// model's numbers, row by row. Writing to an impossible place is reported, not crashed on.
#include "models/ProductionModel.h"
#include "models/SiteMapData.h"
#include "widgets/production/ProductionCharts.h"
#include "widgets/production/ProductionView.h"
#include "widgets/production/ShiftReport.h"

#include <QFile>
#include <QImage>
#include <QLabel>
#include <QProcess>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace ocu;

namespace {

constexpr qint64 kMin = 60'000;

// A model with three trucks, two shovels and two dumps over two hours of a shift.
void fill(ProductionModel& m, qint64 start) {
    m.setShift(start, start + 12 * 60 * kMin);
    m.setPlanTonnes(24000);
    m.setAreaName(4101, QStringLiteral("Pit 1 shovel 1"));
    m.setAreaName(4102, QStringLiteral("Pit 1 shovel 2"));
    m.setAreaName(4201, QStringLiteral("Waste dump 1"));
    m.setAreaName(4203, QStringLiteral("Primary crusher, north"));
    int n = 0;
    for (qint64 t = start + 10 * kMin; t < start + 120 * kMin; t += 7 * kMin, ++n) {
        const QString truck = QStringLiteral("iso23725:t%1").arg(n % 3);
        const qint64 shovel = 4101 + n % 2, dumpWay = n % 3 == 0 ? 4203 : 4201;
        ProductionReport s;
        s.kind = ProductionReport::Kind::State;
        s.truckId = truck;
        s.truckName = QStringLiteral("HT10%1").arg(n % 3 + 1);
        s.state = QStringLiteral("Loading");
        s.wayId = shovel;
        s.unixMs = t - 5 * kMin;
        m.addReport(s);
        ProductionReport d = s;
        d.kind = ProductionReport::Kind::Dump;
        d.wayId = d.dumpWayId = dumpWay;
        d.tonnes = 220 + (n * 7) % 80;
        d.unixMs = t;
        m.addReport(d);
        ProductionReport c = d;
        c.kind = ProductionReport::Kind::Cycle;
        c.loadWayId = shovel;
        c.unixMs = t + 1;
        qint64 at = t - 20 * kMin;
        for (auto [name, sec] : {std::pair<const char*, double>{"Driving", 240.0 + n},
                                 {"Queued", 30.0 * (n % 4)},
                                 {"Spotting", 25},
                                 {"Loading", 110},
                                 {"Hauling", 520},
                                 {"Dumping", 40}}) {
            c.periods.push_back({QString::fromLatin1(name), at, sec});
            at += qint64(sec * 1000);
        }
        m.addReport(c);
    }
}

SiteMapData someMap() {
    SiteMapData d;
    MapFeature road;
    road.id = QStringLiteral("2001");
    road.name = QStringLiteral("Main ramp");
    road.points = {{0, 0}, {200, 150}, {400, 160}};
    road.width = 20;
    d.features << road;
    MapFeature area;
    area.id = QStringLiteral("4101");
    area.name = QStringLiteral("Shovel 1");
    area.kind = MapFeatureKind::Area;
    area.defaultTask = QStringLiteral("load");
    area.points = {{380, 120}, {460, 120}, {460, 200}, {380, 200}, {380, 120}};
    d.features << area;
    d.revision = 1;
    return d;
}

// Splits one CSV line (quoted fields with "" escapes).
QStringList csvSplit(const QString& line) {
    QStringList out;
    QString cur;
    bool quoted = false;
    for (int i = 0; i < line.size(); ++i) {
        const QChar ch = line[i];
        if (quoted) {
            if (ch == QLatin1Char('"') && i + 1 < line.size() && line[i + 1] == QLatin1Char('"'))
                cur += QLatin1Char('"'), ++i;
            else if (ch == QLatin1Char('"'))
                quoted = false;
            else
                cur += ch;
        } else if (ch == QLatin1Char('"')) {
            quoted = true;
        } else if (ch == QLatin1Char(',')) {
            out << cur;
            cur.clear();
        } else {
            cur += ch;
        }
    }
    out << cur;
    return out;
}

} // namespace

class TestShiftReport : public QObject {
    Q_OBJECT
private slots:
    void pdfFirstPageIsNotBlank() {
        const QString pdftoppm = QStandardPaths::findExecutable(QStringLiteral("pdftoppm"));
        if (pdftoppm.isEmpty())
            QFAIL("pdftoppm (poppler-utils) is not installed: scripts/install-deps.sh installs it");
        ProductionModel m;
        fill(m, QDateTime::currentMSecsSinceEpoch() - 150 * kMin);
        QVERIFY(m.shift().loads > 10);
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("shift.pdf"));
        const QImage map = renderSiteSnapshot(nullptr, someMap(), QSize(800, 450));
        QVERIFY(!map.isNull());
        QCOMPARE(writeShiftPdf(m, map, QStringLiteral("Test pit"), pdf), QString());
        QProcess p;
        p.start(pdftoppm, {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"),
                           QStringLiteral("1"), QStringLiteral("-r"), QStringLiteral("60"),
                           QStringLiteral("-png"), pdf, dir.filePath(QStringLiteral("page"))});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QImage page(dir.filePath(QStringLiteral("page-1.png")));
        QVERIFY2(!page.isNull(), qPrintable(QDir(dir.path()).entryList().join(QLatin1Char(' '))));
        QVERIFY(page.width() > 400 && page.height() > page.width()); // A4 portrait
        // Not blank: a real share of the page is drawn on, in the top (title, map) and the lower half
        // (charts), and the charts' colours are there (the blue tonnes line, the stacked cycle bars).
        int inked = 0, inkedLower = 0, blue = 0, red = 0;
        for (int y = 0; y < page.height(); ++y)
            for (int x = 0; x < page.width(); ++x) {
                const QColor c = page.pixelColor(x, y);
                if (c.lightness() < 235) {
                    ++inked;
                    if (y > page.height() / 2)
                        ++inkedLower;
                }
                if (c.blue() > 150 && c.red() < 110 && c.green() < 160)
                    ++blue;
                if (c.red() > 180 && c.green() < 100 && c.blue() < 100)
                    ++red;
            }
        const int total = page.width() * page.height();
        QVERIFY2(inked > total / 20, qPrintable(QStringLiteral("%1 of %2").arg(inked).arg(total)));
        QVERIFY(inkedLower > total / 50);
        QVERIFY(blue > 50);
        QVERIFY(red > 20);
    }

    void csvReadBackEqualsTheModel() {
        ProductionModel m;
        fill(m, QDateTime::currentMSecsSinceEpoch() - 150 * kMin);
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("shift.csv"));
        QCOMPARE(writeShiftCsv(m, csv), QString());
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        QStringList header;
        QHash<QString, QStringList> rows; // "section/key"
        while (!f.atEnd()) {
            const QString line = QString::fromUtf8(f.readLine()).trimmed();
            if (line.startsWith(QLatin1Char('#')) || line.isEmpty())
                continue;
            const QStringList cells = csvSplit(line);
            if (header.isEmpty()) {
                header = cells;
                continue;
            }
            QCOMPARE(cells.size(), header.size());
            rows.insert(cells[0] + QLatin1Char('/') + cells[1], cells);
        }
        QCOMPARE(header.value(3), QStringLiteral("loads"));
        const int tonnesCol = header.indexOf(QStringLiteral("tonnes"));
        const int cyclesCol = header.indexOf(QStringLiteral("cycles"));
        const int queueCol = header.indexOf(QStringLiteral("queue_s"));
        const int haulCol = header.indexOf(QStringLiteral("haul_s"));
        const int returnCol = header.indexOf(QStringLiteral("return_s"));
        QVERIFY(tonnesCol > 0 && cyclesCol > 0 && queueCol > 0 && haulCol > 0 && returnCol > 0);
        auto check = [&](const QString& section, const ProductionTally& t) {
            const QStringList r = rows.value(section + QLatin1Char('/') + t.key);
            QVERIFY2(!r.isEmpty(), qPrintable(section + QLatin1Char('/') + t.key));
            QCOMPARE(r[2], t.name);
            QCOMPARE(r[3].toInt(), t.loads);
            QVERIFY(qAbs(r[tonnesCol].toDouble() - t.tonnes) < 0.05);
            QCOMPARE(r[cyclesCol].toInt(), t.cycle.cycles);
            QVERIFY(qAbs(r[queueCol].toDouble() - t.cycle.average(CycleBreakdown::Queue)) < 0.05);
            QVERIFY(qAbs(r[haulCol].toDouble() - t.cycle.average(CycleBreakdown::Haul)) < 0.05);
            QVERIFY(qAbs(r[returnCol].toDouble() - t.cycle.average(CycleBreakdown::Return)) < 0.05);
        };
        check(QStringLiteral("shift"), m.shift());
        for (const auto& t : m.trucks())
            check(QStringLiteral("truck"), t);
        for (const auto& t : m.shovels())
            check(QStringLiteral("shovel"), t);
        for (const auto& t : m.dumps())
            check(QStringLiteral("dump"), t);
        QCOMPARE(rows.size(), 1 + m.trucks().size() + m.shovels().size() + m.dumps().size());
        // The crusher's name has a comma: quoted, read back whole.
        QCOMPARE(rows.value(QStringLiteral("dump/4203")).value(2), QStringLiteral("Primary crusher, north"));
    }

    void unwritableFilesAreReported() {
        ProductionModel m;
        const QString bad = QStringLiteral("/nonexistent-dir/x/shift");
        QVERIFY(!writeShiftCsv(m, bad + QStringLiteral(".csv")).isEmpty());
        QVERIFY(!writeShiftPdf(m, QImage(), QString(), bad + QStringLiteral(".pdf")).isEmpty());
    }

    void viewShowsTheFigures() {
        ProductionModel m;
        fill(m, QDateTime::currentMSecsSinceEpoch() - 150 * kMin);
        ProductionView v(&m);
        v.resize(1000, 600);
        v.refresh();
        QCOMPARE(v.table(0)->rowCount(), m.trucks().size());
        QCOMPARE(v.table(1)->rowCount(), m.shovels().size());
        QCOMPARE(v.table(0)->item(0, 1)->text(), QString::number(m.trucks().first().loads));
        QVERIFY(v.summaryLabel()->text().contains(QString::number(m.shift().loads)));
        QTemporaryDir dir;
        QCOMPARE(v.writeReport(dir.filePath(QStringLiteral("r.pdf")), dir.filePath(QStringLiteral("r.csv"))),
                 QString());
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("r.pdf"))).size() > 1000);
    }
    // The live charts follow the model: a dump reported during the shift raises the tonnes line
    // (the blue of "Dumped (t)" appears in the upper half of the chart) and a cycle adds its bar (the green
    // of "Haul") to the breakdown, without anything but the model changing.
    void liveChartsFollowTheModel() {
        ProductionModel m;
        const qint64 start = QDateTime::currentMSecsSinceEpoch() - 150 * kMin;
        m.setShift(start, start + 12 * 60 * kMin);
        std::unique_ptr<QWidget> tonnes(createProductionChartView(ProductionChart::TonnesVsPlan, &m));
        std::unique_ptr<QWidget> cycles(createProductionChartView(ProductionChart::CycleBreakdown, &m));
        for (QWidget* w : {tonnes.get(), cycles.get()}) {
            w->resize(600, 400);
            w->show();
        }
        QVERIFY(QTest::qWaitForWindowExposed(tonnes.get()));
        // Pixels of about `c` in the image's upper half (the tonnes line) or anywhere (the bars).
        auto count = [](const QImage& img, QColor c, bool upperHalf) {
            int n = 0;
            for (int y = 0; y < (upperHalf ? img.height() / 2 : img.height()); ++y)
                for (int x = 0; x < img.width(); ++x) {
                    const QColor p = img.pixelColor(x, y);
                    n += std::abs(p.red() - c.red()) < 30 && std::abs(p.green() - c.green()) < 30 &&
                         std::abs(p.blue() - c.blue()) < 30;
                }
            return n;
        };
        const QColor dumped(0x2e, 0x6f, 0xd0), haul(0x2e, 0x9e, 0x5b);
        QCOMPARE(count(tonnes->grab().toImage(), dumped, true), 0);
        const int legendOnly = count(cycles->grab().toImage(), haul, false); // the legend's marker

        fill(m, start); // dumps and cycles over the first two hours of the shift
        QTRY_VERIFY_WITH_TIMEOUT(count(tonnes->grab().toImage(), dumped, true) > 50, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(count(cycles->grab().toImage(), haul, false) > legendOnly + 200, 10000);
    }
};

QTEST_MAIN(TestShiftReport)
#include "test_shift_report.moc"
