#include "widgets/MapSymbols.h"

#include <QFile>
#include <QPainter>
#include <QSvgRenderer>
#include <cmath>

static void initSymbolResources() {
    Q_INIT_RESOURCE(ocu_map_symbols); // the SVGs live in this static library
}

namespace ocu {

namespace {
constexpr int kHeadingStepDeg = 5;
constexpr int kRingMarginPx = 6;

QColor ringColour(SymbolRing r) {
    switch (r) {
    case SymbolRing::Stopped:
        return QColor(0xd0, 0x00, 0x00);
    case SymbolRing::ControlledByMe:
        return QColor(0x9b, 0x30, 0xff);
    case SymbolRing::None:
        break;
    }
    return Qt::transparent;
}
} // namespace

MachineSymbol symbolForType(const QString& type) {
    const QString t = type.toLower();
    auto has = [&](const char* s) { return t.contains(QLatin1String(s)); };
    if (has("truck") || has("haul") || has("dumper"))
        return MachineSymbol::HaulTruck;
    if (has("ugv") || has("robot") || has("unmanned"))
        return MachineSymbol::Ugv;
    if (has("roller") || has("compact"))
        return MachineSymbol::Roller;
    if (has("paver") || has("finisher"))
        return MachineSymbol::Paver;
    if (has("loader") || has("shovel") || has("excavator") || has("dozer"))
        return MachineSymbol::Loader;
    if (has("light") || has("pickup") || has("pick-up") || has("car"))
        return MachineSymbol::LightVehicle;
    return MachineSymbol::Unknown;
}

QString symbolName(MachineSymbol s) {
    switch (s) {
    case MachineSymbol::HaulTruck:
        return QStringLiteral("haul_truck");
    case MachineSymbol::Ugv:
        return QStringLiteral("ugv");
    case MachineSymbol::Roller:
        return QStringLiteral("roller");
    case MachineSymbol::Paver:
        return QStringLiteral("paver");
    case MachineSymbol::Loader:
        return QStringLiteral("loader");
    case MachineSymbol::LightVehicle:
        return QStringLiteral("light_vehicle");
    case MachineSymbol::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

MapSymbolCache::MapSymbolCache() {
    initSymbolResources();
}

MapSymbolCache::~MapSymbolCache() = default;

MachineSymbol MapSymbolCache::symbolFor(const QString& type) {
    // A fleet is mostly one or two types: the last one answers without hashing the text.
    if (m_lastTypeValid && type == m_lastType)
        return m_lastSymbol;
    m_lastType = type;
    m_lastTypeValid = true;
    m_lastSymbol = symbolForTypeCached(type);
    return m_lastSymbol;
}

MachineSymbol MapSymbolCache::symbolForTypeCached(const QString& type) {
    auto it = m_typeSymbols.constFind(type);
    if (it != m_typeSymbols.constEnd())
        return *it;
    if (m_typeSymbols.size() > 1000) // free-text types from foreign peers: bounded
        m_typeSymbols.clear();
    return *m_typeSymbols.insert(type, symbolForType(type));
}

QSizeF MapSymbolCache::footprintPx(double lengthM, double widthM, double pxPerMetre) {
    double len = lengthM * pxPerMetre, wid = widthM * pxPerMetre;
    if (len < kMinLengthPx) {
        // Zoomed out: keep the machine's proportions but at a legible minimum size.
        const double k = kMinLengthPx / std::max(len, 1e-9);
        len = kMinLengthPx;
        wid *= k;
    }
    wid = std::clamp(wid, kMinWidthPx, len);
    return {wid, len};
}

QSvgRenderer* MapSymbolCache::renderer(MachineSymbol s, StatusCategory status) {
    const int key = int(s) * 16 + int(status);
    auto it = m_renderers.find(key);
    if (it != m_renderers.end())
        return it->get();
    QByteArray& src = m_sources[int(s)];
    if (src.isEmpty()) {
        QFile f(QStringLiteral(":/symbols/%1.svg").arg(symbolName(s)));
        if (f.open(QIODevice::ReadOnly))
            src = f.readAll();
    }
    QByteArray text = src;
    text.replace("#00ff01", statusColor(status).name().toLatin1());
    auto r = std::make_shared<QSvgRenderer>(text);
    r->setAspectRatioMode(Qt::IgnoreAspectRatio); // the footprint's own proportions
    m_renderers.insert(key, r);
    return r.get();
}

void MapSymbolCache::paintSymbol(QPainter& p, QPointF centre, QSizeF fp, double headingDeg,
                                 const SymbolStyle& style) {
    const double radius = std::hypot(fp.width(), fp.height()) / 2 + 2;
    if (style.ring != SymbolRing::None) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(Qt::white, 5.5));
        p.drawEllipse(centre, radius, radius);
        p.setPen(QPen(ringColour(style.ring), 3));
        p.drawEllipse(centre, radius, radius);
    }
    p.save();
    if (style.stale)
        p.setOpacity(0.55);
    p.translate(centre);
    p.rotate(headingDeg);
    if (QSvgRenderer* r = renderer(style.symbol, style.status); r && r->isValid()) {
        r->render(&p, QRectF(-fp.width() / 2, -fp.height() / 2, fp.width(), fp.height()));
    } else { // resource missing: still a visible, oriented marker
        p.setPen(QPen(Qt::black, 1));
        p.setBrush(statusColor(style.status));
        p.drawRect(QRectF(-fp.width() / 2, -fp.height() / 2, fp.width(), fp.height()));
    }
    p.restore();
}

QImage MapSymbolCache::image(QSizeF fp, double headingDeg, const SymbolStyle& style, qreal dpr) {
    const int len = int(std::lround(fp.height())), wid = int(std::lround(fp.width()));
    if (len > kMaxCachedPx || wid > kMaxCachedPx || len <= 0 || wid <= 0)
        return {};
    double h = std::fmod(headingDeg, 360.0);
    if (h < 0)
        h += 360;
    const int bucket = int(std::lround(h / kHeadingStepDeg)) % (360 / kHeadingStepDeg);
    const quint64 key = quint64(style.symbol) | quint64(style.status) << 4 | quint64(style.ring) << 8 |
                        quint64(style.stale) << 10 | quint64(len) << 12 | quint64(wid) << 20 |
                        quint64(bucket) << 28 | quint64(std::lround(dpr * 4)) << 36;
    auto it = m_images.constFind(key);
    if (it != m_images.constEnd())
        return *it;
    if (m_images.size() > 6000) // a zoom sweep through many sizes: start over rather than grow without bound
        m_images.clear();
    const int side = int(std::ceil(std::hypot(len, wid))) + 2 * kRingMarginPx;
    QImage img(QSize(side, side) * dpr, QImage::Format_ARGB32_Premultiplied);
    img.setDevicePixelRatio(dpr);
    img.fill(Qt::transparent);
    {
        QPainter ip(&img);
        ip.setRenderHint(QPainter::Antialiasing, true);
        ip.setRenderHint(QPainter::SmoothPixmapTransform, true);
        paintSymbol(ip, QPointF(side / 2.0, side / 2.0), QSizeF(wid, len), bucket * kHeadingStepDeg, style);
    }
    ++m_renders;
    m_images.insert(key, img);
    return img;
}

void MapSymbolCache::draw(QPainter& p, QPointF centre, QSizeF fp, double headingDeg, const SymbolStyle& style,
                          qreal dpr) {
    const QImage img = image(fp, headingDeg, style, dpr);
    if (img.isNull()) {
        p.save();
        p.setRenderHint(QPainter::Antialiasing, true);
        paintSymbol(p, centre, fp, headingDeg, style);
        p.restore();
        return;
    }
    const double half = img.width() / dpr / 2.0;
    // Whole-pixel position: an unscaled blit (the fast path) instead of a resampled one.
    p.drawImage(QPointF(std::round(centre.x() - half), std::round(centre.y() - half)), img);
}

} // namespace ocu
