// The coverage CSV: Veta-style tagged header, then one row per cell and lift in the report's projected CRS
// (docs/coverage-report.md).
#include "models/coverage/CoverageReportCommon.h"

#include <QSaveFile>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <vector>

namespace ocu {

using coverage::areaRing;
using coverage::findArea;
using coverage::liftName;
using coverage::num;
using coverage::ReportText;
using osyris::LocalRing;
using osyris::PassCountSnapshot;

namespace {

// The Veta tagged-data header items that apply to gridded pass counts (anchors-features.md §4.1), then the
// column names.
QByteArray csvHeader(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area) {
    const PassCountSnapshot& snap = *job.snapshot;
    const double cs = snap.cellSize();
    QByteArray head;
    auto tag = [&](const char* k, const QString& v) {
        head += "# ";
        head += k;
        head += ": ";
        head += v.toUtf8();
        head += '\n';
    };
    tag("data-lot-name", job.siteName.isEmpty() ? QStringLiteral("OCU coverage") : job.siteName);
    tag("gridding-width", num(cs, 3));
    tag("gridding-height", num(cs, 3));
    tag("gridding-process", QStringLiteral("gridded"));
    tag("machine-name", job.machines.join(QStringLiteral("; ")));
    tag("machine-type", QStringLiteral("compactor"));
    tag("spatial-reference-authority", QStringLiteral("EPSG"));
    tag("spatial-reference-id", QString::number(frames.epsg()));
    tag("spatial-reference-name", frames.crsName());
    tag("measurement-name", QStringLiteral("pass-count"));
    tag("target-passes", QStringLiteral("%1-%2").arg(snap.targetMin()).arg(snap.targetMax()));
    tag("lift", liftName(snap, lift));
    if (!area.isEmpty())
        tag("area", area);
    for (int i = 0; i < snap.liftCount(); ++i)
        tag(QStringLiteral("lift-%1").arg(i + 1).toUtf8().constData(), QStringLiteral("z %1 .. %2 m")
                                                                           .arg(snap.liftBottom(i), 0, 'f', 3)
                                                                           .arg(snap.liftTop(i), 0, 'f', 3));
    head += "easting,northing,lift,pass-count,target-status,incomplete,cell-x,cell-y\n";
    return head;
}

// The cells of a named area (by centre), as spans of rows; every cell when the ring is empty (no area).
class AreaCells {
public:
    AreaCells(const LocalRing& ring, double cellSize) : m_all(ring.empty()) {
        if (!m_all)
            osyris::rasterizeRings({ring}, cellSize, [&](std::int32_t cy, std::int32_t a, std::int32_t b) {
                m_spans.push_back({cy, a, b});
            });
    }
    bool contains(std::int32_t cx, std::int32_t cy) const {
        if (m_all)
            return true;
        auto it = std::lower_bound(m_spans.begin(), m_spans.end(), cy,
                                   [](const Span& s, std::int32_t y) { return s.cy < y; });
        for (; it != m_spans.end() && it->cy == cy; ++it)
            if (cx >= it->cx0 && cx <= it->cx1)
                return true;
        return false;
    }

private:
    struct Span {
        std::int32_t cy, cx0, cx1;
    };
    bool m_all;
    std::vector<Span> m_spans;
};

// The rows of the CSV, tile by tile of the top view (every cell with a count in any lift is in it): each
// cell's position goes through the geodetic position and PROJ once, then one row per lift asked for.
class CsvRows {
public:
    CsvRows(const PassCountSnapshot& snap, const CoverageFrames& frames, int lift, const AreaCells& area)
        : m_snap(snap), m_frames(frames), m_area(area), m_cs(snap.cellSize()) {
        if (lift == kAllLifts)
            for (int i = 0; i < snap.liftCount(); ++i)
                m_lifts.push_back(i);
        else
            m_lifts.push_back(lift);
        m_top = m_lifts.size() == 1 && (m_lifts[0] < 0 || m_lifts[0] >= snap.liftCount());
        m_liftTiles.resize(m_lifts.size());
        for (int l : m_lifts)
            m_liftNo.push_back(l < 0 || l >= snap.liftCount() ? QByteArray("top")
                                                              : QByteArray::number(l + 1));
    }

    // The rows of one tile of the top view into block() (empty when it has none); false when PROJ failed.
    bool tile(const PassCountSnapshot::Entry& e) {
        m_block.clear();
        if (!selectCells(e))
            return true;
        const std::int32_t x0 = e.tx * osyris::kTileSize, y0 = e.ty * osyris::kTileSize;
        if (!project(x0, y0))
            return false;
        writeRows(x0, y0);
        return true;
    }
    const QByteArray& block() const { return m_block; }
    qint64 rows() const { return m_rows; }

private:
    const osyris::PassCountTile* findTile(int l, std::int32_t tx, std::int32_t ty) const {
        const auto& v = m_snap.tiles(l);
        auto it = std::lower_bound(v.begin(), v.end(), std::pair{ty, tx}, [](const auto& e, const auto& k) {
            return std::pair{e.ty, e.tx} < k;
        });
        return it != v.end() && it->tx == tx && it->ty == ty ? it->tile.get() : nullptr;
    }

    // The cells of this tile that get a row (a count in a lift asked for, or incomplete in the top view, and
    // in the area) into m_idx; false when there are none.
    bool selectCells(const PassCountSnapshot::Entry& e) {
        bool any = false;
        for (std::size_t k = 0; k < m_lifts.size(); ++k) {
            m_liftTiles[k] = m_top ? e.tile.get() : findTile(m_lifts[k], e.tx, e.ty);
            any = any || m_liftTiles[k];
        }
        if (!any)
            return false;
        m_flags =
            m_snap.anyIncomplete() ? static_cast<const osyris::PassCountTopTile*>(e.tile.get()) : nullptr;
        m_idx.clear();
        const std::int32_t x0 = e.tx * osyris::kTileSize, y0 = e.ty * osyris::kTileSize;
        for (int i = 0; i < osyris::kTileCells; ++i) {
            bool has = m_flags && m_top && (m_flags->flags[std::size_t(i)] & osyris::kCellIncomplete);
            for (std::size_t k = 0; k < m_lifts.size() && !has; ++k)
                has = m_liftTiles[k] && m_liftTiles[k]->counts[std::size_t(i)] > 0;
            if (has && m_area.contains(x0 + (i & (osyris::kTileSize - 1)), y0 + (i >> osyris::kTileBits)))
                m_idx.push_back(i);
        }
        return !m_idx.empty();
    }

    // The selected cells' centres to easting/northing, in one PROJ call.
    bool project(std::int32_t x0, std::int32_t y0) {
        const std::size_t n = m_idx.size();
        m_xs.resize(n);
        m_ys.resize(n);
        m_es.resize(n);
        m_ns.resize(n);
        m_lats.resize(n);
        m_lons.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            m_xs[k] = (x0 + (m_idx[k] & (osyris::kTileSize - 1)) + 0.5) * m_cs;
            m_ys[k] = (y0 + (m_idx[k] >> osyris::kTileBits) + 0.5) * m_cs;
        }
        return m_frames.localToProjected(m_xs.data(), m_ys.data(), n, m_es.data(), m_ns.data(), m_lats.data(),
                                         m_lons.data());
    }

    void writeRows(std::int32_t x0, std::int32_t y0) {
        for (std::size_t k = 0; k < m_idx.size(); ++k) {
            const int i = m_idx[k];
            const bool inc = m_flags && (m_flags->flags[std::size_t(i)] & osyris::kCellIncomplete);
            for (std::size_t l = 0; l < m_lifts.size(); ++l) {
                const int c = m_liftTiles[l] ? m_liftTiles[l]->counts[std::size_t(i)] : 0;
                if (c == 0 && !(m_top && inc))
                    continue;
                const char* status = c == 0                    ? "none"
                                     : c < m_snap.targetMin()  ? "under"
                                     : c <= m_snap.targetMax() ? "at"
                                                               : "over";
                put(m_es[k], 4);
                m_block.append(',');
                put(m_ns[k], 4);
                m_block.append(',');
                m_block.append(m_liftNo[l]);
                m_block.append(',');
                putInt(c);
                m_block.append(',');
                m_block.append(status);
                m_block.append(inc ? ",1," : ",0,");
                putInt(x0 + (i & (osyris::kTileSize - 1)));
                m_block.append(',');
                putInt(y0 + (i >> osyris::kTileBits));
                m_block.append('\n');
                ++m_rows;
            }
        }
    }

    void put(double v, int prec) {
        auto [end, ec] = std::to_chars(m_num, m_num + sizeof m_num, v, std::chars_format::fixed, prec);
        m_block.append(m_num, int(end - m_num));
    }
    void putInt(long long v) {
        auto [end, ec] = std::to_chars(m_num, m_num + sizeof m_num, v);
        m_block.append(m_num, int(end - m_num));
    }

    const PassCountSnapshot& m_snap;
    const CoverageFrames& m_frames;
    const AreaCells& m_area;
    const double m_cs;
    std::vector<int> m_lifts;
    bool m_top = false;
    std::vector<QByteArray> m_liftNo;
    std::vector<const osyris::PassCountTile*> m_liftTiles;
    const osyris::PassCountTopTile* m_flags = nullptr;
    std::vector<int> m_idx;
    std::vector<double> m_xs, m_ys, m_es, m_ns, m_lats, m_lons;
    QByteArray m_block;
    char m_num[64];
    qint64 m_rows = 0;
};

} // namespace

QString writeCoverageCsv(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         const QString& path, qint64* rowsOut) {
    if (!job.snapshot)
        return ReportText::tr("no pass counts yet");
    const PassCountSnapshot& snap = *job.snapshot;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    LocalRing ring;
    if (!area.isEmpty()) {
        const CompactionArea* a = findArea(job, area);
        if (!a)
            return ReportText::tr("no area named \"%1\"").arg(area);
        ring = areaRing(frames, *a);
    }
    f.write(csvHeader(job, frames, lift, area));
    const AreaCells cells(ring, snap.cellSize());
    CsvRows rows(snap, frames, lift, cells);
    for (const auto& e : snap.tiles(-1)) {
        if (!rows.tile(e))
            return ReportText::tr("PROJ could not convert a cell to EPSG:%1").arg(frames.epsg());
        if (!rows.block().isEmpty() && f.write(rows.block()) != rows.block().size())
            return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    }
    if (!f.commit())
        return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    if (rowsOut)
        *rowsOut = rows.rows();
    return {};
}

} // namespace ocu
