#include "models/recording/PassCountLog.h"

#include <QtEndian>

#include <cstring>

namespace ocu::recording {

namespace {

constexpr int kGridHeader = 3 * 8 + 6 * 4;
constexpr qint64 kMaxCells = qint64(64) * 1024 * 1024; // 128 MB of counts: far beyond any site

template <class T> void putLe(QByteArray& out, T v) {
    char b[sizeof(T)];
    if constexpr (std::is_same_v<T, double>) {
        quint64 u;
        std::memcpy(&u, &v, 8);
        qToLittleEndian(u, b);
    } else {
        qToLittleEndian(v, b);
    }
    out.append(b, sizeof(T));
}

template <class T> T get(const char*& p) {
    T v;
    if constexpr (std::is_same_v<T, double>) {
        const quint64 u = qFromLittleEndian<quint64>(p);
        std::memcpy(&v, &u, 8);
    } else {
        v = qFromLittleEndian<T>(p);
    }
    p += sizeof(T);
    return v;
}

} // namespace

QByteArray encodePassCounts(const PassCountChange& c) {
    QByteArray out;
    out.reserve(kGridHeader + qsizetype(c.counts.size()) * 2);
    putLe<double>(out, c.origin.x());
    putLe<double>(out, c.origin.y());
    putLe<double>(out, c.cellSize);
    putLe<qint32>(out, c.columns);
    putLe<qint32>(out, c.rows);
    putLe<qint32>(out, c.cells.x());
    putLe<qint32>(out, c.cells.y());
    putLe<qint32>(out, c.cells.width());
    putLe<qint32>(out, c.cells.height());
    for (std::uint16_t v : c.counts)
        putLe<quint16>(out, v);
    return out;
}

bool decodePassCounts(const QByteArray& bytes, PassCountChange& out) {
    if (bytes.size() < kGridHeader)
        return false;
    const char* p = bytes.constData();
    const double ox = get<double>(p), oy = get<double>(p);
    out.origin = QPointF(ox, oy);
    out.cellSize = get<double>(p);
    out.columns = get<qint32>(p);
    out.rows = get<qint32>(p);
    const qint32 x = get<qint32>(p), y = get<qint32>(p), w = get<qint32>(p), h = get<qint32>(p);
    if (!(out.cellSize > 0) || out.columns < 0 || out.rows < 0 ||
        qint64(out.columns) * out.rows > kMaxCells || x < 0 || y < 0 || w < 0 || h < 0 ||
        qint64(x) + w > out.columns || qint64(y) + h > out.rows ||
        bytes.size() - kGridHeader != qint64(w) * h * 2)
        return false;
    out.cells = QRect(x, y, w, h);
    out.counts.resize(std::size_t(w) * std::size_t(h));
    for (auto& v : out.counts)
        v = get<quint16>(p);
    return true;
}

void ReplayPassCounts::apply(const PassCountChange& c) {
    if (!m_grid || !m_geometry.sameGrid(c)) {
        m_grid = std::make_unique<GridPassCountLayer>(c.origin, c.cellSize, c.columns, c.rows);
        m_geometry = c;
        m_geometry.counts.clear();
    }
    const QRect r = c.cells;
    std::size_t i = 0;
    for (int row = r.top(); row < r.top() + r.height(); ++row)
        for (int col = r.left(); col < r.left() + r.width(); ++col, ++i)
            if (m_grid->count(col, row) != c.counts[i])
                m_grid->setCount(col, row, c.counts[i]);
}

void ReplayPassCounts::clear() {
    m_grid.reset();
}

} // namespace ocu::recording
