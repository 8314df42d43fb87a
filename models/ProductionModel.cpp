#include "models/ProductionModel.h"

#include <algorithm>

namespace ocu {

namespace {
constexpr qint64 kDefaultShiftMs = 12LL * 3600 * 1000;
} // namespace

CycleBreakdown::Part CycleBreakdown::partOf(const QString& s) {
    if (s == QLatin1String("Queued"))
        return Queue;
    if (s == QLatin1String("Spotting"))
        return Spot;
    if (s == QLatin1String("Loading"))
        return Load;
    if (s == QLatin1String("Hauling"))
        return Haul;
    if (s == QLatin1String("Dumping"))
        return Dump;
    if (s == QLatin1String("Driving")) // empty, back to a shovel
        return Return;
    return Other; // Stopped, Parked, Off, unknown states
}

QString CycleBreakdown::partName(Part p) {
    static const char* names[PartCount] = {"queue", "spot", "load", "haul", "dump", "return", "other"};
    return QString::fromLatin1(names[p]);
}

void CycleBreakdown::add(const QVector<ProductionStatePeriod>& periods) {
    for (const auto& p : periods)
        if (p.seconds && *p.seconds >= 0)
            seconds[partOf(p.state)] += *p.seconds;
    ++cycles;
}

double CycleBreakdown::total() const {
    double t = 0;
    for (double s : seconds)
        t += s;
    return t;
}

ProductionModel::ProductionModel(QObject* parent) : QObject(parent) {
    m_shiftStart = nowMs();
    m_shiftEnd = m_shiftStart + kDefaultShiftMs;
    m_shift.key = QStringLiteral("shift");
    m_shift.name = tr("Shift");
}

void ProductionModel::setShift(qint64 startUnixMs, qint64 endUnixMs) {
    m_shiftStart = startUnixMs;
    m_shiftEnd = std::max(endUnixMs, startUnixMs + 1);
    emit changed();
}

void ProductionModel::setPlanTonnes(double tonnesPerShift) {
    m_planTonnes = std::max(0.0, tonnesPerShift);
    emit changed();
}

double ProductionModel::plannedTonnesAt(qint64 unixMs) const {
    if (unixMs <= m_shiftStart)
        return 0;
    if (unixMs >= m_shiftEnd)
        return m_planTonnes;
    return m_planTonnes * static_cast<double>(unixMs - m_shiftStart) /
           static_cast<double>(m_shiftEnd - m_shiftStart);
}

void ProductionModel::setAreaName(qint64 wayId, const QString& name) {
    if (name.isEmpty() || m_areaNames.value(wayId) == name)
        return;
    m_areaNames.insert(wayId, name);
    const QString key = QString::number(wayId);
    if (m_shovels.contains(key))
        m_shovels[key].name = name;
    if (m_dumps.contains(key))
        m_dumps[key].name = name;
    emit changed();
}

QString ProductionModel::areaName(qint64 wayId) const {
    return m_areaNames.value(wayId, tr("way %1").arg(wayId));
}

ProductionTally& ProductionModel::tally(QHash<QString, ProductionTally>& in, const QString& key,
                                        const QString& name) {
    auto it = in.find(key);
    if (it == in.end()) {
        ProductionTally t;
        t.key = key;
        t.name = name;
        it = in.insert(key, t);
    }
    return *it;
}

void ProductionModel::countLoad(const ProductionReport& r, TruckState& t, std::optional<qint64> loadWay,
                                std::optional<qint64> dumpWay, std::optional<double> tonnes) {
    auto add = [&](ProductionTally& x) {
        ++x.loads;
        if (tonnes)
            x.tonnes += *tonnes;
        else
            ++x.loadsWithoutTonnes;
    };
    add(m_shift);
    add(tally(m_trucks, r.truckId, t.name));
    add(loadWay ? tally(m_shovels, QString::number(*loadWay), areaName(*loadWay))
                : tally(m_shovels, QStringLiteral("unknown"), tr("unknown shovel")));
    add(dumpWay ? tally(m_dumps, QString::number(*dumpWay), areaName(*dumpWay))
                : tally(m_dumps, QStringLiteral("unknown"), tr("unknown dump")));
    // The series stays in time order even when a late report comes in.
    const qint64 at = r.unixMs;
    auto pos = std::upper_bound(m_tonnesSeries.begin(), m_tonnesSeries.end(), double(at),
                                [](double x, const QPointF& p) { return x < p.x(); });
    const auto i = pos - m_tonnesSeries.begin();
    const double before = i > 0 ? m_tonnesSeries[i - 1].y() : 0;
    const double loadsBefore = i > 0 ? m_loadsSeries[i - 1].y() : 0;
    m_tonnesSeries.insert(i, QPointF(double(at), before + tonnes.value_or(0)));
    m_loadsSeries.insert(i, QPointF(double(at), loadsBefore + 1));
    for (auto k = i + 1; k < m_tonnesSeries.size(); ++k) {
        m_tonnesSeries[k].ry() += tonnes.value_or(0);
        m_loadsSeries[k].ry() += 1;
    }
    t.loadedTonnes.reset();
    t.lastDumpUnknownShovel = !loadWay;
    t.lastDumpTonnes = tonnes;
}

void ProductionModel::addReport(const ProductionReport& r) {
    TruckState& t = m_truckStates[r.truckId];
    t.name = r.truckName.isEmpty() ? r.truckId : r.truckName;
    if (r.unixMs < m_shiftStart) {
        ++m_ignored;
        return;
    }
    ++m_counted;
    switch (r.kind) {
    case ProductionReport::Kind::State:
        if (r.state == QLatin1String("Loading") && r.wayId)
            t.lastLoadingWay = r.wayId;
        return; // the states only attribute loads; their times come with the cycle
    case ProductionReport::Kind::Payload:
        t.loadedTonnes = r.tonnes;
        t.loaderId = r.loaderId;
        return;
    case ProductionReport::Kind::Dump:
        countLoad(r, t, t.lastLoadingWay, r.dumpWayId, r.tonnes ? r.tonnes : t.loadedTonnes);
        ++t.dumpsSinceCycle;
        break;
    case ProductionReport::Kind::Cycle: {
        if (t.dumpsSinceCycle == 0) { // no dump reported for this cycle: the cycle is the load
            countLoad(r, t, r.loadWayId ? r.loadWayId : t.lastLoadingWay, r.dumpWayId,
                      r.tonnes ? r.tonnes : t.loadedTonnes);
        } else if (t.lastDumpUnknownShovel && r.loadWayId) {
            // The dump before went to the unknown shovel: the cycle says which it was.
            auto move = [&](ProductionTally& x, int sign) {
                x.loads += sign;
                if (t.lastDumpTonnes)
                    x.tonnes += sign * *t.lastDumpTonnes;
                else
                    x.loadsWithoutTonnes += sign;
            };
            move(tally(m_shovels, QStringLiteral("unknown"), tr("unknown shovel")), -1);
            move(tally(m_shovels, QString::number(*r.loadWayId), areaName(*r.loadWayId)), +1);
            if (m_shovels.value(QStringLiteral("unknown")).loads <= 0)
                m_shovels.remove(QStringLiteral("unknown"));
        }
        t.dumpsSinceCycle = 0;
        t.lastDumpUnknownShovel = false;
        bool loading = false, dumping = false;
        for (const auto& p : r.periods) {
            loading = loading || p.state == QLatin1String("Loading");
            dumping = dumping || p.state == QLatin1String("Dumping");
        }
        if (!loading || !dumping) { // seen in part only: attributes the load, stays out of the breakdown
            ++m_partialCycles;
            break;
        }
        m_shift.cycle.add(r.periods);
        tally(m_trucks, r.truckId, t.name).cycle.add(r.periods);
        if (r.loadWayId)
            tally(m_shovels, QString::number(*r.loadWayId), areaName(*r.loadWayId)).cycle.add(r.periods);
        if (r.dumpWayId)
            tally(m_dumps, QString::number(*r.dumpWayId), areaName(*r.dumpWayId)).cycle.add(r.periods);
        break;
    }
    }
    emit changed();
}

void ProductionModel::clear() {
    const qint64 length = m_shiftEnd - m_shiftStart;
    m_shiftStart = nowMs();
    m_shiftEnd = m_shiftStart + length;
    m_truckStates.clear();
    m_shift = ProductionTally{QStringLiteral("shift"), tr("Shift"), 0, 0, 0, {}};
    m_trucks.clear();
    m_shovels.clear();
    m_dumps.clear();
    m_tonnesSeries.clear();
    m_loadsSeries.clear();
    m_counted = m_ignored = m_partialCycles = 0;
    emit changed();
}

QVector<ProductionTally> ProductionModel::sorted(const QHash<QString, ProductionTally>& in) {
    QVector<ProductionTally> v(in.begin(), in.end());
    std::sort(v.begin(), v.end(), [](const ProductionTally& a, const ProductionTally& b) {
        return a.name == b.name ? a.key < b.key : a.name < b.name;
    });
    return v;
}

QVector<ProductionTally> ProductionModel::trucks() const {
    return sorted(m_trucks);
}

QVector<ProductionTally> ProductionModel::shovels() const {
    return sorted(m_shovels);
}

QVector<ProductionTally> ProductionModel::dumps() const {
    return sorted(m_dumps);
}

} // namespace ocu
