#pragma once
// Inbound protocol messages in a flight recording (docs/recording.md "Schema"): what the stacks
// handed to the recorder's tap (protocols/common/MessageTap.h). A chunk is one BLOB of the `messages` table
// (qCompress'ed: zlib with Qt's 4-byte length prefix), records back to back:
//   varint channel   index into `msg_channels` (protocol, link, peer, type)
//   varint dt        ms after the chunk's t0
//   u8     flags     bit 0: raw frame/datagram (record.raw) rather than a decoded message
//   varint length, then the bytes (decoded: the validated message the codec decodes again; raw: as received)
// Decoding checks every length: a truncated or hostile blob ends the chunk, never reads past it.
#include <QByteArray>
#include <QString>

#include <cstdint>
#include <functional>

namespace ocu::recording {

struct MessageChannel {
    QString protocol, link, peer, type;
};

struct RecordedMessage {
    qint64 t = 0; // the console's receive time (ms since the epoch)
    std::uint32_t channel = 0;
    bool raw = false;
    QByteArray bytes;
};

void appendMessage(QByteArray& chunk, std::uint32_t channel, std::uint32_t dtMs, bool raw, const char* data,
                   qsizetype size);
// Calls `fn` for each record of the chunk within [fromMs, toMs]; false on a malformed blob (the records
// before the fault were visited). `fn` returning false stops the walk.
bool decodeMessageChunk(const QByteArray& blob, qint64 t0Ms, qint64 fromMs, qint64 toMs,
                        const std::function<bool(const RecordedMessage&)>& fn);

// The tap's hand-off record (one allocation per message): protocol, link, peer, type as u8-length strings
// (cut at 255 bytes), flags, then the bytes.
QByteArray packTapped(std::string_view protocol, std::string_view link, std::string_view peer,
                      std::string_view type, bool raw, const std::uint8_t* data, std::size_t size);
struct UnpackedTapped {
    QByteArray key; // protocol..type as packed: the channel's identity
    MessageChannel channel;
    bool raw = false;
    const char* data = nullptr;
    qsizetype size = 0;
};
bool unpackTapped(const QByteArray& packed, UnpackedTapped& out);

} // namespace ocu::recording
