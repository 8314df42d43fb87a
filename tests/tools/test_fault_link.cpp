// The fault proxy's decisions (tests/tools/FaultLink): what it drops, delays, duplicates, reorders and queues
// is what its profile says, and the same seed gives the same faults.
#include "tests/tools/FaultLink.h"

#include <QtTest/QtTest>

#include <algorithm>

using ocu::tools::FaultLink;
using ocu::tools::FaultProfile;
using namespace std::chrono_literals;

namespace {

FaultProfile profile(const char* text) {
    std::string error;
    FaultProfile p = ocu::tools::parseFaultProfile(text, error);
    if (!error.empty())
        qFatal("profile %s refused: %s", text, error.c_str());
    return p;
}

// Offers `n` frames of `bytes` bytes, one every `gap`, and returns every departure time minus its offer time.
std::vector<FaultLink::Clock::duration> delays(FaultLink& link, int n, std::size_t bytes,
                                               FaultLink::Clock::duration gap) {
    std::vector<FaultLink::Clock::duration> out;
    auto t = FaultLink::Clock::time_point{} + 1h;
    for (int i = 0; i < n; ++i, t += gap)
        for (const auto& at : link.offer(bytes, t))
            out.push_back(at - t);
    return out;
}

} // namespace

class TestFaultLink : public QObject {
    Q_OBJECT
private slots:
    void noFaultsPassesEverythingAtOnce() {
        FaultLink link(profile(""), 1);
        const auto d = delays(link, 1000, 100, 1ms);
        QCOMPARE(d.size(), size_t(1000));
        QVERIFY(
            std::all_of(d.begin(), d.end(), [](auto x) { return x == FaultLink::Clock::duration::zero(); }));
    }

    void lossDuplicationAndReorderingAtTheirRates() {
        FaultLink link(profile("loss=0.3,dup=0.1,reorder=0.1"), 7);
        delays(link, 20000, 100, 1ms);
        const auto& c = link.counters();
        QCOMPARE(c.in, 20000u);
        QVERIFY2(c.lost > 5700 && c.lost < 6300, qPrintable(QString::number(c.lost)));
        const double passed = double(c.in - c.lost);
        QVERIFY(c.duplicated > 0.09 * passed && c.duplicated < 0.11 * passed);
        QVERIFY(c.reordered > 0.09 * passed && c.reordered < 0.11 * passed);
        QCOMPARE(c.sent, c.in - c.lost + c.duplicated);
    }

    void reorderedFramesAreOvertaken() {
        FaultLink link(profile("reorder=0.2"), 3);
        auto t = FaultLink::Clock::time_point{} + 1h;
        std::vector<std::pair<FaultLink::Clock::time_point, int>> departures;
        for (int i = 0; i < 500; ++i, t += 2ms)
            for (const auto& at : link.offer(100, t))
                departures.emplace_back(at, i);
        std::stable_sort(departures.begin(), departures.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        int outOfOrder = 0;
        for (size_t i = 1; i < departures.size(); ++i)
            outOfOrder += departures[i].second < departures[i - 1].second;
        QVERIFY(outOfOrder > 50);
        const auto& c = link.counters();
        QVERIFY(c.reordered > 70 && c.reordered < 130);
    }

    void delayWithJitterStaysInItsBand() {
        FaultLink link(profile("delay=300,jitter=100"), 11);
        const auto d = delays(link, 5000, 100, 1ms);
        QCOMPARE(d.size(), size_t(5000));
        const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
        QVERIFY(*lo >= 200ms && *lo < 205ms);
        QVERIFY(*hi <= 400ms && *hi > 395ms);
        FaultLink::Clock::duration sum{};
        for (auto x : d)
            sum += x;
        const auto mean = std::chrono::duration_cast<std::chrono::milliseconds>(sum / long(d.size()));
        QVERIFY2(mean >= 295ms && mean <= 305ms, qPrintable(QString::number(mean.count())));
    }

    void rateLimitSerialisesAndDropsBeyondTheQueue() {
        // 20 kbit/s: a 250-byte frame takes 100 ms on the line. 50 frames at once: 10 fit the 1 s queue.
        FaultLink link(profile("rate=20000,queue=1000"), 5);
        const auto t0 = FaultLink::Clock::time_point{} + 1h;
        std::vector<FaultLink::Clock::time_point> sent;
        for (int i = 0; i < 50; ++i)
            for (const auto& at : link.offer(250, t0))
                sent.push_back(at);
        QCOMPARE(sent.size(), size_t(11));
        for (size_t i = 0; i < sent.size(); ++i)
            QCOMPARE(sent[i] - t0,
                     std::chrono::duration_cast<FaultLink::Clock::duration>(100ms * long(i + 1)));
        QCOMPARE(link.counters().overflow, 39u);
        // Once the line has drained, a frame goes at the line's speed again.
        const auto later = link.offer(250, t0 + 10s);
        QCOMPARE(later.size(), size_t(1));
        QCOMPARE(later[0] - (t0 + 10s), FaultLink::Clock::duration(100ms));
    }

    void partitionDropsEverythingUntilHealed() {
        FaultLink link(profile("delay=10"), 1);
        link.setPartitioned(true);
        QCOMPARE(delays(link, 100, 100, 1ms).size(), size_t(0));
        QCOMPARE(link.counters().partitioned, 100u);
        link.setPartitioned(false);
        QCOMPARE(delays(link, 100, 100, 1ms).size(), size_t(100));
    }

    void sameSeedSameFaults() {
        const auto p = profile("loss=0.3,dup=0.1,reorder=0.1,delay=300,jitter=100");
        FaultLink a(p, 42), b(p, 42), c(p, 43);
        const auto da = delays(a, 2000, 100, 1ms);
        QVERIFY(da == delays(b, 2000, 100, 1ms));
        QVERIFY(da != delays(c, 2000, 100, 1ms));
    }

    void profileRefusals() {
        std::string error;
        ocu::tools::parseFaultProfile("loss=1.5", error);
        QVERIFY(!error.empty());
        error.clear();
        ocu::tools::parseFaultProfile("delay=10,jitter=20", error);
        QVERIFY(!error.empty());
        error.clear();
        ocu::tools::parseFaultProfile("lag=3", error);
        QVERIFY(error.find("unknown") != std::string::npos);
        error.clear();
        const auto p = ocu::tools::parseFaultProfile("loss=0.3,rate=20000", error);
        QVERIFY(error.empty());
        QCOMPARE(p.loss, 0.3);
        QCOMPARE(p.rateBitsPerS, 20000.0);
    }
};

QTEST_GUILESS_MAIN(TestFaultLink)
#include "test_fault_link.moc"
