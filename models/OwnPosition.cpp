#include "models/OwnPosition.h"

#include <QFile>
#include <QGeoPositionInfoSource>
#include <QNmeaPositionInfoSource>
#include <cmath>

namespace ocu {

OwnPosition::OwnPosition(const GeoFrame& frame, QObject* parent) : QObject(parent), m_frame(frame) {
    qRegisterMetaType<ocu::OwnFix>();
}

OwnPosition::~OwnPosition() {
    stop();
}

void OwnPosition::setFrame(const GeoFrame& frame) {
    m_frame = frame;
    if (m_fix.valid) {
        const EnuPoint p = m_frame.toLocal({m_fix.lat, m_fix.lon, m_fix.alt});
        m_fix.e = p.e;
        m_fix.n = p.n;
        m_fix.u = p.u;
        emit fixChanged(m_fix);
    }
}

void OwnPosition::setSource(QGeoPositionInfoSource* source) {
    stop();
    if (!source)
        return;
    source->setParent(this);
    m_source = source;
    connect(source, &QGeoPositionInfoSource::positionUpdated, this, &OwnPosition::setPositionInfo);
    connect(source, &QGeoPositionInfoSource::errorOccurred, this, [this](QGeoPositionInfoSource::Error e) {
        emit error(tr("position source error %1").arg(int(e)));
    });
    source->startUpdates();
}

bool OwnPosition::startSystemSource(int intervalMs) {
    QGeoPositionInfoSource* src = QGeoPositionInfoSource::createDefaultSource(this);
    if (!src) {
        emit error(tr("no system position source available"));
        return false;
    }
    src->setUpdateInterval(intervalMs);
    setSource(src);
    return true;
}

bool OwnPosition::startNmeaFile(const QString& path, bool simulation) {
    auto* file = new QFile(path);
    if (!file->open(QIODevice::ReadOnly)) {
        emit error(tr("cannot open NMEA log %1: %2").arg(path, file->errorString()));
        delete file;
        return false;
    }
    auto* src = new QNmeaPositionInfoSource(simulation ? QNmeaPositionInfoSource::SimulationMode
                                                       : QNmeaPositionInfoSource::RealTimeMode);
    file->setParent(src);
    src->setDevice(file);
    setSource(src);
    return true;
}

bool OwnPosition::startNmeaDevice(QIODevice* device) {
    if (!device) {
        emit error(tr("no NMEA device"));
        return false;
    }
    auto* src = new QNmeaPositionInfoSource(QNmeaPositionInfoSource::RealTimeMode);
    src->setDevice(device);
    setSource(src);
    return true;
}

void OwnPosition::stop() {
    if (m_source) {
        m_source->stopUpdates();
        delete m_source.data();
    }
    m_source = nullptr;
}

QString OwnPosition::sourceName() const {
    return m_source ? m_source->sourceName() : QString();
}

void OwnPosition::setPositionInfo(const QGeoPositionInfo& info) {
    const QGeoCoordinate c = info.coordinate();
    if (!c.isValid())
        return;
    OwnFix f;
    f.valid = true;
    f.lat = c.latitude();
    f.lon = c.longitude();
    f.alt = std::isnan(c.altitude()) ? m_frame.origin().alt : c.altitude();
    const EnuPoint p = m_frame.toLocal({f.lat, f.lon, f.alt});
    f.e = p.e;
    f.n = p.n;
    f.u = p.u;
    if (info.hasAttribute(QGeoPositionInfo::Direction)) {
        f.hasHeading = true;
        f.headingDeg = info.attribute(QGeoPositionInfo::Direction);
    }
    if (info.hasAttribute(QGeoPositionInfo::GroundSpeed))
        f.speed = info.attribute(QGeoPositionInfo::GroundSpeed);
    f.timeMs = info.timestamp().isValid() ? info.timestamp().toMSecsSinceEpoch() : 0;
    m_fix = f;
    emit fixChanged(m_fix);
}

} // namespace ocu
