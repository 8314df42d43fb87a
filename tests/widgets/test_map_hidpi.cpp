// High-DPI symbols: at a device pixel ratio of 2 (QT_SCALE_FACTOR=2, a 4K laptop) the map's
// SVG symbols are rendered at twice the pixels, not a 1x picture scaled up; the whole scene paints into a
// dpr-2 surface with the machine at the right device pixels.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/MapSymbols.h"
#include "widgets/SiteMapView.h"

#include <QImage>
#include <QPainter>
#include <QTest>

using namespace ocu;

namespace {

// Mean absolute channel difference of two same-sized images.
double meanDiff(const QImage& a, const QImage& b) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
                   std::abs(qBlue(p) - qBlue(q)) + std::abs(qAlpha(p) - qAlpha(q));
        }
    return sum / (a.width() * a.height() * 4.0);
}

} // namespace

class TestMapHiDpi : public QObject {
    Q_OBJECT
private slots:
    void symbolsAreRenderedAtTheDevicePixelRatio() {
        MapSymbolCache cache;
        const QSizeF fp(26, 44);
        for (MachineSymbol s :
             {MachineSymbol::HaulTruck, MachineSymbol::Ugv, MachineSymbol::Roller, MachineSymbol::Paver,
              MachineSymbol::Loader, MachineSymbol::LightVehicle, MachineSymbol::Unknown}) {
            const SymbolStyle style{s, StatusCategory::Ok, SymbolRing::None, false};
            const QImage one = cache.image(fp, 30, style, 1.0);
            const QImage two = cache.image(fp, 30, style, 2.0);
            QVERIFY(!one.isNull() && !two.isNull());
            QCOMPARE(two.devicePixelRatio(), 2.0);
            QVERIFY2(std::abs(two.width() - 2 * one.width()) <= 2 &&
                         std::abs(two.height() - 2 * one.height()) <= 2,
                     qPrintable(QStringLiteral("%1x%2 vs %3x%4")
                                    .arg(two.width())
                                    .arg(two.height())
                                    .arg(one.width())
                                    .arg(one.height())));
            // Rendered at 2x: it differs from the 1x picture blown up (which has blocky 2 px steps) ...
            const QImage blown = one.scaled(two.size(), Qt::IgnoreAspectRatio, Qt::FastTransformation)
                                     .convertToFormat(two.format());
            QVERIFY2(meanDiff(two, blown) > 1.0, qPrintable(QString::number(meanDiff(two, blown))));
            // ... but shows the same symbol: scaled back down, it matches the 1x picture closely.
            const QImage down = two.scaled(one.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation)
                                    .convertToFormat(one.format());
            QVERIFY2(meanDiff(down, one) < 12.0, qPrintable(QString::number(meanDiff(down, one))));
        }
    }

    void sceneAtDevicePixelRatio2() {
        FleetModel fleet;
        fleet.setClock(std::make_shared<ManualModelClock>(1500));
        FleetSelection selection(&fleet);
        MachineState m;
        m.id = QStringLiteral("iso23725:t1");
        m.protocol = Protocol::Iso23725;
        m.name = QStringLiteral("HT1");
        m.type = QStringLiteral("HaulTruck");
        m.link = LinkState::Up;
        m.hasPosition = true;
        m.length = 15;
        m.width = 9;
        m.lastDataMs = 1000;
        fleet.upsert({m});
        SiteMapView v;
        v.resize(600, 400);
        v.setFleet(&fleet, &selection);
        v.setView(QPointF(0, 0), 2.0);
        QImage img(1200, 800, QImage::Format_ARGB32_Premultiplied);
        img.setDevicePixelRatio(2.0);
        QPainter p(&img);
        v.paintScene(p, QSize(600, 400));
        p.end();
        // The machine (green body: status ok) at the view centre: device pixel (600, 400), not (300, 200).
        const QColor c = img.pixelColor(600, 400);
        QVERIFY2(c.green() > c.red() + 40 && c.green() > c.blue() + 40, qPrintable(c.name()));
        // Its label is placed in logical pixels, inside the 600 x 400 view.
        bool label = false;
        for (const auto& l : v.labelPlacements())
            label = label || (l.text == QLatin1String("HT1") && QRectF(0, 0, 600, 400).contains(l.rect));
        QVERIFY(label);
    }
};

QTEST_MAIN(TestMapHiDpi)
#include "test_map_hidpi.moc"
