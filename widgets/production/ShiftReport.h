#pragma once
// The shift report: the production model as a PDF (a map snapshot, the shift's figures, the
// tonnes-vs-plan and cycle-breakdown charts, then tables per truck, shovel and dump) and as CSV (one row per
// truck, shovel, dump and the shift: loads, tonnes, cycles and the average cycle breakdown in seconds).
#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QVector>

namespace ocu {

class FleetModel;
class ProductionModel;
struct SiteMapData;

// The CSV's rows, header first: section,key,name,loads,tonnes,loads_without_tonnes,cycles,avg_cycle_s,
// queue_s,spot_s,load_s,haul_s,dump_s,return_s,other_s (sections: shift, truck, shovel, dump).
QVector<QStringList> shiftCsvRows(const ProductionModel& model);
// Writes the CSV (comment lines first: shift start and end, plan); returns an error text or empty.
QString writeShiftCsv(const ProductionModel& model, const QString& file);
// Writes the PDF; returns an error text or empty. `map` may be null (no snapshot: said so on the page).
QString writeShiftPdf(const ProductionModel& model, const QImage& map, const QString& siteName,
                      const QString& file);
// The site map with the machines where they are now, framed to the content, as an image.
QImage renderSiteSnapshot(FleetModel* fleet, const SiteMapData& map, const QSize& size);

} // namespace ocu
