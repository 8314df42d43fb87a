#pragma once
// Production of the haul fleet over a shift, from what the trucks report (ProductionReport:
// production states, payloads, dumps, completed cycles): loads and tonnes per truck, per shovel (load area),
// per dump (dump area or crusher) and for the shift, the cycle-time breakdown (queue, spot, load, haul, dump,
// return) from the cycles' state times, and the tonnes over the shift against a plan. Nothing here comes from
// what the console asked for.
//
// Counting: a load is counted when the truck reports its dump (tonnes: DumpedWeight, else the payload it
// reported at loading, else unknown and counted as such), attributed to the truck, the dump area and the load
// area it was loaded at (the cycle's LoadWayId, else the way of its last Loading state). A completed cycle
// that no dump preceded counts as the load itself, and a cycle names the load area of the dump before it when
// the truck's Loading state was not seen. Only whole cycles (with Loading and Dumping among their states)
// enter the breakdown: a cycle the AHS saw only part of (it started mid-cycle) would distort the averages.
// Reports timed before the shift's start are not counted.
#include "models/ModelClock.h"
#include "models/ProductionReport.h"

#include <QHash>
#include <QObject>
#include <QPointF>
#include <QString>
#include <QVector>

namespace ocu {

// Seconds spent per part of the cycle, summed over `cycles` cycles.
struct CycleBreakdown {
    enum Part { Queue, Spot, Load, Haul, Dump, Return, Other, PartCount };
    double seconds[PartCount] = {};
    int cycles = 0;

    static Part partOf(const QString& productionState);
    static QString partName(Part p); // queue, spot, load, haul, dump, return, other
    void add(const QVector<ProductionStatePeriod>& periods);
    double total() const;
    double average(Part p) const { return cycles ? seconds[p] / cycles : 0; }
    double averageTotal() const { return cycles ? total() / cycles : 0; }
};

struct ProductionTally {
    QString key;  // truck id, or the area's way id as text; "shift" for the shift
    QString name; // HID, area name
    int loads = 0;
    double tonnes = 0;
    int loadsWithoutTonnes = 0; // dumps whose weight was not reported
    CycleBreakdown cycle;
};

class ProductionModel : public QObject {
    Q_OBJECT
public:
    explicit ProductionModel(QObject* parent = nullptr);

    // The shift: reports from `startUnixMs` on are counted; the plan is spread evenly over [start, end).
    void setShift(qint64 startUnixMs, qint64 endUnixMs);
    qint64 shiftStart() const { return m_shiftStart; }
    // The clock a new shift starts on (clear()) and the charts' "now" (null: the system clock).
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    qint64 nowMs() const { return m_clock->nowMs(); }
    qint64 shiftEnd() const { return m_shiftEnd; }
    void setPlanTonnes(double tonnesPerShift); // 0 = no plan
    double planTonnes() const { return m_planTonnes; }
    // The plan at a time of the shift (0 before it, the whole plan at and after its end).
    double plannedTonnesAt(qint64 unixMs) const;
    // Names of load and dump areas (way id -> name), e.g. from MapConnectivityV1.
    void setAreaName(qint64 wayId, const QString& name);
    QString areaName(qint64 wayId) const;

    const ProductionTally& shift() const { return m_shift; }
    QVector<ProductionTally> trucks() const;  // by name
    QVector<ProductionTally> shovels() const; // by name
    QVector<ProductionTally> dumps() const;   // by name
    // Cumulative tonnes and loads at each counted dump, in time order (x: ms since the Unix epoch).
    const QVector<QPointF>& tonnesOverShift() const { return m_tonnesSeries; }
    const QVector<QPointF>& loadsOverShift() const { return m_loadsSeries; }
    int reportsCounted() const { return m_counted; }
    int reportsIgnored() const { return m_ignored; }      // before the shift
    int partialCycles() const { return m_partialCycles; } // not in the breakdown
    // The site's name for the shift report.
    void setSiteName(const QString& name) { m_siteName = name; }
    QString siteName() const { return m_siteName; }

public slots:
    void addReport(const ocu::ProductionReport& report);
    // Starts a new shift now-empty (same length and plan).
    void clear();

signals:
    void changed();

private:
    struct TruckState {
        QString name;
        std::optional<qint64> lastLoadingWay; // the way of its last Loading state
        std::optional<double> loadedTonnes;   // the payload reported since its last dump
        QString loaderId;
        int dumpsSinceCycle = 0;
        // The last dump's load went to the unknown shovel (tonnes as counted): a cycle naming the load area
        // moves it there.
        bool lastDumpUnknownShovel = false;
        std::optional<double> lastDumpTonnes;
    };
    ProductionTally& tally(QHash<QString, ProductionTally>& in, const QString& key, const QString& name);
    void countLoad(const ProductionReport& r, TruckState& t, std::optional<qint64> loadWay,
                   std::optional<qint64> dumpWay, std::optional<double> tonnes);
    static QVector<ProductionTally> sorted(const QHash<QString, ProductionTally>& in);

    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    qint64 m_shiftStart = 0;
    qint64 m_shiftEnd = 0;
    double m_planTonnes = 0;
    QHash<qint64, QString> m_areaNames;
    QHash<QString, TruckState> m_truckStates;
    ProductionTally m_shift;
    QHash<QString, ProductionTally> m_trucks, m_shovels, m_dumps;
    QVector<QPointF> m_tonnesSeries, m_loadsSeries;
    int m_counted = 0;
    int m_ignored = 0;
    int m_partialCycles = 0;
    QString m_siteName;
};

} // namespace ocu
