// The video watchdog with a fake clock: it waits for the first good frame without latching,
// trips when the stream is lost or the frame grows older than the limit, stays tripped while the video is
// back until the operator resumes, and refuses a resume while the video is still bad.
#include "models/video/VideoWatchdog.h"

#include <QTest>

using namespace ocu;

class TestVideoWatchdog : public QObject {
    Q_OBJECT
private slots:
    void tripsAndResumesOnlyDeliberately() {
        auto clock = std::make_shared<ManualModelClock>(100000);
        VideoWatchdog w(clock);
        QCOMPARE(w.limitMs(), 1000);
        // No camera: nothing is watched.
        QVERIFY(w.check());
        QVERIFY(w.reason().isEmpty());

        w.setRequired(true);
        w.setStream(VideoState::Connecting, std::nullopt);
        QVERIFY(!w.check());
        QVERIFY(!w.tripped());
        QVERIFY(w.reason().contains(QLatin1String("waits")));

        // First frame, 80 ms old: driving allowed without any resume.
        w.setStream(VideoState::Playing, clock->nowMs() - 80);
        QVERIFY(w.check());
        QCOMPARE(*w.frameAgeMs(), 80);

        // The frame ages: at 1000 ms still fine, at 1001 ms the watchdog trips.
        const std::int64_t frame = clock->nowMs() - 80;
        clock->set(frame + 1000);
        QVERIFY(w.check());
        clock->set(frame + 1001);
        QVERIFY(!w.check());
        QVERIFY(w.tripped());
        QVERIFY(w.reason().contains(QLatin1String("1001 ms")));

        // Fresh frames again: still held until the operator resumes.
        w.setStream(VideoState::Playing, clock->nowMs() - 30);
        QVERIFY(!w.check());
        QVERIFY(w.videoGood());
        QVERIFY(w.reason().contains(QLatin1String("Resume")));
        QVERIFY(w.resume());
        QVERIFY(w.check());

        // Stream lost: trips at once (the frame itself is still young).
        w.setStream(VideoState::Lost, clock->nowMs() - 10);
        QVERIFY(!w.check());
        QVERIFY(w.reason().contains(QLatin1String("LOST")));
        // A resume while the video is bad is refused.
        QVERIFY(!w.resume());
        QVERIFY(w.tripped());
        w.setStream(VideoState::Reconnecting, clock->nowMs() - 10);
        QVERIFY(!w.resume());
        w.setStream(VideoState::Playing, clock->nowMs());
        QVERIFY(w.resume());

        // A configurable limit.
        w.setLimitMs(300);
        w.setStream(VideoState::Playing, clock->nowMs() - 301);
        QVERIFY(!w.check());
        QVERIFY(w.tripped());

        // Another camera of the same vehicle (or the panel shown again) while tripped: the trip stays; the
        // new stream's good frames do not let driving resume by themselves, only the operator's resume.
        w.restartStream();
        QVERIFY(w.tripped());
        QVERIFY(!w.videoGood());
        QVERIFY(!w.check());
        QVERIFY(!w.resume()); // no good frame of the new stream yet
        w.setStream(VideoState::Playing, clock->nowMs());
        QVERIFY(!w.check());
        QVERIFY(w.tripped());
        QVERIFY(w.resume());

        // A new stream before any trip: it waits for the first frame without latching on the way.
        w.restartStream();
        w.setStream(VideoState::Connecting, std::nullopt);
        QVERIFY(!w.check());
        QVERIFY(!w.tripped());
        w.setStream(VideoState::Playing, clock->nowMs());
        QVERIFY(w.check());

        // Another vehicle: the trip is forgotten, wait for that vehicle's first frame.
        w.setStream(VideoState::Lost, clock->nowMs());
        QVERIFY(!w.check());
        QVERIFY(w.tripped());
        w.reset();
        QVERIFY(!w.tripped());
        QVERIFY(!w.check());
        w.setStream(VideoState::Playing, clock->nowMs());
        QVERIFY(w.check());
    }
};

QTEST_GUILESS_MAIN(TestVideoWatchdog)
#include "test_video_watchdog.moc"
