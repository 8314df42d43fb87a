// OwnPosition: Qt Positioning fixes converted into the site frame, from a direct fix and an NMEA log.
#include "models/OwnPosition.h"

#include <QGeoCoordinate>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace ocu;

class TestOwnPosition : public QObject {
    Q_OBJECT
private slots:
    void fixIsPlacedInTheSiteFrame() {
        const GeoFrame frame({48.0, 11.0, 500.0});
        OwnPosition pos(frame);
        QSignalSpy spy(&pos, &OwnPosition::fixChanged);
        // 0.001° north of the origin is ~111.2 m north.
        QGeoPositionInfo info(QGeoCoordinate(48.001, 11.0, 500.0), QDateTime::currentDateTimeUtc());
        info.setAttribute(QGeoPositionInfo::Direction, 90.0);
        info.setAttribute(QGeoPositionInfo::GroundSpeed, 2.5);
        pos.setPositionInfo(info);
        QCOMPARE(spy.count(), 1);
        const OwnFix f = pos.fix();
        QVERIFY(f.valid);
        QVERIFY(std::abs(f.e) < 0.01);
        QVERIFY(std::abs(f.n - 111.2) < 0.5);
        QVERIFY(f.hasHeading);
        QCOMPARE(f.headingDeg, 90.0);
        QCOMPARE(f.speed, 2.5);
        // Invalid coordinates are ignored.
        pos.setPositionInfo(QGeoPositionInfo());
        QCOMPARE(spy.count(), 1);
    }

    void replaysAnNmeaLog() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("track.nmea"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        // Two GGA+RMC fixes 0.2 s apart near 48.0N 11.0E (checksums computed below).
        auto sentence = [](const QByteArray& body) {
            quint8 cs = 0;
            for (char c : body)
                cs ^= quint8(c);
            return "$" + body + "*" + QByteArray::number(cs, 16).toUpper().rightJustified(2, '0') + "\r\n";
        };
        f.write(sentence("GPGGA,120000.00,4800.0000,N,01100.0000,E,1,08,0.9,500.0,M,47.0,M,,"));
        f.write(sentence("GPRMC,120000.00,A,4800.0000,N,01100.0000,E,1.5,45.0,211126,,,A"));
        f.write(sentence("GPGGA,120000.20,4800.0600,N,01100.0000,E,1,08,0.9,500.0,M,47.0,M,,"));
        f.write(sentence("GPRMC,120000.20,A,4800.0600,N,01100.0000,E,1.5,45.0,211126,,,A"));
        f.close();

        OwnPosition pos(GeoFrame({48.0, 11.0, 500.0}));
        QSignalSpy spy(&pos, &OwnPosition::fixChanged);
        QVERIFY(pos.startNmeaFile(path, true));
        QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 1, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(pos.fix().n > 100.0, 20000); // 0.06' = 0.001° north ≈ 111 m
        QVERIFY(std::abs(pos.fix().e) < 1.0);
        QVERIFY(!pos.startNmeaFile(dir.filePath(QStringLiteral("missing.nmea"))));
    }
};

QTEST_GUILESS_MAIN(TestOwnPosition)
#include "test_own_position.moc"
