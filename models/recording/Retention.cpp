#include "models/recording/Retention.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace ocu::recording {

qint64 effectiveMaxFileBytes(double maxFileMb, double maxTotalMb) {
    const double mb = maxFileMb > 0 ? maxFileMb : std::max(0.0, maxTotalMb);
    return qint64(mb * 1024 * 1024);
}

QString newRecordingPath(const QString& dir) {
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    return QDir(dir).filePath(
        QStringLiteral("ocu-%1-%2.sqlite").arg(stamp).arg(QCoreApplication::applicationPid()));
}

QStringList applyRetention(const QString& dir, qint64 maxTotalBytes, double maxAgeDays, const QString& keep) {
    QDir d(dir);
    QFileInfoList files = d.entryInfoList({QStringLiteral("ocu-*.sqlite")}, QDir::Files,
                                          QDir::Time | QDir::Reversed); // oldest first
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QString keepAbs = keep.isEmpty() ? QString() : QFileInfo(keep).absoluteFilePath();
    auto sizeOf = [](const QFileInfo& f) {
        return f.size() + QFileInfo(f.absoluteFilePath() + QStringLiteral("-wal")).size();
    };
    qint64 total = 0;
    for (const QFileInfo& f : files)
        total += sizeOf(f);
    QStringList deleted;
    // A recording whose creation was cut off (createRecordingFile): not a recording, nothing to keep.
    for (const QFileInfo& f : d.entryInfoList({QStringLiteral("ocu-*.sqlite.part")}, QDir::Files)) {
        if (f.lastModified().secsTo(now) < 300)
            continue;
        for (const QString& suffix : {QString(), QStringLiteral("-journal")})
            QFile::remove(f.absoluteFilePath() + suffix);
        deleted << f.fileName();
    }
    for (const QFileInfo& f : files) {
        if (f.absoluteFilePath() == keepAbs || f.lastModified().secsTo(now) < 300)
            continue;
        const bool tooOld = maxAgeDays > 0 && f.lastModified().secsTo(now) > qint64(maxAgeDays * 86400);
        const bool tooMuch = maxTotalBytes > 0 && total > maxTotalBytes;
        if (!tooOld && !tooMuch)
            continue;
        total -= sizeOf(f);
        for (const QString& suffix : {QString(), QStringLiteral("-wal"), QStringLiteral("-shm")})
            QFile::remove(f.absoluteFilePath() + suffix);
        deleted << f.fileName();
    }
    return deleted;
}

} // namespace ocu::recording
