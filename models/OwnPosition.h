#pragma once
// The console's own position from Qt Positioning: the system source, or an NMEA log / serial
// device through QNmeaPositionInfoSource (no plugin needed; toolchain.md §6), converted into the site frame.
// The app forwards fixes to the ISO bridge as MachinePositionV1 when the site names this console as an
// FMS machine.
#include "protocols/common/GeoFrame.h"

#include <QGeoPositionInfo>
#include <QMetaType>
#include <QObject>
#include <QPointer>

class QGeoPositionInfoSource;
class QIODevice;

namespace ocu {

struct OwnFix {
    bool valid = false;
    double lat = 0, lon = 0, alt = 0; // WGS84
    double e = 0, n = 0, u = 0;       // site frame
    bool hasHeading = false;
    double headingDeg = 0; // 0 = north, clockwise
    double speed = 0;      // m/s (0 when unknown)
    qint64 timeMs = 0;     // fix time, ms since the Unix epoch
};

class OwnPosition : public QObject {
    Q_OBJECT
public:
    explicit OwnPosition(const GeoFrame& frame = GeoFrame(), QObject* parent = nullptr);
    ~OwnPosition() override;

    void setFrame(const GeoFrame& frame);
    const GeoFrame& frame() const { return m_frame; }

    // Each start* replaces the current source. False (with error()) when the source cannot be opened.
    bool startSystemSource(int intervalMs = 1000);
    // Replays an NMEA log; `simulation` paces it by its timestamps (real time), otherwise reads it as live.
    bool startNmeaFile(const QString& path, bool simulation = true);
    // A serial port or any QIODevice delivering NMEA sentences in real time (not owned).
    bool startNmeaDevice(QIODevice* device);
    // Any source (takes ownership), e.g. a test double.
    void setSource(QGeoPositionInfoSource* source);
    void stop();

    OwnFix fix() const { return m_fix; }
    QString sourceName() const;

public slots:
    // Also usable directly (tests, a fixed console position from the configuration).
    void setPositionInfo(const QGeoPositionInfo& info);

signals:
    void fixChanged(const ocu::OwnFix& fix);
    void error(const QString& message);

private:
    GeoFrame m_frame;
    QPointer<QGeoPositionInfoSource> m_source;
    OwnFix m_fix;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::OwnFix)
