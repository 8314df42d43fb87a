#pragma once
// The folder of recordings: the name of a new run's file, the limit of one run's file, and retention (the
// older runs deleted so the folder stays within record.max_total_mb and record.max_age_days).
#include <QString>
#include <QStringList>

namespace ocu::recording {

// Retention (record.max_total_mb, record.max_age_days): deletes recordings (ocu-*.sqlite and their -wal/-shm)
// in `dir` older than maxAgeDays, then the oldest while the folder holds more than maxTotalBytes. `keep` and
// files written to within the last 5 minutes (another console's run) are never deleted. Returns the names
// deleted.
QStringList applyRetention(const QString& dir, qint64 maxTotalBytes, double maxAgeDays,
                           const QString& keep = {});
// The limit of one run's file: record.max_file_mb when set, else the folder's record.max_total_mb (a run
// alone never outgrows the folder's budget); 0 = none. In bytes.
qint64 effectiveMaxFileBytes(double maxFileMb, double maxTotalMb);
// ocu-YYYYMMDD-HHMMSS-<pid>.sqlite in dir (the pattern retention looks for).
QString newRecordingPath(const QString& dir);

} // namespace ocu::recording
