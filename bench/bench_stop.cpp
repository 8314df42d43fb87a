// STOP ALL latency at the wire (docs/decisions/stop-from-callers-thread.md): from the trigger to the first
// byte of each protocol's stop message on the loopback interface, timed by the kernel (AF_PACKET socket on
// "lo" with SO_TIMESTAMPNS: the realtime stamp each packet gets when lo passes it on, in the same call as its
// transmission), so the figure does not depend on how the console reports results.
//   (a) window:   the real MainWindow's STOP ALL action (QAction::trigger) of an in-process console
//                 (SiteRuntime + MainWindow on the offscreen platform, drawing);
//   (b) click:    a real press of the mouse on the window's STOP ALL button, injected through the X server
//                 (XTest, tests/support/XTestClicker) under Xvfb: the press goes through the X server, Qt's
//                 xcb event reader and the GUI thread's queue behind painting, as an operator's click does;
//   (c) headless: the line {"cmd":"stop_all"} written into the stdin of `ocu --headless` (its own process).
// The machines are `ocu-sim` in its own process: idle = 1 UGV, 1 truck at 2 Hz, 1 roller; full = 20 UGVs,
// 1,000 trucks at 10 Hz, 3 rollers. Stop messages recognised on the wire:
//   JAUS      a JUDP datagram carrying SetEmergency (0x0006) to a vehicle (first and last of each trial),
//   ISO 23725 a WebSocket frame to the AHS whose (unmasked) JSON holds "ModeAllStop":"Apply",
//   OSYRIS    a datagram to the group holding the CmMsg text "STOP ALL".
// Needs CAP_NET_RAW (root) for the packet socket. Usage:
//   bench_stop [--load idle,full] [--trigger window,click,headless] [--trials 1000] [--sim-nice 10]
// The click trigger needs an X server: xvfb-run -a -s "-screen 0 1920x1200x24" ./bench/bench_stop --trigger
// click
// --sim-nice runs ocu-sim (the machines, on other hosts in reality) at that nice value. The console's
// stop-path threads raise their priority as in `ocu` (OCU_THREAD_PRIORITY=off|nice to measure without).
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "protocols/common/ThreadPriority.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/Messages.h"
#include "tests/support/XTestClicker.h"

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTimer>
#include <QUrl>
#include <QWindow>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <fcntl.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/ip.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

namespace {

std::int64_t realtimeNs() {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return std::int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

enum Proto { Jaus = 0, Iso = 1, Osyris = 2, kProtos = 3 };
const char* const kProtoNames[kProtos] = {"JAUS SetEmergency", "ISO 23725 all-stop Apply",
                                          "OSYRIS STOP text"};

// Watches every packet leaving on loopback and keeps, per protocol, the kernel time of the first stop message
// sent after arm().
class WireSniffer {
public:
    std::uint16_t ahsPort = 0;
    std::uint16_t osyrisPort = 0;

    bool open(std::string& error) {
        m_fd = ::socket(AF_PACKET, SOCK_DGRAM, htons(ETH_P_IP));
        if (m_fd < 0) {
            error = std::string("AF_PACKET socket: ") + std::strerror(errno) +
                    " (needs CAP_NET_RAW: run as root)";
            return false;
        }
        int on = 1;
        ::setsockopt(m_fd, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
        int rcv = 32 * 1024 * 1024;
        ::setsockopt(m_fd, SOL_SOCKET, SO_RCVBUFFORCE, &rcv, sizeof rcv);
        sockaddr_ll sll{};
        sll.sll_family = AF_PACKET;
        sll.sll_protocol = htons(ETH_P_IP);
        sll.sll_ifindex = static_cast<int>(if_nametoindex("lo"));
        if (::bind(m_fd, reinterpret_cast<sockaddr*>(&sll), sizeof sll) != 0) {
            error = std::string("bind to lo: ") + std::strerror(errno);
            return false;
        }
        m_thread = std::thread([this] { run(); });
        return true;
    }
    ~WireSniffer() {
        m_stop = true;
        if (m_thread.joinable())
            m_thread.join();
        if (m_fd >= 0)
            ::close(m_fd);
    }
    void arm(std::int64_t t0) {
        for (auto& f : m_first)
            f.store(0);
        m_jausLast.store(0);
        m_jausCount.store(0);
        m_t0.store(t0);
    }
    // Every protocol in mask (bit per Proto) seen since arm().
    bool allSeen(unsigned mask = 7u) const {
        for (int p = 0; p < kProtos; ++p)
            if ((mask & (1u << p)) && m_first[p].load() == 0)
                return false;
        return true;
    }
    std::int64_t first(int p) const { return m_first[p].load(); }
    std::int64_t jausLast() const { return m_jausLast.load(); }
    int jausCount() const { return m_jausCount.load(); }
    std::uint64_t packets() const { return m_packets.load(); }

private:
    void seen(int p, std::int64_t ts) {
        if (ts < m_t0.load())
            return;
        std::int64_t zero = 0;
        m_first[p].compare_exchange_strong(zero, ts);
        if (p == Jaus) {
            m_jausLast.store(ts);
            ++m_jausCount;
        }
    }
    void run() {
        std::vector<unsigned char> buf(70000);
        char control[256];
        while (!m_stop) {
            pollfd pfd{m_fd, POLLIN, 0};
            if (::poll(&pfd, 1, 50) <= 0)
                continue;
            for (;;) {
                sockaddr_ll from{};
                iovec iov{buf.data(), buf.size()};
                msghdr msg{};
                msg.msg_name = &from;
                msg.msg_namelen = sizeof from;
                msg.msg_iov = &iov;
                msg.msg_iovlen = 1;
                msg.msg_control = control;
                msg.msg_controllen = sizeof control;
                const ssize_t n = ::recvmsg(m_fd, &msg, MSG_DONTWAIT);
                if (n <= 0)
                    break;
                ++m_packets;
                // Loopback shows each packet twice. The outgoing copy of a TCP segment carries the stack's
                // monotonic departure time, not a CLOCK_REALTIME stamp; the incoming copy is stamped in
                // realtime when lo hands it to the receive queue, in the same call as the transmission.
                if (from.sll_pkttype == PACKET_OUTGOING)
                    continue;
                std::int64_t ts = 0;
                for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c; c = CMSG_NXTHDR(&msg, c))
                    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_TIMESTAMPNS) {
                        timespec t{};
                        std::memcpy(&t, CMSG_DATA(c), sizeof t);
                        ts = std::int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
                    }
                const std::int64_t now = realtimeNs();
                if (ts == 0 || ts > now || now - ts > 1'000'000'000) // no stamp, or not in realtime
                    ts = now;
                classify(buf.data(), static_cast<std::size_t>(n), ts);
            }
        }
    }
    void classify(const unsigned char* p, std::size_t n, std::int64_t ts) {
        if (n < 20 || (p[0] >> 4) != 4)
            return;
        const std::size_t ihl = (p[0] & 0x0F) * 4u;
        const std::size_t total = std::min<std::size_t>(n, (p[2] << 8) | p[3]);
        if (total <= ihl)
            return;
        const unsigned char* l4 = p + ihl;
        const std::size_t l4n = total - ihl;
        if (p[9] == IPPROTO_UDP && l4n >= 8) {
            const std::uint16_t dport = static_cast<std::uint16_t>((l4[2] << 8) | l4[3]);
            const unsigned char* d = l4 + 8;
            const std::size_t dn = l4n - 8;
            if (dport == osyrisPort) {
                static const char kText[] = "STOP ALL";
                if (memmem(d, dn, kText, sizeof kText - 1))
                    seen(Osyris, ts);
                return;
            }
            if (dn > 0 && d[0] == 2) { // JUDP version 2
                auto dec = ocu::jaus::decodeDatagram(ocu::ByteSpan(d, dn));
                if (!dec)
                    return;
                for (const auto& m : dec->messages)
                    if (m.messageId() == ocu::jaus::msg::SetEmergency) {
                        seen(Jaus, ts);
                        return;
                    }
            }
        } else if (p[9] == IPPROTO_TCP && l4n >= 20) {
            const std::uint16_t dport = static_cast<std::uint16_t>((l4[2] << 8) | l4[3]);
            if (dport != ahsPort)
                return;
            const std::size_t off = (l4[12] >> 4) * 4u;
            if (l4n <= off)
                return;
            scanWebSocket(l4 + off, l4n - off, ts);
        }
    }
    // The console is the WebSocket client: its frames are masked (RFC 6455 §5.3). Unmask each frame that
    // starts in this segment and look for the all-stop Apply.
    void scanWebSocket(const unsigned char* d, std::size_t n, std::int64_t ts) {
        std::size_t i = 0;
        while (i + 2 <= n) {
            const unsigned opcode = d[i] & 0x0F;
            const bool masked = d[i + 1] & 0x80;
            std::uint64_t len = d[i + 1] & 0x7F;
            std::size_t h = i + 2;
            if (len == 126) {
                if (h + 2 > n)
                    return;
                len = (std::uint64_t(d[h]) << 8) | d[h + 1];
                h += 2;
            } else if (len == 127) {
                if (h + 8 > n)
                    return;
                len = 0;
                for (int k = 0; k < 8; ++k)
                    len = (len << 8) | d[h + k];
                h += 8;
            }
            unsigned char key[4] = {0, 0, 0, 0};
            if (masked) {
                if (h + 4 > n)
                    return;
                std::memcpy(key, d + h, 4);
                h += 4;
            }
            const std::size_t avail = static_cast<std::size_t>(std::min<std::uint64_t>(len, n - h));
            if (opcode == 1) {
                std::string text(avail, '\0');
                for (std::size_t k = 0; k < avail; ++k)
                    text[k] = static_cast<char>(d[h + k] ^ key[k % 4]);
                if (text.find("\"ModeAllStop\":\"Apply\"") != std::string::npos) {
                    seen(Iso, ts);
                    return;
                }
            }
            i = h + avail;
            if (avail < len)
                return;
        }
    }

    int m_fd = -1;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    std::atomic<std::int64_t> m_t0{std::numeric_limits<std::int64_t>::max()};
    std::atomic<std::int64_t> m_first[kProtos]{};
    std::atomic<std::int64_t> m_jausLast{0};
    std::atomic<int> m_jausCount{0};
    std::atomic<std::uint64_t> m_packets{0};
};

struct Samples {
    std::vector<double> ms[kProtos];
    std::vector<double> jausLastMs;
    std::vector<int> jausCount;
    int missed[kProtos] = {0, 0, 0};
};

double pct(std::vector<double> v, double q) {
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * double(v.size())));
    return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::string loadAverage() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return a + " " + b + " " + c;
}

std::string cpuModel() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    return "?";
}

void report(const char* load, const char* trigger, const Samples& s, const std::string& loadBefore) {
    std::printf("\n[%s load, %s trigger] %zu trials; load average before %s, after %s\n", load, trigger,
                s.ms[Jaus].size() + std::size_t(s.missed[Jaus]), loadBefore.c_str(), loadAverage().c_str());
    std::printf("  %-34s %6s %9s %9s %9s %7s\n", "first byte on the wire", "n", "p50 ms", "p99 ms", "max ms",
                "missed");
    for (int p = 0; p < kProtos; ++p)
        std::printf("  %-34s %6zu %9.3f %9.3f %9.3f %7d\n", kProtoNames[p], s.ms[p].size(), pct(s.ms[p], 0.5),
                    pct(s.ms[p], 0.99), pct(s.ms[p], 1.0), s.missed[p]);
    std::vector<double> counts(s.jausCount.begin(), s.jausCount.end());
    std::printf("  %-34s %6zu %9.3f %9.3f %9.3f   (SetEmergency per trial: median %.0f)\n",
                "JAUS SetEmergency, last vehicle", s.jausLastMs.size(), pct(s.jausLastMs, 0.5),
                pct(s.jausLastMs, 0.99), pct(s.jausLastMs, 1.0), pct(counts, 0.5));
    std::fflush(stdout);
}

// Waits (processing Qt events when there is an application) until the sniffer saw all three, or timeout.
bool waitAll(WireSniffer& sn, int timeoutMs, bool qt, unsigned mask) {
    QElapsedTimer t;
    t.start();
    while (!sn.allSeen(mask) && t.elapsed() < timeoutMs) {
        if (qt) {
            QEventLoop loop;
            QTimer::singleShot(1, Qt::PreciseTimer, &loop, &QEventLoop::quit);
            loop.exec();
        } else {
            std::this_thread::sleep_for(std::chrono::microseconds(300));
        }
    }
    return sn.allSeen(mask);
}

void pause(int ms, bool qt) {
    if (qt) {
        QEventLoop loop;
        QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
        loop.exec();
    } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    }
}

// Runs n trials of `trigger` (warm-up first: repeated until every protocol's stop is on the wire).
// mask: the protocols whose stop must be on the wire (see main: JAUS only where this console controls
// vehicles).
// `after` runs after each trigger, outside the timing (the click's release).
template <class Trigger, class Prelude, class After = void (*)()>
bool trials(
    WireSniffer& sn, Samples& s, int n, bool qt, unsigned mask, Trigger trigger, Prelude prelude,
    After after = [] {}) {
    // Warm-up: the console has discovered the machines and its links are up once a stop reaches all three.
    QElapsedTimer warm;
    warm.start();
    bool ready = false;
    while (!ready && warm.elapsed() < 120000) {
        prelude();
        pause(300, qt);
        sn.arm(realtimeNs());
        trigger();
        ready = waitAll(sn, 1000, qt, mask);
        after();
        if (!ready)
            pause(500, qt);
    }
    if (!ready) {
        std::fprintf(stderr,
                     "bench_stop: no stop on the wire for every protocol within 120 s (JAUS %d, ISO %d, "
                     "OSYRIS %d)\n",
                     sn.first(Jaus) != 0, sn.first(Iso) != 0, sn.first(Osyris) != 0);
        return false;
    }
    pause(5000, qt); // let discovery of the remaining vehicles settle
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> gap(20, 40); // < 200 ms: no SetEmergency retry falls into a trial
    for (int i = 0; i < n; ++i) {
        const std::int64_t t0 = realtimeNs();
        sn.arm(t0);
        trigger();
        waitAll(sn, 2000, qt, mask);
        after();
        pause(gap(rng), qt); // the remaining vehicles' SetEmergency leave meanwhile
        for (int p = 0; p < kProtos; ++p) {
            if (sn.first(p))
                s.ms[p].push_back(double(sn.first(p) - t0) / 1e6);
            else
                ++s.missed[p];
        }
        if (sn.jausLast()) {
            s.jausLastMs.push_back(double(sn.jausLast() - t0) / 1e6);
            s.jausCount.push_back(sn.jausCount());
        }
    }
    return true;
}

pid_t spawn(const std::vector<std::string>& argv, int stdinFd, const char* stdoutPath, int niceness = 0) {
    const pid_t pid = ::fork();
    if (pid != 0)
        return pid;
    if (niceness != 0) {
        [[maybe_unused]] const int r = ::nice(niceness);
    }
    if (stdinFd >= 0) {
        ::dup2(stdinFd, 0);
    } else {
        const int nul = ::open("/dev/null", O_RDONLY);
        ::dup2(nul, 0);
    }
    const int out = ::open(stdoutPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(out, 2);
    std::vector<char*> a;
    for (const auto& s : argv)
        a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    ::execv(a[0], a.data());
    ::_exit(127);
}

bool endChild(pid_t pid, int sig, int timeoutMs) {
    if (sig)
        ::kill(pid, sig);
    for (int i = 0; i < timeoutMs / 10; ++i) {
        int st = 0;
        if (::waitpid(pid, &st, WNOHANG) == pid)
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return false;
}

QJsonObject waitForConfig(const QString& path, pid_t sim) {
    for (int i = 0; i < 1200; ++i) {
        QFile f(path);
        if (f.open(QIODevice::ReadOnly)) {
            QJsonParseError err{};
            const QJsonObject o = QJsonDocument::fromJson(f.readAll(), &err).object();
            if (err.error == QJsonParseError::NoError && o.contains("jaus") && o.contains("iso23725") &&
                o.contains("osyris"))
                return o;
        }
        if (::waitpid(sim, nullptr, WNOHANG) == sim)
            return {};
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return {};
}

} // namespace

int main(int argc, char** argv) {
    QStringList loads{"idle", "full"}, triggers{"window", "headless"};
    int n = 1000;
    int simNice = 0;
    for (int i = 1; i + 1 < argc; i += 2) {
        const QString k = QString::fromLocal8Bit(argv[i]), v = QString::fromLocal8Bit(argv[i + 1]);
        if (k == "--load")
            loads = v.split(',');
        else if (k == "--trigger")
            triggers = v.split(',');
        else if (k == "--trials")
            n = std::max(1, v.toInt());
        else if (k == "--sim-nice") // the load generator at lower priority (it stands for other hosts)
            simNice = v.toInt();
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) // a click needs a real window system (Xvfb)
        qputenv("QT_QPA_PLATFORM", triggers.contains("click") ? "xcb" : "offscreen");
    qputenv("QT_LOGGING_RULES", "*.debug=false;*.info=false;*.warning=false");
    QApplication app(argc, argv);
    ::signal(SIGPIPE, SIG_IGN);
    // As the console's main does (the in-process window console): the stop-path threads ahead of ordinary
    // threads where permitted. OCU_THREAD_PRIORITY=off measures without (it reaches ocu --headless too).
    ocu::enableStopPathPriority();

    WireSniffer sn;
    std::string error;
    if (!sn.open(error)) {
        std::fprintf(stderr, "bench_stop: %s\n", error.c_str());
        return 2;
    }
    std::printf("bench_stop: STOP ALL trigger -> first byte of each protocol's stop message on lo (kernel "
                "receive timestamps on lo)\nmachine: %u cores, %s\n",
                std::thread::hardware_concurrency(), cpuModel().c_str());

    for (const QString& load : loads) {
        const bool full = load == "full";
        QTemporaryDir dir;
        const QString cfg = dir.filePath("site.json");
        std::vector<std::string> simArgs{
            OCU_SIM_BINARY,    "--duration",        "3600",           "--ugvs",         full ? "20" : "1",
            "--trucks",        full ? "1000" : "1", "--rollers",      full ? "3" : "1", "--truck-rate",
            full ? "10" : "2", "--write-config",    cfg.toStdString()};
        const pid_t sim = spawn(simArgs, -1, dir.filePath("ocu-sim.log").toLocal8Bit().constData(), simNice);
        const QJsonObject site = waitForConfig(cfg, sim);
        if (site.isEmpty()) {
            std::fprintf(stderr, "bench_stop: ocu-sim wrote no configuration\n");
            endChild(sim, SIGTERM, 5000);
            return 3;
        }
        sn.ahsPort = static_cast<std::uint16_t>(QUrl(site["iso23725"]["links"][0]["url"].toString()).port());
        sn.osyrisPort = static_cast<std::uint16_t>(site["osyris"]["port"].toInt());
        std::printf("\nload %s: ocu-sim %s at nice %d (AHS port %u, OSYRIS port %u); stop-path priority %s\n",
                    qPrintable(load),
                    full ? "--ugvs 20 --trucks 1000 --truck-rate 10 --rollers 3"
                         : "--ugvs 1 --trucks 1 --truck-rate 2 --rollers 1",
                    simNice, sn.ahsPort, sn.osyrisPort,
                    qEnvironmentVariableIsEmpty("OCU_THREAD_PRIORITY")
                        ? "rt (default)"
                        : qgetenv("OCU_THREAD_PRIORITY").constData());

        if (triggers.contains("window") || triggers.contains("click")) {
            auto loaded = ocu::loadSite(cfg);
            if (!loaded) {
                std::fprintf(stderr, "bench_stop: %s\n", loaded.error().c_str());
                return 3;
            }
            ocu::SiteConfig config = std::move(loaded.value());
            config.simulation.enabled = false;
            Samples s;
            {
                ocu::SiteRuntime runtime(config);
                runtime.start();
                ocu::MainWindow window;
                runtime.populate(window);
                window.resize(1366, 768);
                window.show();
                auto* stopAll = window.findChild<QAction*>("action-stop-all");
                if (!stopAll) {
                    std::fprintf(stderr, "bench_stop: the main window has no action-stop-all\n");
                    return 3;
                }
                const std::string before = loadAverage();
                // JAUS is recorded when seen, not awaited: the window trials measure the ISO 23725 and OSYRIS
                // stops (STOP ALL reaches every discovered UGV, controlled or not; the headless trials below
                // take control first, as their warm-up always did).
                const unsigned mask = (1u << Iso) | (1u << Osyris);
                if (triggers.contains("window") &&
                    trials(
                        sn, s, n, true, mask, [stopAll] { stopAll->trigger(); }, [] {}))
                    report(qPrintable(load), "window (QAction::trigger)", s, before);
                if (triggers.contains("click")) {
                    ocu::test::XTestClicker clicker;
                    if (!clicker.open(error)) {
                        std::fprintf(stderr, "bench_stop: --trigger click: %s\n", error.c_str());
                        return 3;
                    }
                    auto* button = window.findChild<QWidget*>("button-stop-all");
                    QElapsedTimer shown;
                    shown.start();
                    while ((!window.windowHandle() || !window.windowHandle()->isExposed()) &&
                           shown.elapsed() < 10000)
                        pause(20, true);
                    if (!button || !button->isVisible()) {
                        std::fprintf(stderr, "bench_stop: the main window shows no button-stop-all\n");
                        return 3;
                    }
                    const QPoint at = button->mapToGlobal(button->rect().center());
                    clicker.moveTo(at.x(), at.y());
                    Samples c;
                    const std::string clickBefore = loadAverage();
                    if (trials(
                            sn, c, n, true, mask, [&clicker] { clicker.press(); }, [] {},
                            [&clicker] { clicker.release(); }))
                        report(qPrintable(load), "click (XTest press on the STOP ALL button)", c,
                               clickBefore);
                }
                runtime.stop();
            }
        }
        if (triggers.contains("headless")) {
            int in[2];
            if (::pipe2(in, O_CLOEXEC) != 0)
                return 3;
            const int child = ::fcntl(in[0], F_DUPFD, 10); // not close-on-exec: becomes the child's stdin
            const pid_t ocu = spawn({OCU_BINARY, "--config", cfg.toStdString(), "--no-sim", "--headless"},
                                    child, dir.filePath("ocu.log").toLocal8Bit().constData());
            ::close(child);
            ::close(in[0]);
            static const char kLine[] = "{\"cmd\":\"stop_all\"}\n";
            Samples s;
            const std::string before = loadAverage();
            // The warm-up takes control of every UGV (as a UGV operator's console would), and JAUS is
            // measured too.
            std::string control;
            for (const auto& e : site["jaus"]["static_endpoints"].toArray())
                control += "{\"cmd\":\"request_control\",\"id\":\"jaus:" +
                           std::to_string(e.toObject()["subsystem"].toInt()) + "\"}\n";
            auto send = [fd = in[1]](const std::string& line) {
                [[maybe_unused]] auto w = ::write(fd, line.data(), line.size());
            };
            if (trials(
                    sn, s, n, false, 7u, [&] { send(kLine); }, [&] { send(control); }))
                report(qPrintable(load), "headless (stdin line)", s, before);
            ::close(in[1]); // end of input: the monitor exits
            endChild(ocu, 0, 10000);
        }
        endChild(sim, SIGTERM, 10000);
    }
    std::printf("\nsniffer saw %llu packets\n", static_cast<unsigned long long>(sn.packets()));
    return 0;
}
