#include "tests/IncludeRules.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QQueue>
#include <QRegularExpression>
#include <QSet>

#include <optional>

namespace ocu::rules {

QString IncludeViolation::toString() const {
    QString s = QStringLiteral("%1:%2: #include %3: %4").arg(file).arg(line).arg(include, rule);
    if (!chain.isEmpty())
        s += QStringLiteral(" (%1)").arg(chain);
    return s;
}

namespace {

const QStringList kCheckedFolders{QStringLiteral("protocols"), QStringLiteral("sim"),
                                  QStringLiteral("models"), QStringLiteral("widgets"), QStringLiteral("app")};
const QStringList kProjectFolders =
    kCheckedFolders + QStringList{QStringLiteral("tests"), QStringLiteral("bench")};

struct Include {
    int line = 0;
    QString name;   // path as written, without delimiters
    QString quoted; // as written, with delimiters
    bool angle = false;
};

enum class Zone { ProtoCommon, ProtoSite, ProtoStack, SimStack, SimTop, Models, Widgets, App, Other };

struct Place {
    Zone zone = Zone::Other;
    QString stack; // protocols/<stack>, sim/<stack>
};

Place placeOf(const QString& rel) {
    const QStringList parts = rel.split(QLatin1Char('/'));
    const QString top = parts.value(0);
    const bool inSub = parts.size() >= 3;
    if (top == QLatin1String("protocols")) {
        if (inSub && parts[1] == QLatin1String("common"))
            return {Zone::ProtoCommon, {}};
        if (inSub && parts[1] == QLatin1String("site"))
            return {Zone::ProtoSite, {}};
        return {Zone::ProtoStack, inSub ? parts[1] : QString()};
    }
    if (top == QLatin1String("sim")) {
        if (inSub && parts[1] != QLatin1String("modules"))
            return {Zone::SimStack, parts[1]};
        return {Zone::SimTop, {}};
    }
    if (top == QLatin1String("models"))
        return {Zone::Models, {}};
    if (top == QLatin1String("widgets"))
        return {Zone::Widgets, {}};
    if (top == QLatin1String("app"))
        return {Zone::App, {}};
    return {Zone::Other, {}};
}

bool isQtHeader(const Include& inc) {
    static const QRegularExpression qt(
        QStringLiteral(R"(^(Qt[A-Za-z]*|Q[A-Z][A-Za-z0-9]*)(/.*)?$|^q[a-z0-9_]+\.h$)"));
    return inc.angle && qt.match(inc.name).hasMatch();
}

bool isGenerated(const QString& name) {
    const QString file = QFileInfo(name).fileName();
    return file.endsWith(QLatin1String(".moc")) || file.startsWith(QLatin1String("moc_")) ||
           file.startsWith(QLatin1String("ui_"));
}

// The rule a direct include from `from` to the project file `target` breaks, or nothing.
std::optional<QString> directRule(const Place& from, const QString& target) {
    const Place to = placeOf(target);
    const bool toProtocols =
        to.zone == Zone::ProtoCommon || to.zone == Zone::ProtoSite || to.zone == Zone::ProtoStack;
    switch (from.zone) {
    case Zone::ProtoCommon:
    case Zone::ProtoSite:
    case Zone::ProtoStack:
    case Zone::SimStack:
    case Zone::SimTop:
        if (to.zone == Zone::Models || to.zone == Zone::Widgets || to.zone == Zone::App ||
            to.zone == Zone::Other)
            return QStringLiteral(
                "protocols/ and sim/ include nothing from models/, widgets/, app/ (or tests/, "
                "bench/)");
        break;
    case Zone::Models:
        if (to.zone == Zone::Models || toProtocols)
            return std::nullopt;
        return QStringLiteral("models/ includes only models/ and protocols/");
    case Zone::Widgets:
        if (to.zone == Zone::Widgets || to.zone == Zone::Models || to.zone == Zone::ProtoCommon)
            return std::nullopt;
        if (toProtocols)
            return QStringLiteral(
                "widgets/ include from protocols/ only protocols/common/, never a stack header");
        return QStringLiteral("widgets/ include only widgets/, models/ and protocols/common/");
    case Zone::App:
    case Zone::Other:
        return std::nullopt;
    }
    switch (from.zone) {
    case Zone::ProtoCommon:
        if (to.zone != Zone::ProtoCommon)
            return QStringLiteral("protocols/common/ includes only protocols/common/");
        break;
    case Zone::ProtoStack:
        if (to.zone == Zone::ProtoCommon || (to.zone == Zone::ProtoStack && to.stack == from.stack))
            break;
        if (to.zone == Zone::ProtoSite)
            return QStringLiteral(
                "protocols/<stack>/ does not include protocols/site/ (the site configuration "
                "aggregates every stack)");
        return QStringLiteral("protocols/<stack>/ includes only protocols/common/ and itself");
    case Zone::ProtoSite:
        if (to.zone == Zone::ProtoCommon || to.zone == Zone::ProtoSite)
            break;
        if (to.zone == Zone::ProtoStack && QFileInfo(target).fileName().endsWith(QLatin1String("Config.h")))
            break;
        return QStringLiteral("protocols/site/ includes only protocols/common/, itself and the stacks' "
                              "protocols/<stack>/*Config.h");
    case Zone::SimStack:
        if (to.zone == Zone::ProtoCommon || to.zone == Zone::ProtoSite)
            break;
        if ((to.zone == Zone::ProtoStack || to.zone == Zone::SimStack) && to.stack == from.stack)
            break;
        return QStringLiteral(
            "sim/<stack>/ includes only protocols/common/, protocols/site/, protocols/<stack>/ "
            "and sim/<stack>/ of its own stack");
    case Zone::SimTop:
        break; // protocols/ and sim/
    default:
        break;
    }
    return std::nullopt;
}

class Checker {
public:
    explicit Checker(QString root) : m_root(std::move(root)) {}

    QVector<IncludeViolation> run() {
        QVector<IncludeViolation> out;
        for (const QString& rel : sourceFiles())
            checkFile(rel, out);
        return out;
    }

private:
    QStringList sourceFiles() const {
        QStringList files;
        for (const QString& folder : kCheckedFolders) {
            QDirIterator it(m_root + QLatin1Char('/') + folder, {"*.h", "*.hpp", "*.cpp", "*.cc", "*.cxx"},
                            QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext())
                files << QDir(m_root).relativeFilePath(it.next());
        }
        files.sort();
        return files;
    }

    const QVector<Include>& includesOf(const QString& rel) {
        auto it = m_includes.find(rel);
        if (it != m_includes.end())
            return *it;
        static const QRegularExpression re(QStringLiteral(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])"));
        QVector<Include> incs;
        QFile f(m_root + QLatin1Char('/') + rel);
        if (f.open(QIODevice::ReadOnly | QIODevice::Text)) {
            int line = 0;
            while (!f.atEnd()) {
                const QString text = QString::fromUtf8(f.readLine());
                ++line;
                const auto m = re.match(text);
                if (!m.hasMatch())
                    continue;
                const bool angle = m.captured(1) == QLatin1String("<");
                incs.push_back({line, m.captured(2).trimmed(),
                                angle ? QStringLiteral("<%1>").arg(m.captured(2).trimmed())
                                      : QStringLiteral("\"%1\"").arg(m.captured(2).trimmed()),
                                angle});
            }
        }
        return *m_includes.insert(rel, incs);
    }

    // The repository file an include names, when it names one of the project's folders.
    std::optional<QString> projectFile(const Include& inc) const {
        const QString first = inc.name.section(QLatin1Char('/'), 0, 0);
        if (!inc.name.contains(QLatin1Char('/')) || !kProjectFolders.contains(first))
            return std::nullopt;
        return QDir::cleanPath(inc.name);
    }

    bool exists(const QString& rel) const { return QFileInfo(m_root + QLatin1Char('/') + rel).isFile(); }

    void checkFile(const QString& rel, QVector<IncludeViolation>& out) {
        const Place from = placeOf(rel);
        const bool qtFree = from.zone == Zone::ProtoCommon || from.zone == Zone::ProtoSite ||
                            from.zone == Zone::ProtoStack || from.zone == Zone::SimStack ||
                            from.zone == Zone::SimTop;
        for (const Include& inc : includesOf(rel)) {
            if (qtFree && isQtHeader(inc)) {
                out.push_back(
                    {rel, inc.line, inc.quoted, QStringLiteral("protocols/ and sim/ include no Qt"), {}});
                continue;
            }
            const auto target = projectFile(inc);
            if (!target) {
                if (!inc.angle && !isGenerated(inc.name))
                    out.push_back(
                        {rel,
                         inc.line,
                         inc.quoted,
                         QStringLiteral("a quoted include names its folder from the repository root"),
                         {}});
                continue;
            }
            if (!inc.angle && !exists(*target)) {
                out.push_back(
                    {rel, inc.line, inc.quoted, QStringLiteral("no such file from the repository root"), {}});
                continue;
            }
            if (auto rule = directRule(from, *target))
                out.push_back({rel, inc.line, inc.quoted, *rule, {}});
        }
        if (from.zone == Zone::Widgets)
            checkWidgetClosure(rel, out);
    }

    // Everything a widgets/ file reaches through project headers: no stack header on any path.
    void checkWidgetClosure(const QString& rel, QVector<IncludeViolation>& out) {
        struct Node {
            QString file;
            QString parent;
            int firstLine = 0;    // line of the direct include in `rel` this path started with
            QString firstInclude; // that include as written
        };
        QHash<QString, Node> seen;
        QQueue<QString> queue;
        seen.insert(rel, {rel, {}, 0, {}});
        queue.enqueue(rel);
        while (!queue.isEmpty()) {
            const QString cur = queue.dequeue();
            const Node curNode = seen.value(cur);
            for (const Include& inc : includesOf(cur)) {
                const auto target = projectFile(inc);
                if (!target || seen.contains(*target) || !exists(*target))
                    continue;
                if (cur == rel && directRule(placeOf(rel), *target))
                    continue; // already reported as a direct violation
                Node n{*target, cur, cur == rel ? inc.line : curNode.firstLine,
                       cur == rel ? inc.quoted : curNode.firstInclude};
                seen.insert(*target, n);
                const Zone z = placeOf(*target).zone;
                if (z == Zone::ProtoStack || z == Zone::ProtoSite) {
                    if (cur != rel) { // direct includes were judged above
                        QStringList chain{*target};
                        for (QString p = cur; !p.isEmpty(); p = seen.value(p).parent)
                            chain.prepend(p);
                        out.push_back(
                            {rel, n.firstLine, n.firstInclude,
                             QStringLiteral("widgets/ never reach a stack header through the headers "
                                            "they include"),
                             chain.join(QStringLiteral(" -> "))});
                    }
                    continue; // one report per offending header; do not walk the stack's own includes
                }
                queue.enqueue(*target);
            }
        }
    }

    QString m_root;
    QHash<QString, QVector<Include>> m_includes;
};

} // namespace

QVector<IncludeViolation> checkIncludeRules(const QString& root) {
    return Checker(QDir(root).absolutePath()).run();
}

} // namespace ocu::rules
