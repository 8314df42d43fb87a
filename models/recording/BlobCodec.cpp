#include "models/recording/BlobCodec.h"

#include <QString>

#include <zstd.h>

#include <algorithm>

namespace ocu::recording {

BlobCodec blobCodecFromName(const QString& name) {
    if (name == QLatin1String("zlib"))
        return BlobCodec::Zlib;
    if (name == QLatin1String("zstd"))
        return BlobCodec::Zstd;
    return BlobCodec::None;
}

const char* blobCodecName(BlobCodec codec) {
    switch (codec) {
    case BlobCodec::Zlib:
        return "zlib";
    case BlobCodec::Zstd:
        return "zstd";
    case BlobCodec::None:
        break;
    }
    return "";
}

QByteArray compressBlob(const QByteArray& data, BlobCodec codec, int level) {
    switch (codec) {
    case BlobCodec::Zlib:
        return qCompress(data, std::clamp(level, 0, 9));
    case BlobCodec::Zstd: {
        QByteArray out(qsizetype(ZSTD_compressBound(size_t(data.size()))), Qt::Uninitialized);
        const size_t n = ZSTD_compress(out.data(), size_t(out.size()), data.constData(), size_t(data.size()),
                                       std::clamp(level, 1, 19));
        if (ZSTD_isError(n))
            return {};
        out.truncate(qsizetype(n));
        return out;
    }
    case BlobCodec::None:
        break;
    }
    return data;
}

QByteArray uncompressBlob(const QByteArray& blob, BlobCodec codec) {
    switch (codec) {
    case BlobCodec::Zlib:
        return qUncompress(blob);
    case BlobCodec::Zstd: {
        // ZSTD_compress always records the size in the frame; a blob without it is not ours.
        const unsigned long long size = ZSTD_getFrameContentSize(blob.constData(), size_t(blob.size()));
        if (size == ZSTD_CONTENTSIZE_UNKNOWN || size == ZSTD_CONTENTSIZE_ERROR ||
            size > quint64(kMaxBlobBytes))
            return {};
        QByteArray out(qsizetype(size), Qt::Uninitialized);
        const size_t n =
            ZSTD_decompress(out.data(), size_t(out.size()), blob.constData(), size_t(blob.size()));
        if (ZSTD_isError(n) || n != size)
            return {};
        return out;
    }
    case BlobCodec::None:
        break;
    }
    return blob;
}

} // namespace ocu::recording
