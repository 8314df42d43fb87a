#pragma once
// Machine symbols of the 2D map: one SVG per machine type (resources/symbols/), coloured by
// state, rotated to heading, rendered once per type/size/state/heading bucket into a cached image so a frame
// with 1,000 machines is a series of small blits.
#include "models/MachineState.h"

#include <QHash>
#include <QImage>
#include <QSizeF>
#include <QString>
#include <memory>

class QPainter;
class QSvgRenderer;

namespace ocu {

enum class MachineSymbol : quint8 { HaulTruck, Ugv, Roller, Paver, Loader, LightVehicle, Unknown };
constexpr int kMachineSymbolCount = 7;

// The symbol for a free-text equipment type ("haul truck", "UGV", "Shovel", "LightVehicle", ...).
MachineSymbol symbolForType(const QString& type);
QString symbolName(MachineSymbol s); // "haul_truck", ... (the resource file's base name)

// The ring drawn around a symbol for states that must stand out beyond the fill colour.
enum class SymbolRing : quint8 { None, Stopped, ControlledByMe };

struct SymbolStyle {
    MachineSymbol symbol = MachineSymbol::Unknown;
    StatusCategory status = StatusCategory::Ok; // body fill
    SymbolRing ring = SymbolRing::None;
    bool stale = false; // drawn faded
};

class MapSymbolCache {
public:
    MapSymbolCache();
    ~MapSymbolCache();
    MapSymbolCache(const MapSymbolCache&) = delete;
    MapSymbolCache& operator=(const MapSymbolCache&) = delete;

    // Minimum on-screen length of a symbol (px): smaller machines are drawn at this size, not at true size.
    static constexpr double kMinLengthPx = 22.0;
    static constexpr double kMinWidthPx = 13.0;
    // Symbols longer than this are drawn straight from the SVG (few machines are on screen when this big).
    static constexpr int kMaxCachedPx = 96;

    // The on-screen footprint (width across, length along) of a machine of lengthM x widthM at scale px/m.
    static QSizeF footprintPx(double lengthM, double widthM, double pxPerMetre);

    // Draws the symbol centred at `centre`, rotated to headingDeg (0 = north, clockwise).
    void draw(QPainter& p, QPointF centre, QSizeF footprint, double headingDeg, const SymbolStyle& style,
              qreal dpr);
    // The cached image for one style (exposed for tests); null when the footprint is too big to cache.
    QImage image(QSizeF footprint, double headingDeg, const SymbolStyle& style, qreal dpr);

    // symbolForType(type), remembered per type text (a frame asks once per machine).
    MachineSymbol symbolFor(const QString& type);

    int cachedImages() const { return int(m_images.size()); }
    int renders() const { return m_renders; } // images rendered so far (cache misses)

private:
    MachineSymbol symbolForTypeCached(const QString& type);
    QSvgRenderer* renderer(MachineSymbol s, StatusCategory status);
    void paintSymbol(QPainter& p, QPointF centre, QSizeF footprint, double headingDeg,
                     const SymbolStyle& style);

    QHash<quint64, QImage> m_images;
    QHash<int, std::shared_ptr<QSvgRenderer>> m_renderers; // per (symbol, status colour)
    QHash<int, QByteArray> m_sources;                      // SVG text per symbol
    QHash<QString, MachineSymbol> m_typeSymbols;
    QString m_lastType;
    bool m_lastTypeValid = false;
    MachineSymbol m_lastSymbol = MachineSymbol::Unknown;
    int m_renders = 0;
};

} // namespace ocu
