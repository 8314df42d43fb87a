// Ribbon store: memory and SQLite modes, gaps, crash safety of committed data; OSYRIS configuration.
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/RibbonStore.h"

#include "protocols/common/ConfigReader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sys/wait.h>
#include <unistd.h>

using namespace ocu;
using namespace ocu::osyris;

namespace {
PositionRecord rec(std::uint32_t slot, float x = 0) {
    PositionRecord r;
    r.pos.slot = slot;
    r.pos.x = x;
    r.pos.flags = kPosValid | kPosAccuracyHigh;
    r.pos.numPos = slot * 2;
    return r;
}
} // namespace

class TestOsyrisStore : public QObject {
    Q_OBJECT
private slots:
    void intervalSet() {
        IntervalSet s;
        s.insert(5, 9);
        s.insert(11, 12);
        s.insert(10);
        QCOMPARE(s.ranges().size(), std::size_t(1));
        QCOMPARE(s.count(), std::uint64_t(8));
        s.erase(7, 8);
        QCOMPARE(s.ranges(), (std::vector<SlotRange>{{5, 6}, {9, 12}}));
        QCOMPARE(s.gaps(0, 14), (std::vector<SlotRange>{{0, 4}, {7, 8}, {13, 14}}));
        QVERIFY(s.containsAll(9, 12));
        QVERIFY(!s.containsAll(6, 9));
        s.insert(0xFFFFFFF0u, kSlotLast);
        QVERIFY(s.contains(kSlotLast));
        QCOMPARE(s.max(), kSlotLast);
    }
    void memoryStore() {
        auto st = RibbonStore::inMemory();
        QVERIFY(st->put(3, rec(0)));
        QVERIFY(st->put(3, rec(1)));
        QVERIFY(st->put(3, rec(5)));
        QVERIFY(!st->put(3, rec(5, 99.f))); // a slot is immutable: duplicates never overwrite
        QCOMPARE(st->get(3, 5)->pos.x, 0.f);
        QCOMPARE(st->count(3), std::uint64_t(3));
        QCOMPARE(st->newest(3)->pos.slot, 5u);
        QCOMPARE(st->held(3).gaps(0, 6), (std::vector<SlotRange>{{2, 4}, {6, 6}})); // gaps = what to ask for
        std::vector<std::uint32_t> seen;
        auto next = st->forEachConsecutive(3, 0, [&](const PositionRecord& r) {
            seen.push_back(r.pos.slot);
            return true;
        });
        QCOMPARE(next, 2u);
        QCOMPARE(seen, (std::vector<std::uint32_t>{0, 1}));
        QVERIFY(st->addProps(3, 1, {PosProp::fromFloat(7, 1.5f)}));
        QVERIFY(!st->addProps(3, 1, {PosProp::fromFloat(7, 2.5f)}));
        QCOMPARE(st->get(3, 1)->props.at(0).asFloat(), 1.5f);
        QCOMPARE(st->machines(), std::vector<std::uint8_t>{3});
    }
    // With SQLite behind (a site file, or the private temporary database of a store without one), memory
    // holds only each machine's newest hotSlots positions; everything older reads back the same through
    // get, forEachConsecutive, addProps and a reopen, so a shift's ribbons do not grow the process.
    void memoryIsBoundedWithSqliteBehind() {
        QTemporaryDir dir;
        const std::string file = dir.filePath("bounded.osyris.sqlite").toStdString();
        for (const std::string& path : {std::string(), file}) {
            auto opened = RibbonStore::open(path);
            QVERIFY(opened);
            auto& st = *opened;
            st->setHotSlots(32);
            // Two machines, 1,000 slots each; machine 4 has a gap at 500..509, slot 7 has no props yet.
            for (std::uint32_t i = 0; i < 1000; ++i) {
                PositionRecord r = rec(i, float(i) * 0.5f);
                if (i != 7)
                    r.props = {PosProp::fromFloat(3, float(i))};
                QVERIFY(st->put(2, r));
                if (i < 500 || i >= 510)
                    QVERIFY(st->put(4, r));
            }
            QVERIFY(st->cachedCount() <= 64);
            QVERIFY(!st->put(2, rec(5, 99.f))); // an evicted slot is still held: immutable
            QCOMPARE(st->count(2), std::uint64_t(1000));
            QCOMPARE(st->count(4), std::uint64_t(990));
            QCOMPARE(st->totalCount(), std::uint64_t(1990));
            QCOMPARE(st->machines(), (std::vector<std::uint8_t>{2, 4}));
            QCOMPARE(st->newest(4)->pos.slot, 999u);
            QCOMPARE(st->get(2, 5)->pos.x, 2.5f);
            QCOMPARE(st->get(2, 5)->props.at(0).asFloat(), 5.f);
            QVERIFY(!st->get(4, 505));
            QVERIFY(st->addProps(2, 7, {PosProp::fromFloat(3, 7.f)})); // evicted, without props: added
            QVERIFY(!st->addProps(2, 7, {PosProp::fromFloat(3, 8.f)}));
            QCOMPARE(st->get(2, 7)->props.at(0).asFloat(), 7.f);
            // Consecutive slots across SQLite and memory, stopping at the gap and where fn says.
            std::uint32_t expect = 0;
            bool same = true;
            auto next = st->forEachConsecutive(4, 0, [&](const PositionRecord& r) {
                same = same && r.pos.slot == expect && r.pos.x == float(expect) * 0.5f;
                ++expect;
                return true;
            });
            QCOMPARE(next, 500u);
            QVERIFY(same);
            expect = 510;
            next = st->forEachConsecutive(4, 510, [&](const PositionRecord& r) {
                same = same && r.pos.slot == expect;
                ++expect;
                return true;
            });
            QCOMPARE(next, 1000u);
            QVERIFY(same);
            int visits = 0;
            next = st->forEachConsecutive(2, 100, [&](const PositionRecord&) { return ++visits < 10; });
            QCOMPARE(next, 109u);
            st->commit();
        }
        // The file reopened: every slot held, the newest in memory, the rest read back.
        auto again = RibbonStore::open(file);
        QVERIFY(again);
        QCOMPARE((*again)->count(4), std::uint64_t(990));
        QCOMPARE((*again)->held(4).gaps(0, 999), (std::vector<SlotRange>{{500, 509}}));
        QCOMPARE((*again)->get(2, 7)->props.at(0).asFloat(), 7.f);
        QCOMPARE((*again)->get(4, 3)->pos.x, 1.5f);
        QCOMPARE((*again)->newest(2)->pos.slot, 999u);
    }

    void sqliteSurvivesReopen() {
        QTemporaryDir dir;
        std::string path = dir.filePath("site.osyris.sqlite").toStdString();
        {
            auto st = RibbonStore::open(path);
            QVERIFY2(st.ok(), st.ok() ? "" : st.error().c_str());
            for (std::uint32_t s = 0; s < 100; ++s) {
                auto r = rec(s, float(s));
                if (s % 10 == 0)
                    r.props = {PosProp::fromFloat(42, float(s) / 2)};
                QVERIFY((*st)->put(1, r));
            }
            (*st)->put(2, rec(7));
            (*st)->commit();
        }
        auto st = RibbonStore::open(path);
        QVERIFY(st.ok());
        QCOMPARE((*st)->count(1), std::uint64_t(100));
        QCOMPARE((*st)->get(1, 50)->props.at(0).asFloat(), 25.f);
        QCOMPARE((*st)->get(1, 99)->pos.x, 99.f);
        QCOMPARE((*st)->held(2).ranges(), (std::vector<SlotRange>{{7, 7}}));
        QVERIFY(!(*st)->put(1, rec(3)));
    }
    void crashKeepsCommittedOnly() {
        QTemporaryDir dir;
        std::string path = dir.filePath("crash.sqlite").toStdString();
        pid_t pid = fork();
        if (pid == 0) {
            auto st = RibbonStore::open(path);
            if (!st)
                _exit(2);
            for (std::uint32_t s = 0; s < 50; ++s)
                (*st)->put(4, rec(s));
            (*st)->commit();
            for (std::uint32_t s = 50; s < 60; ++s)
                (*st)->put(4, rec(s)); // never committed
            _exit(0);                  // crash: no destructor, no commit
        }
        int status = 0;
        waitpid(pid, &status, 0);
        QVERIFY(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        auto st = RibbonStore::open(path);
        QVERIFY(st.ok());
        QCOMPARE((*st)->count(4), std::uint64_t(50));
        QCOMPARE((*st)->held(4).ranges(), (std::vector<SlotRange>{{0, 49}}));
    }
    void badFileIsAnError() {
        QTemporaryDir dir;
        QString p = dir.filePath("garbage.sqlite");
        QFile f(p);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(4096, 'x'));
        f.close();
        auto st = RibbonStore::open(p.toStdString());
        QVERIFY(!st.ok());
        QVERIFY(QString::fromStdString(st.error()).contains("garbage.sqlite"));
    }
    void siteConfig() {
        auto doc = ConfigDocument::parse(R"({"osyris": {"group": "233.1.1.2", "port": 50123, "beatMs": 50,
            "checksum": "crc16", "stationIndex": 9, "targetMin": 2, "targetMax": 4, "active": 15,
            "originLat": 48.1, "originLon": 11.5, "cellSize": 0.5, "tailPos": 100,
            "machines": [{"idx": 1, "name": "Roller 1", "type": "roller"}]}})");
        QVERIFY(doc.ok());
        ConfigErrors errs;
        ConfigObject root(*doc, "", errs);
        auto sec = root.object("osyris");
        QVERIFY(sec);
        auto c = parseOsyrisConfig(*sec);
        QVERIFY2(errs.empty(), errs.joined().c_str());
        QCOMPARE(c.group, std::string("233.1.1.2"));
        QCOMPARE(int(c.port), 50123);
        QCOMPARE(c.beatMs, 50);
        QVERIFY(c.checksum == Checksum::Crc16);
        QCOMPARE(int(c.stationIndex), 9);
        QCOMPARE(c.passCount.cellSize, 0.5);
        QCOMPARE(c.tailPos, 100u);
        QCOMPARE(c.machineNames.at(1), std::string("Roller 1"));
        QCOMPARE(c.machineTypes.at(1), std::string("roller"));

        auto bad = ConfigDocument::parse(R"({"osyris": {"group": "10.0.0.1", "port": 80, "beatMS": 5}})");
        ConfigErrors e2;
        ConfigObject r2(*bad, "", e2);
        auto s2 = r2.object("osyris");
        parseOsyrisConfig(*s2);
        QCOMPARE(e2.messages().size(), std::size_t(3)); // not multicast, port range, unknown key
        QVERIFY(QString::fromStdString(e2.joined()).contains("beatMS"));
    }
    void xmlImport() {
        auto r = importOsyrisXml(R"(<Multi><MultiAddr>233.1.1.1:50002</MultiAddr><Beat>200</Beat>
            <MinLen>100</MinLen><MaxLen>1000</MaxLen><SendPeriod>4000</SendPeriod><TailPos>50</TailPos>
            <TTL>10</TTL><Active>7</Active><MaxRange>150.5</MaxRange></Multi>)");
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QCOMPARE(int(r->port), 50002);
        QCOMPARE(r->beatMs, 200);
        QCOMPARE(r->minLen, 100);
        QCOMPARE(r->maxLen, 1000);
        QCOMPARE(r->sendPeriodMs, 4000);
        QCOMPARE(r->tailPos, 50u);
        QCOMPARE(r->ttlBeats, 10);
        QCOMPARE(r->active, 7);
        QCOMPARE(r->maxRange, 150.5);
        auto attrs = importOsyrisXml(R"(<config MultiAddr="192.168.1.255" Port="50003" Beat="100"/>)");
        QVERIFY(attrs.ok());
        QVERIFY(attrs->addressing == Addressing::Broadcast);
        QCOMPARE(int(attrs->port), 50003);
        QVERIFY(!importOsyrisXml("<Multi><Beat>fast</Beat></Multi>").ok());
        // Not a number at all: "nan" parses as a double and passed both range comparisons (then the cast to
        // int was undefined behaviour); likewise for a double item.
        for (const char* bad : {"<Multi><Beat>nan</Beat></Multi>", "<Multi><TTL>-NAN</TTL></Multi>",
                                "<Multi MaxRange=\"nan\"/>", "<Multi><TailPos>inf</TailPos></Multi>"})
            QVERIFY2(!importOsyrisXml(bad).ok(), bad);
        // A million levels of nesting (pugixml parses it without recursion): the item search must not
        // recurse either (it did, one stack frame per level, and overflowed the stack).
        {
            const int depth = 1'000'000;
            std::string deep;
            deep.reserve(std::size_t(depth) * 7 + 64);
            for (int i = 0; i < depth; ++i)
                deep += "<a>";
            deep += "<Beat>250</Beat>";
            for (int i = 0; i < depth; ++i)
                deep += "</a>";
            auto nested = importOsyrisXml(deep);
            QVERIFY(nested.ok());
            QCOMPARE(nested->beatMs, 250);
        }
        QTemporaryDir dir;
        QFile f(dir.filePath("multi.xml"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<Multi><MultiAddr>233.1.1.1</MultiAddr><MultiPort>50009</MultiPort><TTL>5</TTL></Multi>");
        f.close();
        auto fromFile = importOsyrisXmlFile(f.fileName().toStdString());
        QVERIFY(fromFile.ok());
        QCOMPARE(int(fromFile->port), 50009);
        QCOMPARE(fromFile->ttlBeats, 5);
        auto missing = importOsyrisXmlFile(dir.filePath("none.xml").toStdString());
        QVERIFY(!missing.ok() && QString::fromStdString(missing.error()).contains("none.xml"));
        QVERIFY(!importOsyrisXml("<Multi><Beat>").ok());
    }
};

QTEST_GUILESS_MAIN(TestOsyrisStore)
#include "test_osyris_store.moc"
