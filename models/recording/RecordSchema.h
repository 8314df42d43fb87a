#pragma once
// The SQLite schema of a flight recording (docs/recording.md "Schema"). Times `t` are the console's receive
// times in ms since the Unix epoch (UTC), never going backwards within a file.
#include "models/SiteMapData.h"

#include <QByteArray>

namespace ocu::recording {

// 2: inbound messages (msg_channels, messages) replace the never-written `raw` table of 1; pass counts.
// 3: the `states` and `keyframes` blobs are qCompress'ed (meta states_codec = zlib); 1 and 2 still read.
// 4: compact record headers and Move records (fixed point) in columns, blobs compressed with zstd
//    (states_codec, messages_codec = zstd); decoded inbound messages only with record.messages; an index on
//    links. 1 to 3 still read. The `details` table (a protocol's own records, e.g. a UGV's mission) came
//    later within 4: a file without it has none.
constexpr int kSchemaVersion = 4;
constexpr int kLegacySchemaVersion = 3; // RecorderOptions::legacySchema3

inline constexpr const char* kSchemaSql = R"SQL(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT);
CREATE TABLE IF NOT EXISTS machines(idx INTEGER PRIMARY KEY, id TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS states(id INTEGER PRIMARY KEY, t0 INTEGER NOT NULL, t1 INTEGER NOT NULL,
                                  n INTEGER NOT NULL, data BLOB NOT NULL);
CREATE INDEX IF NOT EXISTS states_t1 ON states(t1);
CREATE TABLE IF NOT EXISTS keyframes(t INTEGER PRIMARY KEY, chunk INTEGER NOT NULL, n INTEGER NOT NULL,
                                     data BLOB NOT NULL);
CREATE TABLE IF NOT EXISTS events(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, time_ms INTEGER, severity INTEGER,
                                  kind INTEGER, machine TEXT, source TEXT, text TEXT, requires_ack INTEGER,
                                  key TEXT);
CREATE INDEX IF NOT EXISTS events_t ON events(t);
CREATE TABLE IF NOT EXISTS acks(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, key TEXT, by TEXT, at_ms INTEGER);
CREATE TABLE IF NOT EXISTS commands(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, origin TEXT, action TEXT,
                                    target TEXT, ok INTEGER, audit TEXT);
CREATE TABLE IF NOT EXISTS links(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, protocol TEXT, link TEXT,
                                 state INTEGER, age_ms INTEGER, detail TEXT);
CREATE INDEX IF NOT EXISTS links_key ON links(protocol, link, t);
CREATE TABLE IF NOT EXISTS sitemaps(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, data BLOB);
CREATE TABLE IF NOT EXISTS msg_channels(idx INTEGER PRIMARY KEY, protocol TEXT, link TEXT, peer TEXT, type TEXT);
CREATE TABLE IF NOT EXISTS messages(id INTEGER PRIMARY KEY, t0 INTEGER NOT NULL, t1 INTEGER NOT NULL,
                                    n INTEGER NOT NULL, data BLOB NOT NULL);
CREATE INDEX IF NOT EXISTS messages_t1 ON messages(t1);
CREATE TABLE IF NOT EXISTS passcounts(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, data BLOB NOT NULL);
CREATE TABLE IF NOT EXISTS details(id INTEGER PRIMARY KEY, t INTEGER NOT NULL, machine TEXT, kind TEXT,
                                   data BLOB);
CREATE INDEX IF NOT EXISTS details_t ON details(t);
)SQL";

// The site map as compact JSON ({"revision":..,"features":[{"id","name","kind","task","auto","width",
// "points":[e,n,e,n,...]}]}), and back (malformed input gives an empty map).
QByteArray siteMapToJson(const SiteMapData& map);
SiteMapData siteMapFromJson(const QByteArray& json);

} // namespace ocu::recording
