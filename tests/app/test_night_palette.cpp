// The night palette legible: the night palette's text/background pairs keep a contrast the
// WCAG calls readable (>= 7:1 for body text, 4.5:1 for buttons and selections), and the 2D map follows the
// palette by itself: dim ground, dark machine labels with light text; back to the day look when switched off.
#include "app/Theme.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/PassCountLayer.h"
#include "widgets/SiteMapView.h"
#ifdef OCU_HAVE_COVERAGE_WIDGETS
#include "models/coverage/CompactionView.h"
#include "widgets/coverage/CompactionMapOverlay.h"
#endif

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QTest>
#include <cmath>

using namespace ocu;

namespace {

double luminance(QColor c) {
    auto lin = [](double v) {
        v /= 255.0;
        return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * lin(c.red()) + 0.7152 * lin(c.green()) + 0.0722 * lin(c.blue());
}

double contrast(QColor a, QColor b) {
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

MachineState truck() {
    MachineState m;
    m.id = QStringLiteral("iso23725:t1");
    m.protocol = Protocol::Iso23725;
    m.name = QStringLiteral("HT1");
    m.type = QStringLiteral("HaulTruck");
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = 0;
    m.n = 0;
    m.length = 15;
    m.width = 9;
    m.lastDataMs = 1000;
    return m;
}

QImage paint(SiteMapView& v) {
    QImage img(600, 400, QImage::Format_ARGB32_Premultiplied);
    QPainter p(&img);
    v.paintScene(p, img.size());
    return img;
}

// The darkest and lightest pixels in a rectangle.
std::pair<int, int> lightnessRange(const QImage& img, QRect r) {
    int lo = 255, hi = 0;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) {
            const int l = QColor(img.pixel(x, y)).lightness();
            lo = std::min(lo, l);
            hi = std::max(hi, l);
        }
    return {lo, hi};
}

#ifdef OCU_HAVE_COVERAGE_WIDGETS
// One drawn area, nothing else: what the compaction overlay draws for it.
class OneArea : public CompactionView {
public:
    OneArea() {
        m_geometry.areas.push_back(
            {QStringLiteral("Lot A"), QPolygonF({{-20, -20}, {20, -20}, {20, 20}, {-20, 20}})});
        m_geometry.areaFromDesign.push_back(false);
    }
    const MapGeometry& mapGeometry() const override { return m_geometry; }
    DesignInfo designInfo() const override { return {}; }
    CoverageTable coverageTable(int) const override { return {}; }
    int areaCount() const override { return 1; }
    QString addArea(const QString&, const QPolygonF&) override { return {}; }
    bool removeArea(const QString&) override { return false; }
    QString saveAreas() override { return {}; }
    QString areasFile() const override { return {}; }
    bool hasWorksite() const override { return false; }
    QJsonObject reportCommand(const QJsonObject&) const override { return {}; }

private:
    MapGeometry m_geometry;
};

// Share of the pixels of r lighter than 220.
double lightShare(const QImage& img, QRect r) {
    int n = 0;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x)
            n += QColor(img.pixel(x, y)).lightness() > 220;
    return double(n) / (r.width() * r.height());
}
#endif

} // namespace

class TestNightPalette : public QObject {
    Q_OBJECT
private slots:
    void paletteContrast() {
        auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
        applyTheme(*app, Theme::Night);
        const QPalette p = QApplication::palette();
        QVERIFY(p.color(QPalette::Window).lightness() < 80); // it is a night palette
        QVERIFY(contrast(p.color(QPalette::Text), p.color(QPalette::Base)) >= 7.0);
        QVERIFY(contrast(p.color(QPalette::WindowText), p.color(QPalette::Window)) >= 7.0);
        QVERIFY(contrast(p.color(QPalette::ButtonText), p.color(QPalette::Button)) >= 4.5);
        QVERIFY(contrast(p.color(QPalette::HighlightedText), p.color(QPalette::Highlight)) >= 4.5);
        QVERIFY(contrast(p.color(QPalette::ToolTipText), p.color(QPalette::ToolTipBase)) >= 7.0);
        QVERIFY(contrast(p.color(QPalette::Text), p.color(QPalette::AlternateBase)) >= 7.0);
        applyTheme(*app, Theme::Day);
    }

    void mapFollowsThePalette() {
        auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
        FleetModel fleet;
        fleet.setClock(std::make_shared<ManualModelClock>(1500));
        FleetSelection selection(&fleet);
        fleet.upsert({truck()});
        SiteMapView v;
        v.resize(600, 400);
        v.setFleet(&fleet, &selection);
        v.setView(QPointF(0, 0), 2.0);
        QVERIFY(!v.isNight());
        const QImage day = paint(v);
        const QColor dayGround = day.pixel(5, 395);
        QVERIFY2(dayGround.lightness() > 200, qPrintable(dayGround.name()));

        applyTheme(*app, Theme::Night);
        QTRY_VERIFY(v.isNight()); // the palette change reaches the view by itself
        const QImage night = paint(v);
        const QColor nightGround = night.pixel(5, 395);
        QVERIFY2(nightGround.lightness() < 110, qPrintable(nightGround.name()));
        // The machine's label, where the view placed it: a dark box with light text in it.
        QRect labelArea;
        for (const auto& l : v.labelPlacements())
            if (l.text == QLatin1String("HT1"))
                labelArea = l.rect.toAlignedRect().adjusted(2, 2, -2, -2);
        QVERIFY(!labelArea.isEmpty());
        const auto [lo, hi] = lightnessRange(night, labelArea.intersected(night.rect()));
        QVERIFY2(lo < 60 && hi > 190, qPrintable(QStringLiteral("%1..%2").arg(lo).arg(hi)));
        const auto [dlo, dhi] = lightnessRange(day, labelArea.intersected(day.rect()));
        QVERIFY2(dlo < 60 && dhi > 230, qPrintable(QStringLiteral("%1..%2").arg(dlo).arg(dhi)));

        applyTheme(*app, Theme::Day);
        QTRY_VERIFY(!v.isNight());
        QCOMPARE(QColor(paint(v).pixel(5, 395)), dayGround);
    }

    // The pass-count legend, the scale bar and the north arrow drawn on the map follow the palette too: the
    // legend stayed a white box with black text at night (glare, and the only white area of the map).
    void legendScaleAndNorthArrowFollowThePalette() {
        auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
        FleetModel fleet;
        FleetSelection selection(&fleet);
        GridPassCountLayer pass({-100, -100}, 1.0, 200, 200);
        pass.fillRect(QRect(90, 90, 20, 20), 4);
        SiteMapView v;
        v.resize(600, 400);
        v.setFleet(&fleet, &selection);
        v.setPassCountLayer(&pass);
        v.setLayerVisible(SiteMapView::LayerCursor, false);
        v.setView(QPointF(0, 0), 2.0);
        // drawLegend's box: x from 8, bottom edge 30 px above the view's bottom, ten 8-pt lines tall; (10,
        // 400 - 33) is inside it, left of the colour swatches; x 38..60 over the lower 95 px holds the count
        // labels ("1" … "9+") and the box between them.
        const QPoint boxPixel(10, 400 - 33);
        const QRect titleRow(38, 400 - 130, 22, 95);
        const QImage day = paint(v);
        QVERIFY2(QColor(day.pixel(boxPixel)).lightness() > 200,
                 qPrintable(QColor(day.pixel(boxPixel)).name()));
        const auto [dlo, dhi] = lightnessRange(day, titleRow);
        QVERIFY2(dlo < 80 && dhi > 200, qPrintable(QStringLiteral("%1..%2").arg(dlo).arg(dhi)));

        applyTheme(*app, Theme::Night);
        QTRY_VERIFY(v.isNight());
        const QImage night = paint(v);
        QVERIFY2(QColor(night.pixel(boxPixel)).lightness() < 60,
                 qPrintable(QColor(night.pixel(boxPixel)).name()));
        const auto [nlo, nhi] = lightnessRange(night, titleRow);
        QVERIFY2(nlo < 60 && nhi > 190, qPrintable(QStringLiteral("%1..%2").arg(nlo).arg(nhi)));
        // Scale bar (2 px line ending 16 px left of the right edge, 30 px above the bottom) and north arrow
        // (its tip area right of centre at the top right): light at night, dark by day.
        const QPoint scale(600 - 20, 400 - 30);
        const QPoint north(600 - 28, 34);
        QVERIFY2(QColor(night.pixel(scale)).lightness() > 180, qPrintable(QColor(night.pixel(scale)).name()));
        QVERIFY2(QColor(day.pixel(scale)).lightness() < 60, qPrintable(QColor(day.pixel(scale)).name()));
        QVERIFY2(QColor(night.pixel(north)).lightness() > 150, qPrintable(QColor(night.pixel(north)).name()));
        QVERIFY2(QColor(day.pixel(north)).lightness() < 80, qPrintable(QColor(day.pixel(north)).name()));
        applyTheme(*app, Theme::Day);
        QTRY_VERIFY(!v.isNight());
    }

#ifdef OCU_HAVE_COVERAGE_WIDGETS
    // The compaction overlay's name boxes and halos were white at night.
    void compactionLabelsFollowThePalette() {
        auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
        SiteMapView v;
        v.resize(600, 400);
        for (auto l : {SiteMapView::LayerCursor, SiteMapView::LayerLegend, SiteMapView::LayerScaleBar,
                       SiteMapView::LayerNorthArrow})
            v.setLayerVisible(l, false);
        v.setView(QPointF(0, 0), 2.0);
        OneArea session;
        CompactionMapOverlay overlay(&v, &session);
        // The name's box: right of and above the first vertex (-20, -20) on screen, one text line high.
        const QImage day = paint(v); // (the view learns its size from the first paint)
        const QPoint corner = v.worldToScreen(QPointF(-20, -20)).toPoint();
        const QRect nameBox(corner.x() + 3, corner.y() - 15, 34, 9);
        QVERIFY2(lightShare(day, nameBox) > 0.5, qPrintable(QString::number(lightShare(day, nameBox))));
        applyTheme(*app, Theme::Night);
        QTRY_VERIFY(v.isNight());
        const QImage night = paint(v);
        QVERIFY2(lightShare(night, nameBox) < 0.1, qPrintable(QString::number(lightShare(night, nameBox))));
        // The name itself stays readable: light text in the dark box.
        const auto [lo, hi] = lightnessRange(night, nameBox);
        QVERIFY2(lo < 60 && hi > 150, qPrintable(QStringLiteral("%1..%2").arg(lo).arg(hi)));
        applyTheme(*app, Theme::Day);
        QTRY_VERIFY(!v.isNight());
    }
#endif
};

QTEST_MAIN(TestNightPalette)
#include "test_night_palette.moc"
