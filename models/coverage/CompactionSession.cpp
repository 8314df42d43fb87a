#include "models/coverage/CompactionSession.h"

#include "protocols/site/CrsTransform.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStandardPaths>

#include <cmath>

namespace ocu {

CompactionSession::CompactionSession(const CompactionConfig& config, const GeoFrame& siteFrame,
                                     QObject* parent)
    : CompactionView(parent), m_config(config), m_site(siteFrame) {
    for (const auto& a : m_config.areas) {
        CompactionArea area{QString::fromStdString(a.name), QString::fromStdString(a.source), {}};
        for (const auto& g : a.ring)
            area.ring.push_back(g);
        m_areas.push_back(area);
    }
    // Areas saved next to the user's data for a configuration that is not a writable file.
    QFile f(areasFile());
    if (areasFile() != QString::fromStdString(m_config.configFile) && f.open(QIODevice::ReadOnly)) {
        const QJsonArray arr =
            QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("areas")).toArray();
        for (const auto& v : arr) {
            const QJsonObject o = v.toObject();
            CompactionArea a{o.value(QStringLiteral("name")).toString(), QStringLiteral("drawn"), {}};
            for (const auto& p : o.value(QStringLiteral("points")).toArray()) {
                const QJsonArray ll = p.toArray();
                const double lat = ll.at(0).toDouble(1000), lon = ll.at(1).toDouble(1000);
                if (std::fabs(lat) <= 90 && std::fabs(lon) <= 180)
                    a.ring.push_back({lat, lon, 0});
            }
            if (!a.name.isEmpty() && a.ring.size() >= 3) {
                removeArea(a.name);
                m_areas.push_back(a);
            }
        }
    }
    rebuildGeometry();
}

CompactionSession::~CompactionSession() = default;

QString CompactionSession::loadDesign(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return tr("cannot open %1: %2").arg(path, f.errorString());
    const landxml::LandXmlLimits limits;
    if (f.size() > qint64(limits.maxBytes))
        return tr("%1 is larger than %2 MiB").arg(path).arg(limits.maxBytes >> 20);
    const QByteArray text = f.readAll();
    auto d = landxml::parseLandXml(std::string_view(text.constData(), std::size_t(text.size())), limits);
    if (!d)
        return tr("%1: %2").arg(path, QString::fromStdString(d.error()));
    m_designCrs.reset();
    if (d->epsg > 0) {
        auto t = CrsTransform::fromWgs84To(d->epsg);
        if (!t)
            return tr("%1: %2").arg(path, QString::fromStdString(t.error()));
        m_designCrs = std::make_unique<CrsTransform>(std::move(t.value()));
    }
    m_design = std::make_shared<const landxml::LandXmlDesign>(std::move(d.value()));
    m_designPath = path;
    // The design's boundaries as areas (replacing those of an earlier design).
    m_areas.erase(std::remove_if(m_areas.begin(), m_areas.end(),
                                 [](const CompactionArea& a) { return a.source == QLatin1String("design"); }),
                  m_areas.end());
    if (m_designCrs)
        for (const auto& b : m_design->boundaries) {
            CompactionArea a{QString::fromStdString(b.name), QStringLiteral("design"), {}};
            for (const auto& p : b.points) {
                double lat = 0, lon = 0;
                if (m_designCrs->toGeographic(p.e, p.n, lat, lon))
                    a.ring.push_back({lat, lon, 0});
            }
            if (a.ring.size() >= 3 && b.kind == "outer")
                m_areas.push_back(a);
        }
    rebuildGeometry();
    emit changed();
    return {};
}

QStringList CompactionSession::designWarnings() const {
    QStringList out;
    if (m_design)
        for (const auto& w : m_design->warnings)
            out << QString::fromStdString(w);
    if (m_design && !m_designCrs)
        out << tr(
            "the design names no EPSG code (CoordinateSystem/@epsgCode): it cannot be placed on the map");
    return out;
}

QString CompactionSession::addArea(const QString& name, const QPolygonF& siteEN) {
    const QString n = name.trimmed();
    if (n.isEmpty())
        return tr("an area needs a name");
    if (siteEN.size() < 3)
        return tr("an area needs at least 3 points");
    CompactionArea a{n, QStringLiteral("drawn"), {}};
    for (const QPointF& p : siteEN)
        a.ring.push_back(m_site.toGeodetic({p.x(), p.y(), 0}));
    removeArea(n);
    m_areas.push_back(a);
    rebuildGeometry();
    emit changed();
    return {};
}

bool CompactionSession::removeArea(const QString& name) {
    const auto before = m_areas.size();
    m_areas.erase(std::remove_if(m_areas.begin(), m_areas.end(),
                                 [&](const CompactionArea& a) { return a.name == name; }),
                  m_areas.end());
    if (m_areas.size() == before)
        return false;
    rebuildGeometry();
    emit changed();
    return true;
}

QString CompactionSession::areasFile() const {
    const QString cfg = QString::fromStdString(m_config.configFile);
    const QFileInfo fi(cfg);
    if (!cfg.isEmpty() && !cfg.startsWith(QLatin1Char(':')) && fi.exists() && fi.isWritable())
        return cfg;
    QString site = m_siteName.isEmpty() ? QStringLiteral("site") : m_siteName;
    site.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("-"));
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/compaction-areas-%1.json").arg(site);
}

QString CompactionSession::saveAreas() {
    QJsonArray arr;
    for (const CompactionArea& a : m_areas) {
        if (a.source != QLatin1String("drawn"))
            continue;
        QJsonArray pts;
        for (const GeoPoint& g : a.ring)
            pts << QJsonArray{g.lat, g.lon};
        arr << QJsonObject{{QStringLiteral("name"), a.name}, {QStringLiteral("points"), pts}};
    }
    const QString path = areasFile();
    QJsonObject root;
    const bool isConfig = path == QString::fromStdString(m_config.configFile);
    if (isConfig) {
        QFile in(path);
        if (!in.open(QIODevice::ReadOnly))
            return tr("cannot read %1: %2").arg(path, in.errorString());
        QJsonParseError e{};
        root = QJsonDocument::fromJson(in.readAll(), &e).object();
        if (e.error != QJsonParseError::NoError)
            return tr("%1 is not valid JSON (%2): areas not saved").arg(path, e.errorString());
        QJsonObject c = root.value(QStringLiteral("compaction")).toObject();
        c[QStringLiteral("areas")] = arr;
        root[QStringLiteral("compaction")] = c;
    } else {
        root[QStringLiteral("areas")] = arr;
        QDir().mkpath(QFileInfo(path).absolutePath());
    }
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly))
        return tr("cannot write %1: %2").arg(path, out.errorString());
    out.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
    if (!out.commit())
        return tr("cannot write %1: %2").arg(path, out.errorString());
    return {};
}

std::optional<QPointF> CompactionSession::designToSite(const landxml::PlanPoint& p) const {
    double lat = 0, lon = 0;
    if (!m_designCrs || !m_designCrs->toGeographic(p.e, p.n, lat, lon))
        return std::nullopt;
    const EnuPoint e = m_site.toLocal({lat, lon, m_site.origin().alt});
    return QPointF(e.e, e.n);
}

void CompactionSession::rebuildGeometry() {
    MapGeometry g;
    if (m_design && m_designCrs) {
        for (const auto& al : m_design->alignments) {
            QPolygonF line;
            for (const auto& p : al.polyline(10))
                if (auto q = designToSite(p))
                    line << *q;
            g.centreLines << line;
            const double first = std::ceil(al.staStart / kTickSpacing) * kTickSpacing;
            for (double s = first; s <= al.staEnd() + 1e-6 && g.ticks.size() < 100000; s += kTickSpacing) {
                auto l = al.pointAt(s, -3), r = al.pointAt(s, 3);
                std::optional<QPointF> ql, qr;
                if (l && r && (ql = designToSite(*l)) && (qr = designToSite(*r)))
                    g.ticks.push_back({*ql, *qr, s});
            }
        }
        for (const auto& b : m_design->boundaries) {
            QPolygonF poly;
            for (const auto& p : b.points)
                if (auto q = designToSite(p))
                    poly << *q;
            g.boundaries << poly;
        }
    }
    for (const CompactionArea& a : m_areas) {
        QPolygonF poly;
        for (const GeoPoint& p : a.ring) {
            const EnuPoint e = m_site.toLocal({p.lat, p.lon, m_site.origin().alt});
            poly << QPointF(e.e, e.n);
        }
        g.areas.push_back({a.name, poly});
        g.areaFromDesign.push_back(a.source == QLatin1String("design"));
    }
    m_geometry = std::move(g);
    m_stationBands.clear();
}

QString CompactionView::stationText(double station, int decimals) {
    return QString::fromStdString(landxml::formatStation(station, decimals));
}

CompactionView::DesignInfo CompactionSession::designInfo() const {
    DesignInfo d;
    if (!m_design)
        return d;
    d.loaded = true;
    d.path = m_designPath;
    d.alignments = int(m_design->alignments.size());
    d.boundaries = int(m_design->boundaries.size());
    d.warnings = designWarnings();
    return d;
}

static void figures(CompactionView::CoverageFigures& out, const osyris::CoverageStats& stats) {
    if (!stats.cells)
        return; // nothing of it is counted: no figures
    out.hasStats = true;
    out.coveragePercent = stats.coveragePercent();
    out.atTargetPercent = stats.percentOf(stats.atTarget);
    out.underPercent = stats.percentOf(stats.under);
    out.overPercent = stats.percentOf(stats.over);
    out.incompleteCells = stats.incomplete;
}

CompactionView::CoverageTable CompactionSession::coverageTable(int lift) const {
    const CoverageJob job = this->job();
    CoverageTable out;
    if (job.snapshot)
        for (int i = 0; i < job.snapshot->liftCount(); ++i)
            out.lifts.push_back({job.snapshot->liftBottom(i), job.snapshot->liftTop(i)});
    CoverageTables t;
    if (job.snapshot && m_haveWorksite) {
        CoverageFrames frames;
        if (frames.init(job).isEmpty())
            t = computeCoverageTables(job, frames, lift);
    }
    for (const CompactionArea& a : job.areas) {
        AreaRow row;
        row.name = a.name;
        row.fromDesign = a.source == QLatin1String("design");
        for (const AreaStats& x : t.areas)
            if (x.name == a.name)
                figures(row, x.stats);
        out.areas.push_back(row);
    }
    out.alignment = t.alignment;
    out.stationStep = job.stationStep > 0 ? job.stationStep : 20;
    out.bandLeft = job.bandLeft;
    out.bandRight = job.bandRight;
    const landxml::Alignment* al =
        m_design && !m_design->alignments.empty() ? &m_design->alignments.front() : nullptr;
    // The band of each range in the site frame, built like the statistics' (osyris::stationBandRing).
    const osyris::StationPointFn inSite = [&](double s, double off) -> std::optional<osyris::LocalPoint> {
        const auto p = al ? al->pointAt(s, off) : std::nullopt;
        const auto q = p ? designToSite(*p) : std::nullopt;
        if (!q)
            return std::nullopt;
        return osyris::LocalPoint{q->x(), q->y()};
    };
    for (const osyris::StationBin& b : t.stations) {
        StationRow row;
        row.from = b.from;
        row.to = b.to;
        figures(row, b.stats);
        auto band = m_stationBands.find({b.from, b.to});
        if (band == m_stationBands.end()) {
            QPolygonF ring;
            for (const auto& pt :
                 osyris::stationBandRing(inSite, b.from, b.to, job.bandLeft, job.bandRight, 2.0))
                ring << QPointF(pt.x, pt.y);
            band = m_stationBands.insert({b.from, b.to}, ring);
        }
        row.band = *band;
        out.stations.push_back(row);
    }
    return out;
}

CoverageJob CompactionSession::job() const {
    CoverageJob j;
    j.snapshot = m_snapshot ? m_snapshot() : nullptr;
    if (j.snapshot && j.snapshot->dataFromMs() > 0) { // the counted positions' time range (UTC)
        j.dataFrom = QDateTime::fromMSecsSinceEpoch(j.snapshot->dataFromMs(), Qt::UTC);
        j.dataTo = QDateTime::fromMSecsSinceEpoch(j.snapshot->dataToMs(), Qt::UTC);
    }
    j.worksiteOrigin = m_haveWorksite ? m_worksite : m_site.origin();
    j.design = m_design;
    j.designPath = m_designPath;
    j.areas = m_areas;
    j.machines = m_machines;
    j.siteName = m_siteName;
    j.stationStep = m_config.stationStep;
    j.bandLeft = m_config.bandLeft;
    j.bandRight = m_config.bandRight;
    j.epsg = m_config.epsg;
    return j;
}

QJsonObject CompactionSession::reportCommand(const QJsonObject& cmd) const {
    CoverageReportRequest r;
    r.pdf = cmd.value(QStringLiteral("pdf")).toString();
    r.csv = cmd.value(QStringLiteral("csv")).toString();
    r.geotiff = cmd.value(QStringLiteral("geotiff")).toString();
    r.area = cmd.value(QStringLiteral("area")).toString();
    const QJsonValue lift = cmd.value(QStringLiteral("lift"));
    if (lift.isString() && lift.toString() == QLatin1String("all"))
        r.lift = kAllLifts;
    else if (lift.isDouble())
        r.lift = lift.toInt(-1) >= 1 ? lift.toInt() - 1 : -1; // 1-based in the command, like the report
    if (!m_haveWorksite || !m_snapshot)
        return {
            {QStringLiteral("ok"), false},
            {QStringLiteral("message"), tr("no OSYRIS station in this console: no pass counts to report")},
            {QStringLiteral("written"), QJsonObject{{QStringLiteral("pdf"), false},
                                                    {QStringLiteral("csv"), false},
                                                    {QStringLiteral("geotiff"), false}}}};
    return writeCoverageReport(job(), r);
}

} // namespace ocu
