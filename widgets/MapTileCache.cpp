#include "widgets/MapTileCache.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <algorithm>

namespace ocu {

namespace {

const QString kMeta = QStringLiteral("meta.json");

QString tileName(int level, int tx, int ty) {
    return QStringLiteral("L%1_%2_%3.png").arg(level).arg(tx).arg(ty);
}

qint64 dirBytes(const QString& path) {
    qint64 n = 0;
    QDirIterator it(path, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        it.next();
        n += it.fileInfo().size();
    }
    return n;
}

} // namespace

MapTileCache::MapTileCache(QString dir, qint64 maxBytes) : m_dir(std::move(dir)), m_maxBytes(maxBytes) {}

QString MapTileCache::defaultDir() {
    if (qEnvironmentVariableIsSet("OCU_TILE_CACHE_DIR")) {
        const QString d = qEnvironmentVariable("OCU_TILE_CACHE_DIR");
        return d == QLatin1String("off") ? QString() : d;
    }
    const QString base = QStandardPaths::writableLocation(QStandardPaths::CacheLocation);
    return base.isEmpty() ? QString() : base + QStringLiteral("/map-tiles");
}

QString MapTileCache::keyFor(const QString& sourcePath, const GeoFrame& frame, int maxSidePx, int tilePx) {
    const QFileInfo fi(sourcePath);
    if (!fi.exists() || !fi.isFile())
        return {};
    const QString canonical = fi.canonicalFilePath();
    const QString id = QStringLiteral("v%1|%2|%3|%4|%5,%6,%7|%8|%9")
                           .arg(kFormatVersion)
                           .arg(canonical)
                           .arg(fi.size())
                           .arg(fi.lastModified().toMSecsSinceEpoch())
                           .arg(frame.origin().lat, 0, 'f', 10)
                           .arg(frame.origin().lon, 0, 'f', 10)
                           .arg(frame.origin().alt, 0, 'f', 3)
                           .arg(maxSidePx)
                           .arg(tilePx);
    return QString::fromLatin1(QCryptographicHash::hash(id.toUtf8(), QCryptographicHash::Sha1).toHex());
}

QString MapTileCache::entryPath(const QString& key) const {
    return m_dir + QLatin1Char('/') + key;
}

std::optional<MapTilePyramid> MapTileCache::load(const QString& key, int tilePx) const {
    if (m_dir.isEmpty() || key.isEmpty())
        return std::nullopt;
    const QString path = entryPath(key);
    QFile meta(path + QLatin1Char('/') + kMeta);
    if (!meta.exists())
        return std::nullopt;
    auto corrupt = [&]() -> std::optional<MapTilePyramid> {
        QDir(path).removeRecursively(); // warped again and rewritten by the caller
        return std::nullopt;
    };
    if (!meta.open(QIODevice::ReadOnly) || meta.size() > 1024 * 1024)
        return corrupt();
    QJsonParseError err{};
    const QJsonObject o = QJsonDocument::fromJson(meta.readAll(), &err).object();
    if (err.error != QJsonParseError::NoError ||
        o.value(QStringLiteral("version")).toInt() != kFormatVersion ||
        o.value(QStringLiteral("tile")).toInt() != tilePx)
        return corrupt();
    MapTilePyramid p;
    const QJsonArray b = o.value(QStringLiteral("bounds")).toArray();
    p.mpp = o.value(QStringLiteral("mpp")).toDouble();
    p.size = QSize(o.value(QStringLiteral("width")).toInt(), o.value(QStringLiteral("height")).toInt());
    if (b.size() != 4 || !(p.mpp > 0) || p.size.width() < 1 || p.size.height() < 1 ||
        p.size.width() > 65536 || p.size.height() > 65536)
        return corrupt();
    p.bounds = QRectF(b[0].toDouble(), b[1].toDouble(), b[2].toDouble(), b[3].toDouble());
    if (!(p.bounds.width() > 0 && p.bounds.height() > 0))
        return corrupt();
    const QJsonArray levels = o.value(QStringLiteral("levels")).toArray();
    if (levels.isEmpty() || levels.size() > 32)
        return corrupt();
    // Each level must have exactly the tiles its size implies (level k is level 0 halved k times).
    int w = p.size.width(), h = p.size.height();
    for (int li = 0; li < levels.size(); ++li) {
        const QJsonObject lo = levels[li].toObject();
        MapTileLevel L;
        L.mpp = lo.value(QStringLiteral("mpp")).toDouble();
        L.cols = lo.value(QStringLiteral("cols")).toInt();
        L.rows = lo.value(QStringLiteral("rows")).toInt();
        if (!(L.mpp > 0) || L.cols != (w + tilePx - 1) / tilePx || L.rows != (h + tilePx - 1) / tilePx)
            return corrupt();
        for (int ty = 0; ty < L.rows; ++ty)
            for (int tx = 0; tx < L.cols; ++tx) {
                QImage t(path + QLatin1Char('/') + tileName(li, tx, ty), "PNG");
                if (t.isNull() || t.size() != QSize(tilePx, tilePx))
                    return corrupt();
                L.tiles.push_back(t.convertToFormat(QImage::Format_ARGB32_Premultiplied));
            }
        p.levels.push_back(std::move(L));
        w = std::max(1, (w + 1) / 2);
        h = std::max(1, (h + 1) / 2);
    }
    meta.close();
    // Used now: the least recently used entries are trimmed first.
    if (meta.open(QIODevice::ReadWrite))
        meta.setFileTime(QDateTime::currentDateTimeUtc(), QFileDevice::FileModificationTime);
    return p;
}

bool MapTileCache::store(const QString& key, const MapTilePyramid& p, const QString& sourcePath) const {
    if (m_dir.isEmpty() || key.isEmpty() || p.levels.isEmpty())
        return false;
    if (!QDir().mkpath(m_dir))
        return false;
    const QString target = entryPath(key);
    const QString tmp =
        target + QStringLiteral(".tmp-%1").arg(QRandomGenerator::global()->generate64(), 0, 16);
    QDir tmpDir(tmp);
    if (!QDir().mkpath(tmp))
        return false;
    auto abandon = [&] {
        tmpDir.removeRecursively();
        return false;
    };
    QJsonArray levels;
    for (int li = 0; li < p.levels.size(); ++li) {
        const MapTileLevel& L = p.levels[li];
        for (int ty = 0; ty < L.rows; ++ty)
            for (int tx = 0; tx < L.cols; ++tx) {
                // Quality 80: light zlib compression, the write costs little next to the warp.
                if (!L.tiles[ty * L.cols + tx].save(tmp + QLatin1Char('/') + tileName(li, tx, ty), "PNG", 80))
                    return abandon();
            }
        levels.append(QJsonObject{{QStringLiteral("mpp"), L.mpp},
                                  {QStringLiteral("cols"), L.cols},
                                  {QStringLiteral("rows"), L.rows}});
    }
    const QJsonObject o{{QStringLiteral("version"), kFormatVersion},
                        {QStringLiteral("source"), sourcePath},
                        {QStringLiteral("tile"),
                         p.levels.front().tiles.isEmpty() ? 0 : p.levels.front().tiles.front().width()},
                        {QStringLiteral("bounds"),
                         QJsonArray{p.bounds.x(), p.bounds.y(), p.bounds.width(), p.bounds.height()}},
                        {QStringLiteral("mpp"), p.mpp},
                        {QStringLiteral("width"), p.size.width()},
                        {QStringLiteral("height"), p.size.height()},
                        {QStringLiteral("levels"), levels}};
    QFile meta(tmp + QLatin1Char('/') + kMeta);
    if (!meta.open(QIODevice::WriteOnly) || meta.write(QJsonDocument(o).toJson()) <= 0 || !meta.flush())
        return abandon();
    meta.close();
    QDir(target).removeRecursively(); // a corrupt or older entry of the same key
    if (!QDir().rename(tmp, target))
        return abandon(); // another console wrote it at the same moment: theirs stays
    trim();
    return true;
}

qint64 MapTileCache::trim() const {
    if (m_dir.isEmpty())
        return 0;
    struct Entry {
        QString path;
        qint64 bytes;
        QDateTime used;
    };
    QVector<Entry> entries;
    qint64 total = 0;
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QFileInfoList dirs = QDir(m_dir).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QFileInfo& d : dirs) {
        const QFileInfo meta(d.filePath() + QLatin1Char('/') + kMeta);
        if (d.fileName().contains(QStringLiteral(".tmp-"))) {
            // A write that died half-way (crash, power cut) an hour ago or more.
            if (d.lastModified().secsTo(now) > 3600)
                QDir(d.filePath()).removeRecursively();
            continue;
        }
        const qint64 bytes = dirBytes(d.filePath());
        entries.push_back({d.filePath(), bytes, meta.exists() ? meta.lastModified() : d.lastModified()});
        total += bytes;
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    for (const Entry& e : std::as_const(entries)) {
        if (total <= m_maxBytes)
            break;
        QDir(e.path).removeRecursively();
        total -= e.bytes;
    }
    return total;
}

} // namespace ocu
