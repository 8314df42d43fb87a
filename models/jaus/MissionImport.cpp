#include "models/jaus/MissionImport.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <memory>
#include <mutex>

namespace ocu {

namespace {

struct DatasetClose {
    void operator()(void* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<void, DatasetClose>;
struct FeatureDestroy {
    void operator()(OGRFeatureH f) const { OGR_F_Destroy(f); }
};
using Feature = std::unique_ptr<std::remove_pointer_t<OGRFeatureH>, FeatureDestroy>;

// GDAL's messages while reading this file, instead of its default printing to stderr.
class ErrorCapture {
public:
    ErrorCapture() { CPLPushErrorHandlerEx(&ErrorCapture::handler, this); }
    ~ErrorCapture() { CPLPopErrorHandler(); }
    QString text() const { return m_text; }

private:
    static void handler(CPLErr level, CPLErrorNum, const char* msg) {
        auto* self = static_cast<ErrorCapture*>(CPLGetErrorHandlerUserData());
        if (self && level >= CE_Failure && self->m_text.isEmpty())
            self->m_text = QString::fromUtf8(msg);
    }
    QString m_text;
};

// To WGS84 longitude/latitude order, or null when the layer is WGS84 already (GPX and KML always are).
OGRCoordinateTransformationH toWgs84(OGRLayerH layer) {
    OGRSpatialReferenceH src = OGR_L_GetSpatialRef(layer);
    if (!src)
        return nullptr;
    OGRSpatialReferenceH wgs = OSRNewSpatialReference(nullptr);
    OSRSetWellKnownGeogCS(wgs, "WGS84");
    OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH ct = nullptr;
    if (!OSRIsSame(src, wgs)) {
        OGRSpatialReferenceH s = OSRClone(src);
        OSRSetAxisMappingStrategy(s, OAMS_TRADITIONAL_GIS_ORDER);
        ct = OCTNewCoordinateTransformation(s, wgs);
        OSRDestroySpatialReference(s);
    }
    OSRDestroySpatialReference(wgs);
    return ct;
}

void addPoints(OGRGeometryH g, OGRCoordinateTransformationH ct, QVector<MissionWaypoint>& out) {
    if (ct)
        OGR_G_Transform(g, ct);
    for (int i = 0; i < OGR_G_GetPointCount(g); ++i)
        out << MissionWaypoint{OGR_G_GetY(g, i), OGR_G_GetX(g, i), 0, 0};
}

// The first line of the layer (a LineString, or the parts of a MultiLineString in order), else its points.
void readLayer(OGRLayerH layer, QVector<MissionWaypoint>& line, QVector<MissionWaypoint>& points) {
    OGRCoordinateTransformationH ct = toWgs84(layer);
    OGR_L_ResetReading(layer);
    while (line.isEmpty()) {
        Feature f(OGR_L_GetNextFeature(layer));
        if (!f)
            break;
        OGRGeometryH g = OGR_F_GetGeometryRef(f.get());
        if (!g)
            continue;
        switch (wkbFlatten(OGR_G_GetGeometryType(g))) {
        case wkbLineString:
            addPoints(g, ct, line);
            break;
        case wkbMultiLineString:
            for (int k = 0; k < OGR_G_GetGeometryCount(g); ++k)
                addPoints(OGR_G_GetGeometryRef(g, k), ct, line);
            break;
        case wkbPoint:
            addPoints(g, ct, points);
            break;
        default:
            break;
        }
    }
    if (ct)
        OCTDestroyCoordinateTransformation(ct);
}

} // namespace

MissionFileRead importMissionRoute(const QString& path) {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    auto fail = [&](const QString& why) {
        return MissionFileRead{{}, QStringLiteral("%1: %2").arg(path, why)};
    };
    const QFileInfo fi(path);
    if (!fi.isFile() || !fi.isReadable())
        return fail(QCoreApplication::translate("ocu::MissionImport", "no such readable file"));
    ErrorCapture errors;
    const QByteArray p8 = path.toUtf8();
    Dataset ds(GDALOpenEx(p8.constData(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!ds)
        return fail(QCoreApplication::translate("ocu::MissionImport", "not a route GDAL can read (%1)")
                        .arg(errors.text().isEmpty()
                                 ? QCoreApplication::translate("ocu::MissionImport", "unknown format")
                                 : errors.text()));
    // GPX: routes before tracks before waypoints, whatever order the driver lists its layers in.
    const char* preferred[] = {"routes", "tracks"};
    QVector<MissionWaypoint> line, points;
    for (const char* name : preferred)
        if (OGRLayerH l = GDALDatasetGetLayerByName(ds.get(), name); l && line.isEmpty())
            readLayer(l, line, points);
    for (int i = 0; line.isEmpty() && i < GDALDatasetGetLayerCount(ds.get()); ++i) {
        OGRLayerH l = GDALDatasetGetLayer(ds.get(), i);
        const QByteArray name = OGR_L_GetName(l);
        if (name == "route_points" || name == "track_points") // the same points as routes and tracks
            continue;
        readLayer(l, line, points);
    }
    QVector<MissionWaypoint> out = line.isEmpty() ? points : line;
    if (out.isEmpty())
        return fail(QCoreApplication::translate("ocu::MissionImport", "has no route, track or points"));
    for (const MissionWaypoint& w : out)
        if (!(std::abs(w.lat) <= 90 && std::abs(w.lon) <= 180))
            return fail(QCoreApplication::translate("ocu::MissionImport", "has points outside WGS84"));
    return {out, {}};
}

} // namespace ocu
