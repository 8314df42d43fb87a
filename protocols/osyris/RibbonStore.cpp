#include "protocols/osyris/RibbonStore.h"

#include "protocols/common/Log.h"

#include <sqlite3.h>

namespace ocu::osyris {

namespace {

Bytes encodeProps(const std::vector<PosProp>& props) {
    Bytes b;
    ByteWriter w(b);
    for (auto& p : props) {
        w.u32(p.value);
        w.u32(p.id);
    }
    return b;
}

std::vector<PosProp> decodeProps(ByteSpan s) {
    std::vector<PosProp> out;
    ByteReader r(s);
    while (r.remaining() >= kPosPropSize) {
        PosProp p;
        p.value = r.u32();
        p.id = r.u32();
        out.push_back(p);
    }
    return out;
}

bool exec(sqlite3* db, const char* sql, std::string& err) {
    char* msg = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &msg) != SQLITE_OK) {
        err = msg ? msg : "unknown error";
        sqlite3_free(msg);
        return false;
    }
    return true;
}

} // namespace

std::unique_ptr<RibbonStore> RibbonStore::inMemory() {
    return std::unique_ptr<RibbonStore>(new RibbonStore());
}

Result<std::unique_ptr<RibbonStore>> RibbonStore::open(const std::string& path) {
    auto store = inMemory();
    if (path.empty() || path == ":memory:")
        return store;
    store->m_path = path;
    auto fail = [&](const std::string& what) -> Result<std::unique_ptr<RibbonStore>> {
        std::string msg = "ribbon store " + path + ": " + what;
        return makeError(msg);
    };
    if (sqlite3_open_v2(path.c_str(), &store->m_db,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK)
        return fail(store->m_db ? sqlite3_errmsg(store->m_db) : "cannot open");
    sqlite3_busy_timeout(store->m_db, 2000);
    std::string err;
    // WAL + synchronous=FULL: a committed transaction survives an application or OS crash.
    if (!exec(store->m_db, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;", err) ||
        !exec(store->m_db,
              "CREATE TABLE IF NOT EXISTS ribbon_pos(idx INTEGER NOT NULL, slot INTEGER NOT NULL, pos BLOB "
              "NOT NULL,"
              " props BLOB, PRIMARY KEY(idx, slot)) WITHOUT ROWID;",
              err))
        return fail(err);
    sqlite3_stmt* sel = nullptr;
    if (sqlite3_prepare_v2(store->m_db, "SELECT idx, slot, pos, props FROM ribbon_pos", -1, &sel, nullptr) !=
        SQLITE_OK)
        return fail(sqlite3_errmsg(store->m_db));
    std::uint64_t bad = 0;
    while (sqlite3_step(sel) == SQLITE_ROW) {
        int idx = sqlite3_column_int(sel, 0);
        auto* blob = static_cast<const std::uint8_t*>(sqlite3_column_blob(sel, 2));
        int n = sqlite3_column_bytes(sel, 2);
        if (idx < 0 || idx >= kIdxNobody || !blob || n != static_cast<int>(kPosBodySize)) {
            ++bad;
            continue;
        }
        ByteReader r(ByteSpan(blob, static_cast<std::size_t>(n)));
        PositionRecord rec;
        rec.pos = decodePosBody(r);
        if (auto* pb = static_cast<const std::uint8_t*>(sqlite3_column_blob(sel, 3)))
            rec.props = decodeProps(ByteSpan(pb, static_cast<std::size_t>(sqlite3_column_bytes(sel, 3))));
        auto u = static_cast<std::uint8_t>(idx);
        store->m_held[u].insert(rec.pos.slot);
        store->m_ribbons[u].emplace(rec.pos.slot, std::move(rec));
    }
    sqlite3_finalize(sel);
    if (bad)
        logWarning("osyris", "ribbon store " + path + ": skipped " + std::to_string(bad) + " malformed rows");
    if (sqlite3_prepare_v2(store->m_db,
                           "INSERT OR IGNORE INTO ribbon_pos(idx, slot, pos, props) VALUES(?,?,?,?)", -1,
                           &store->m_insert, nullptr) != SQLITE_OK ||
        sqlite3_prepare_v2(store->m_db, "UPDATE ribbon_pos SET props=? WHERE idx=? AND slot=?", -1,
                           &store->m_update, nullptr) != SQLITE_OK)
        return fail(sqlite3_errmsg(store->m_db));
    return store;
}

RibbonStore::~RibbonStore() {
    if (m_db) {
        commit();
        sqlite3_finalize(m_insert);
        sqlite3_finalize(m_update);
        sqlite3_close(m_db);
    }
}

void RibbonStore::beginIfNeeded() {
    if (!m_db || m_inTransaction)
        return;
    std::string err;
    if (exec(m_db, "BEGIN", err))
        m_inTransaction = true;
    else
        logWarning("osyris", "ribbon store " + m_path + ": BEGIN failed: " + err);
}

void RibbonStore::commit() {
    std::lock_guard lock(m_mutex);
    if (!m_db || !m_inTransaction)
        return;
    std::string err;
    if (!exec(m_db, "COMMIT", err))
        logWarning("osyris", "ribbon store " + m_path + ": COMMIT failed: " + err);
    m_inTransaction = false;
}

bool RibbonStore::put(std::uint8_t idx, const PositionRecord& rec) {
    std::lock_guard lock(m_mutex);
    auto& rib = m_ribbons[idx];
    auto [it, inserted] = rib.emplace(rec.pos.slot, rec);
    if (!inserted)
        return false;
    m_held[idx].insert(rec.pos.slot);
    if (m_db) {
        beginIfNeeded();
        Bytes body;
        ByteWriter w(body);
        encodePosBody(w, rec.pos);
        Bytes props = encodeProps(rec.props);
        sqlite3_bind_int(m_insert, 1, idx);
        sqlite3_bind_int64(m_insert, 2, rec.pos.slot);
        sqlite3_bind_blob(m_insert, 3, body.data(), static_cast<int>(body.size()), SQLITE_TRANSIENT);
        if (props.empty())
            sqlite3_bind_null(m_insert, 4);
        else
            sqlite3_bind_blob(m_insert, 4, props.data(), static_cast<int>(props.size()), SQLITE_TRANSIENT);
        if (sqlite3_step(m_insert) != SQLITE_DONE)
            logWarning("osyris", "ribbon store " + m_path + ": insert failed: " + sqlite3_errmsg(m_db));
        sqlite3_reset(m_insert);
    }
    return true;
}

bool RibbonStore::addProps(std::uint8_t idx, std::uint32_t slot, const std::vector<PosProp>& props) {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    if (r == m_ribbons.end())
        return false;
    auto it = r->second.find(slot);
    if (it == r->second.end() || !it->second.props.empty() || props.empty())
        return false;
    it->second.props = props;
    if (m_db) {
        beginIfNeeded();
        Bytes b = encodeProps(props);
        sqlite3_bind_blob(m_update, 1, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
        sqlite3_bind_int(m_update, 2, idx);
        sqlite3_bind_int64(m_update, 3, slot);
        if (sqlite3_step(m_update) != SQLITE_DONE)
            logWarning("osyris", "ribbon store " + m_path + ": update failed: " + sqlite3_errmsg(m_db));
        sqlite3_reset(m_update);
    }
    return true;
}

bool RibbonStore::has(std::uint8_t idx, std::uint32_t slot) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    return h != m_held.end() && h->second.contains(slot);
}

std::optional<PositionRecord> RibbonStore::get(std::uint8_t idx, std::uint32_t slot) const {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    if (r == m_ribbons.end())
        return std::nullopt;
    auto it = r->second.find(slot);
    if (it == r->second.end())
        return std::nullopt;
    return it->second;
}

std::optional<PositionRecord> RibbonStore::newest(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    if (r == m_ribbons.end() || r->second.empty())
        return std::nullopt;
    return std::prev(r->second.end())->second;
}

IntervalSet RibbonStore::held(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto h = m_held.find(idx);
    return h == m_held.end() ? IntervalSet{} : h->second;
}

std::uint64_t RibbonStore::count(std::uint8_t idx) const {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    return r == m_ribbons.end() ? 0 : r->second.size();
}

std::uint64_t RibbonStore::totalCount() const {
    std::lock_guard lock(m_mutex);
    std::uint64_t n = 0;
    for (auto& [i, r] : m_ribbons)
        n += r.size();
    return n;
}

std::vector<std::uint8_t> RibbonStore::machines() const {
    std::lock_guard lock(m_mutex);
    std::vector<std::uint8_t> out;
    for (auto& [i, r] : m_ribbons)
        if (!r.empty())
            out.push_back(i);
    return out;
}

std::uint32_t RibbonStore::forEachConsecutive(std::uint8_t idx, std::uint32_t slot,
                                              const std::function<bool(const PositionRecord&)>& fn) const {
    std::lock_guard lock(m_mutex);
    auto r = m_ribbons.find(idx);
    if (r == m_ribbons.end())
        return slot;
    auto it = r->second.find(slot);
    while (it != r->second.end() && it->first == slot) {
        if (!fn(it->second))
            break;
        ++it;
        ++slot;
        if (slot == 0)
            break; // wrapped: end of the slot space
    }
    return slot;
}

} // namespace ocu::osyris
