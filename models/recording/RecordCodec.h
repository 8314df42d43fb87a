#pragma once
// Binary encoding of machine-state records in a flight recording (docs/recording.md "Schema"). A chunk is
// one BLOB of the `states` table: records back to back, each with a header (type, machine index into the
// `machines` table, time offset from the chunk's t0 in ms) and a body:
//   Full     every field of MachineState (doubles exact, strings UTF-8): the first record of a machine and
//            whenever anything but the moving part (position, heading, speed, times) changed;
//   Position e/n/u in mm (int32), lat/lon as doubles, heading/speed as floats, lastDataMs (delta to the
//            record time) and lastMessageMs (delta to lastDataMs); applied onto the machine's last Full;
//   Delta    (schema 3) a Position as differences to the machine's state before it: e/n/u mm and the data
//            and message time deltas as zigzag varints, lat/lon/heading/speed as varints of the XOR of
//            their bits with the previous ones (exact, and short when they changed little);
//   Removed  the machine left the fleet model.
//   Move     (schema 4) the moving part in fixed point (ENU 1 cm, heading 0.01 deg, speed 0.01 m/s,
//            lat/lon 1e-7 deg or derived from ENU through the site frame) as varint differences to the
//            machine's previous sample; e/n (and explicit lat/lon) predicted from the machine's previous step
//            within the chunk, so a steady drive costs about a byte per coordinate before compression.
// Schema 1-3 chunks: records with a fixed-width header. Schema 4 chunks: columns - the record headers (type,
// the machine index and the time as varint differences to the record before) with the Full bodies, then one
// column per Move field (u8 column count, varint column lengths, the columns): the compressor sees runs of
// equal bytes and each field's small differences together.
// Decoding checks every length (a truncated or hostile blob ends the chunk with an error, never reads past
// it).
#include "models/MachineState.h"
#include "protocols/common/GeoFrame.h"

#include <QByteArray>
#include <QHash>
#include <QSet>
#include <QString>

#include <cstdint>
#include <functional>

namespace ocu::recording {

enum class RecordType : std::uint8_t {
    Full = 1,
    Position = 2,
    Removed = 3,
    Delta = 4,
    Move = 5,        // lat/lon derived from e/n/u through the site frame
    MoveGeodetic = 6 // lat/lon carried (they do not follow e/n/u in the site frame)
};

// The resolution of a Move record (docs/recording.md): what a replay of a schema 4 file reproduces.
inline constexpr double kMoveMetre = 100;            // 1 cm
inline constexpr double kMoveDegree = 100;           // heading 0.01 deg
inline constexpr double kMoveSpeed = 100;            // 0.01 m/s
inline constexpr double kMoveGeodetic = 1e7;         // lat/lon 1e-7 deg (about 1.1 cm)
inline constexpr double kDerivedGeoTolerance = 1e-7; // deg: lat/lon derived from ENU when this close

// Everything but the moving part is equal (a Position record suffices).
bool sameStatus(const MachineState& a, const MachineState& b);
// A Position record can carry b exactly enough (positions within 1 mm, the local frame within +-2,000 km).
bool positionEncodable(const MachineState& s);

void appendFull(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, const MachineState& s);
void appendPosition(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, qint64 tMs, const MachineState& s);
// s's moving part relative to `base` (the machine as the file holds it before this record: a Full or a
// base after applyPosition); both must be positionEncodable. Decodes like appendPosition (visited as
// RecordType::Position).
void appendDelta(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, qint64 tMs, const MachineState& base,
                 const MachineState& s);
// base's moving part becomes in's as a Position record written at tMs decodes (quantised).
void applyPosition(MachineState& base, const MachineState& in, qint64 tMs);
void appendRemoved(QByteArray& out, std::uint32_t idx, std::int32_t dtMs);

// One decoded record; `state` is valid for Full, and for Position after it was applied to the base.
struct DecodedRecord {
    RecordType type = RecordType::Full;
    std::uint32_t idx = 0;
    qint64 tMs = 0;
};

// Schema 4: writes one chunk's records. Machines' previous steps are remembered within the chunk only, so
// every chunk decodes from the picture before it (a keyframe and the chunks after it) and nothing else.
class ChunkEncoder {
public:
    // frame: the site frame the fleet's e/n/u are in (lat/lon of a Move are derived through it when they
    // agree within kDerivedGeoTolerance); nullptr: lat/lon always carried.
    explicit ChunkEncoder(const GeoFrame* frame) : m_frame(frame) {}
    void begin(qint64 t0);
    bool empty() const { return m_cols[0].isEmpty(); }
    QByteArray data() const; // the chunk's blob (before compression)
    qint64 t0() const { return m_t0; }
    void full(std::uint32_t idx, qint64 tMs, const MachineState& s);
    void removed(std::uint32_t idx, qint64 tMs);
    // s's moving part against `base` (the machine as the file holds it; sameStatus(base, s)); `base` becomes
    // what a replay decodes. False (nothing written) when the values do not fit a Move: write a Full.
    bool move(std::uint32_t idx, qint64 tMs, MachineState& base, const MachineState& s);

    static constexpr int columns() { return kColumns; }
    struct Track {
        std::int64_t ve = 0, vn = 0, vlat = 0, vlon = 0; // the machine's previous step in this chunk
        std::int64_t dataOffset = 0, messageOffset = 0;
        bool moved = false, geodetic = false;
    };

private:
    void header(RecordType type, std::uint32_t idx, qint64 tMs);
    const GeoFrame* m_frame;
    // 0: headers and Full bodies; 1-9: a Move's e, n, u, heading, speed, data time, message time, lat, lon.
    static constexpr int kColumns = 10;
    QByteArray m_cols[kColumns];
    qint64 m_t0 = 0, m_prevT = 0;
    std::uint32_t m_prevIdx = 0;
    QHash<std::uint32_t, Track> m_tracks;
};

enum class ChunkFormat : std::uint8_t { Fixed, Compact };

struct DecodeOptions {
    ChunkFormat format = ChunkFormat::Fixed;
    const GeoFrame* frame = nullptr; // Move records: the file's site frame
    // When set, a Move's derived lat/lon is not computed: the machine's index is put here instead (and taken
    // out by any later record that sets its lat/lon); resolveGeodetic() computes them once at the end.
    QSet<std::uint32_t>* deferGeodetic = nullptr;
};
void resolveGeodetic(QHash<std::uint32_t, MachineState>& states, QSet<std::uint32_t>& pending,
                     const GeoFrame& frame);

// Decodes `blob` (a chunk starting at t0Ms). For each record, `visit(record)` is called after the record was
// applied to `states` (machine index -> state; Removed erases, Position updates the moving part of the
// existing state and is skipped when there is none). Records later than `untilMs` are not applied and end
// the walk (chunks are in time order). Returns false on a malformed blob (the records before the fault are
// applied).
using RecordVisitor = std::function<void(const DecodedRecord&)>;
bool decodeChunk(const QByteArray& blob, qint64 t0Ms, QHash<std::uint32_t, MachineState>& states,
                 qint64 fromExclusiveMs, qint64 untilMs, const RecordVisitor& visit = {},
                 const DecodeOptions& options = {});

} // namespace ocu::recording
