#pragma once
// Compression of a recording's chunk blobs (docs/recording.md "Schema"): zlib through qCompress (schema 3 and
// the message chunks) and zstd (schema 4 state chunks and keyframes; smaller and faster on the records'
// varints than zlib, bench_recording measures both).
#include <QByteArray>
#include <QString>

namespace ocu::recording {

enum class BlobCodec { None, Zlib, Zstd };

// The meta value states_codec names it: "" (none), "zlib", "zstd"; unknown names read as None.
BlobCodec blobCodecFromName(const QString& name);
const char* blobCodecName(BlobCodec codec);

// level: zlib 0-9, zstd 1-19 (clamped).
QByteArray compressBlob(const QByteArray& data, BlobCodec codec, int level);
// An empty result for a malformed blob, or one that would inflate beyond kMaxBlobBytes.
QByteArray uncompressBlob(const QByteArray& blob, BlobCodec codec);
inline constexpr qint64 kMaxBlobBytes = 256ll << 20;

} // namespace ocu::recording
