// The CSV export of a recording: one row per machine state change.
#include "models/recording/Recording.h"

#include "models/recording/RecordingQuery.h"

#include <QCoreApplication>

namespace ocu::recording {

namespace {

QByteArray csvField(const QString& s) {
    QString v = s;
    if (v.contains(QLatin1Char('"')) || v.contains(QLatin1Char(',')) || v.contains(QLatin1Char('\n')) ||
        v.contains(QLatin1Char('\r'))) {
        v.replace(QLatin1String("\""), QLatin1String("\"\""));
        v = QLatin1Char('"') + v + QLatin1Char('"');
    }
    return v.toUtf8();
}

} // namespace

bool Recording::exportCsv(QIODevice* out, qint64 from, qint64 to, QString* error) const {
    if (!out || !out->isWritable()) {
        if (error)
            *error = QCoreApplication::translate("Recording", "the output is not writable");
        return false;
    }
    bool ok =
        out->write("time,t_ms,id,name,protocol,e,n,u,lat,lon,heading,speed,mode,stop,health,link\r\n") > 0;
    changes(from - 1, to, [&](const StateChange& c) {
        if (c.removed)
            return true;
        const MachineState& m = c.state;
        QByteArray line;
        line += isoTime(c.t).toUtf8() + ',' + QByteArray::number(c.t) + ',' + csvField(m.id) + ',' +
                csvField(m.name) + ',' + toText(m.protocol).toUtf8() + ',';
        if (m.hasPosition)
            line += QByteArray::number(m.e, 'f', 3) + ',' + QByteArray::number(m.n, 'f', 3) + ',' +
                    QByteArray::number(m.u, 'f', 3) + ',' + QByteArray::number(m.lat, 'f', 8) + ',' +
                    QByteArray::number(m.lon, 'f', 8) + ',' + QByteArray::number(m.headingDeg, 'f', 1) + ',';
        else
            line += ",,,,,,";
        line += QByteArray::number(m.speed, 'f', 3) + ',' +
                csvField(m.modeText.isEmpty() ? toText(m.mode) : m.modeText) + ',' + toText(m.stop).toUtf8() +
                ',' + toText(m.health).toUtf8() + ',' + toText(m.link).toUtf8() + "\r\n";
        ok = ok && out->write(line) > 0;
        return ok;
    });
    if (!ok && error)
        *error = QCoreApplication::translate("Recording", "write failed: %1").arg(out->errorString());
    return ok;
}

} // namespace ocu::recording
