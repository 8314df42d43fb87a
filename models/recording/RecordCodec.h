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
// Little-endian, fixed-width; decoding checks every length (a truncated or hostile blob ends the chunk with
// an error, never reads past it).
#include "models/MachineState.h"

#include <QByteArray>
#include <QHash>
#include <QString>

#include <cstdint>
#include <functional>

namespace ocu::recording {

enum class RecordType : std::uint8_t { Full = 1, Position = 2, Removed = 3, Delta = 4 };

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

// Decodes `blob` (a chunk starting at t0Ms). For each record, `visit(record)` is called after the record was
// applied to `states` (machine index -> state; Removed erases, Position updates the moving part of the
// existing state and is skipped when there is none). Records later than `untilMs` are not applied and end
// the walk (chunks are in time order). Returns false on a malformed blob (the records before the fault are
// applied).
using RecordVisitor = std::function<void(const DecodedRecord&)>;
bool decodeChunk(const QByteArray& blob, qint64 t0Ms, QHash<std::uint32_t, MachineState>& states,
                 qint64 fromExclusiveMs, qint64 untilMs, const RecordVisitor& visit = {});

} // namespace ocu::recording
