// The dependency rule of the source tree (tests/IncludeRules.h, docs/architecture.md) and the protocol seam
// (tests/ProtocolNames.h): this repository follows them, and the checkers find each kind of violation in a
// synthetic tree.
#include "tests/IncludeRules.h"
#include "tests/ProtocolNames.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

using namespace ocu::rules;

namespace {

// A tree of files: {relative path, content}.
using Tree = QList<QPair<QString, QString>>;

QVector<IncludeViolation> check(const Tree& tree) {
    QTemporaryDir dir;
    if (!dir.isValid())
        qFatal("no temporary directory");
    for (const auto& [rel, content] : tree) {
        const QString path = dir.filePath(rel);
        QDir().mkpath(QFileInfo(path).absolutePath());
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            qFatal("cannot write %s", qPrintable(path));
        f.write(content.toUtf8());
    }
    return checkIncludeRules(dir.path());
}

QString describe(const QVector<IncludeViolation>& v) {
    QStringList lines;
    for (const auto& x : v)
        lines << x.toString();
    return lines.join(QLatin1Char('\n'));
}

// Headers every synthetic tree has, so that includes of them resolve.
const Tree kBase{
    {"protocols/common/Clock.h", "#pragma once\n#include <chrono>\n"},
    {"protocols/jaus/JausConfig.h", "#pragma once\n#include \"protocols/common/Clock.h\"\n"},
    {"protocols/jaus/JausTypes.h", "#pragma once\n#include \"protocols/jaus/JausConfig.h\"\n"},
    {"protocols/osyris/OsyrisStack.h", "#pragma once\n"},
    {"protocols/site/SiteConfig.h", "#pragma once\n#include \"protocols/jaus/JausConfig.h\"\n"},
    {"sim/jaus/SimulatedUgv.h", "#pragma once\n#include \"protocols/jaus/JausTypes.h\"\n"},
    {"sim/osyris/SimulatedRoller.h", "#pragma once\n#include \"protocols/osyris/OsyrisStack.h\"\n"},
    {"models/FleetModel.h", "#pragma once\n#include <QObject>\n#include \"protocols/common/Clock.h\"\n"},
    {"models/jaus/JausVehicle.h", "#pragma once\n#include <QString>\n"},
    {"models/bridges/JausBridge.h",
     "#pragma once\n#include \"models/FleetModel.h\"\n#include \"protocols/jaus/JausTypes.h\"\n"},
    {"widgets/FleetList.h", "#pragma once\n#include <QWidget>\n#include \"models/FleetModel.h\"\n"},
    {"app/Main.cpp", "#include \"widgets/FleetList.h\"\n#include \"models/bridges/JausBridge.h\"\n"
                     "#include \"sim/jaus/SimulatedUgv.h\"\n"},
};

// Declarations of a toString that takes an argument, as "path:line". QCOMPARE prints a value with an
// unqualified toString(value), so argument-dependent lookup picks such a function over QTest's own and
// then frees the static text it returns: a failing comparison aborts instead of reporting.
QStringList toStringTakingAnArgument(const QString& root) {
    static const QRegularExpression decl(
        QStringLiteral(R"(^\s*(?:static\s+)?(?:const\s+)?[\w:]+\s*\*?\s*toString\(\s*\w)"),
        QRegularExpression::MultilineOption);
    QStringList out;
    QDirIterator it(root, {QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        const QString rel = QDir(root).relativeFilePath(path);
        if (rel.startsWith(QLatin1String("build")) || rel.startsWith(QLatin1Char('.')))
            continue;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            continue;
        const QString text = QString::fromUtf8(f.readAll());
        for (auto m = decl.globalMatch(text); m.hasNext();) {
            const auto hit = m.next();
            out << QStringLiteral("%1:%2").arg(rel).arg(
                text.left(hit.capturedStart()).count(QLatin1Char('\n')) + 1);
        }
    }
    return out;
}

} // namespace

class TestIncludeRules : public QObject {
    Q_OBJECT
private slots:
    void repositoryFollowsTheRule() {
        const auto v = checkIncludeRules(QStringLiteral(OCU_SOURCE_DIR));
        for (const auto& x : v)
            qWarning().noquote() << x.toString();
        QVERIFY2(v.isEmpty(),
                 qPrintable(
                     QStringLiteral("%1 include(s) break the dependency rule (listed above)").arg(v.size())));
    }

    void cleanTreePasses() {
        const auto v = check(kBase);
        QVERIFY2(v.isEmpty(), qPrintable(describe(v)));
    }

    void violations_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("content");
        QTest::addColumn<QString>("rule"); // a part of the expected rule text
        QTest::addColumn<int>("line");

        QTest::newRow("protocols includes Qt") << "protocols/jaus/Bad.cpp"
                                               << "#include <vector>\n#include <QString>\n"
                                               << "include no Qt" << 2;
        QTest::newRow("protocols includes QtCore/") << "protocols/common/Bad.h"
                                                    << "#include <QtCore/QObject>\n"
                                                    << "include no Qt" << 1;
        QTest::newRow("sim includes Qt") << "sim/jaus/Bad.cpp"
                                         << "#include \"sim/jaus/SimulatedUgv.h\"\n#  include <QTimer>\n"
                                         << "include no Qt" << 2;
        QTest::newRow("protocols includes models") << "protocols/jaus/Bad.cpp"
                                                   << "#include \"models/FleetModel.h\"\n"
                                                   << "nothing from models/, widgets/, app/" << 1;
        QTest::newRow("sim includes widgets") << "sim/Bad.cpp"
                                              << "#include \"widgets/FleetList.h\"\n"
                                              << "nothing from models/, widgets/, app/" << 1;
        QTest::newRow("sim includes app") << "sim/osyris/Bad.cpp"
                                          << "#include \"app/Main.cpp\"\n"
                                          << "nothing from models/, widgets/, app/" << 1;
        QTest::newRow("stack includes another stack") << "protocols/jaus/Bad.cpp"
                                                      << "#include \"protocols/osyris/OsyrisStack.h\"\n"
                                                      << "only protocols/common/ and itself" << 1;
        QTest::newRow("stack includes the site") << "protocols/jaus/Bad.h"
                                                 << "#include \"protocols/site/SiteConfig.h\"\n"
                                                 << "does not include protocols/site/" << 1;
        QTest::newRow("common includes a stack") << "protocols/common/Bad.h"
                                                 << "#include \"protocols/jaus/JausTypes.h\"\n"
                                                 << "protocols/common/ includes only protocols/common/" << 1;
        QTest::newRow("site includes more than a stack's configuration")
            << "protocols/site/Bad.cpp"
            << "#include \"protocols/jaus/JausConfig.h\"\n#include \"protocols/jaus/JausTypes.h\"\n"
            << "Config.h" << 2;
        QTest::newRow("sim stack includes another simulator") << "sim/jaus/Bad.cpp"
                                                              << "#include \"sim/osyris/SimulatedRoller.h\"\n"
                                                              << "of its own stack" << 1;
        QTest::newRow("sim stack includes another stack") << "sim/jaus/Bad.cpp"
                                                          << "#include \"protocols/osyris/OsyrisStack.h\"\n"
                                                          << "of its own stack" << 1;
        QTest::newRow("widget includes a stack header") << "widgets/jaus/Bad.h"
                                                        << "#include \"protocols/jaus/JausTypes.h\"\n"
                                                        << "never a stack header" << 1;
        QTest::newRow("widget includes the site configuration")
            << "widgets/Bad.cpp"
            << "#include \"protocols/site/SiteConfig.h\"\n"
            << "never a stack header" << 1;
        QTest::newRow("widget includes sim") << "widgets/Bad.cpp"
                                             << "#include \"sim/jaus/SimulatedUgv.h\"\n"
                                             << "widgets/ include only widgets/, models/" << 1;
        QTest::newRow("widget reaches a stack header through models/")
            << "widgets/jaus/Bad.cpp"
            << "#include \"widgets/FleetList.h\"\n#include \"models/bridges/JausBridge.h\"\n"
            << "never reach a stack header" << 2;
        QTest::newRow("widget reaches a stack header through a widget header")
            << "widgets/jaus/Bad.cpp"
            << "#include \"widgets/jaus/Middle.h\"\n"
            << "never reach a stack header" << 1;
        QTest::newRow("models include widgets") << "models/Bad.cpp"
                                                << "#include \"widgets/FleetList.h\"\n"
                                                << "models/ includes only models/ and protocols/" << 1;
        QTest::newRow("include without its folder") << "models/Bad.cpp"
                                                    << "#include \"FleetModel.h\"\n"
                                                    << "names its folder from the repository root" << 1;
        QTest::newRow("include of a missing file") << "app/Bad.cpp"
                                                   << "#include \"models/Nope.h\"\n"
                                                   << "no such file" << 1;
    }

    void violations() {
        QFETCH(QString, file);
        QFETCH(QString, content);
        QFETCH(QString, rule);
        QFETCH(int, line);
        Tree tree = kBase;
        tree.append(QPair<QString, QString>(file, content));
        // For the case through a widget header: a widgets/ header that includes the bridge.
        tree.append(QPair<QString, QString>("widgets/jaus/Middle.h",
                                            "#pragma once\n#include \"models/bridges/JausBridge.h\"\n"));
        auto v = check(tree);
        // widgets/jaus/Middle.h itself reaches the stack header: not the case under test.
        v.erase(std::remove_if(v.begin(), v.end(),
                               [&](const IncludeViolation& x) { return x.file == "widgets/jaus/Middle.h"; }),
                v.end());
        QVERIFY2(v.size() == 1, qPrintable(QStringLiteral("expected one violation, got:\n") + describe(v)));
        QCOMPARE(v[0].file, file);
        QCOMPARE(v[0].line, line);
        QVERIFY2(v[0].rule.contains(rule), qPrintable(v[0].toString()));
    }

    void transitiveViolationNamesTheChain() {
        Tree tree = kBase;
        tree.append(
            QPair<QString, QString>("widgets/jaus/Panel.cpp", "#include \"models/bridges/JausBridge.h\"\n"));
        const auto v = check(tree);
        QCOMPARE(v.size(), 1);
        QCOMPARE(v[0].chain, QStringLiteral("widgets/jaus/Panel.cpp -> models/bridges/JausBridge.h -> "
                                            "protocols/jaus/JausTypes.h"));
    }

    void generatedAndSystemIncludesAreAllowed() {
        Tree tree = kBase;
        tree.append(QPair<QString, QString>(
            "widgets/Panel.cpp", "#include \"widgets/FleetList.h\"\n#include <vector>\n"
                                 "#include \"Panel.moc\"\n#include \"moc_Panel.cpp\"\n"
                                 "#include \"ui_Panel.h\"\n#include \"protocols/common/Clock.h\"\n"));
        tree.append(QPair<QString, QString>("protocols/jaus/Codec.cpp",
                                            "#include <boost/asio.hpp>\n#include <nlohmann/json.hpp>\n"
                                            "// #include <QString> in a comment is no include\n"));
        const auto v = check(tree);
        QVERIFY2(v.isEmpty(), qPrintable(describe(v)));
    }

    // The shared app files name no protocol: everything a protocol adds comes through its module.
    void sharedAppFilesNameNoProtocol() {
        const auto uses = findProtocolNames(QStringLiteral(OCU_SOURCE_DIR), protocolNeutralFiles());
        QStringList lines;
        for (const auto& u : uses)
            lines << u.toString();
        QVERIFY2(uses.isEmpty(), qPrintable(lines.join(QLatin1Char('\n'))));
    }

    void noToStringThatQTestWouldFree() {
        const QStringList found = toStringTakingAnArgument(QStringLiteral(OCU_SOURCE_DIR));
        QVERIFY2(found.isEmpty(),
                 qPrintable(QStringLiteral("name these nameFor: ") + found.join(QLatin1Char(' '))));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile f(dir.filePath(QStringLiteral("Kinds.h")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#pragma once\nstruct Id { std::string toString() const; };\nconst char* nameFor(Kind k);\n"
                "const char* toString(Kind k);\n");
        f.close();
        QCOMPARE(toStringTakingAnArgument(dir.path()), QStringList{QStringLiteral("Kinds.h:4")});
    }

    void protocolNameInASharedFileIsFound() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QDir().mkpath(dir.filePath(QStringLiteral("app")));
        QFile f(dir.filePath(QStringLiteral("app/SiteRuntime.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#include \"app/SiteRuntime.h\"\n// the map of the fleet\n"
                "#include \"widgets/osyris/CrewMessagesPanel.h\"\nauto* b = findBridge(\"ISO 23725\");\n");
        f.close();
        const auto uses = findProtocolNames(dir.path(), {QStringLiteral("app/SiteRuntime.cpp")});
        QCOMPARE(uses.size(), 3);
        QCOMPARE(uses[0].line, 3);
        QCOMPARE(uses[0].word, QStringLiteral("osyris"));
        QCOMPARE(uses[1].word, QStringLiteral("Crew"));
        QCOMPARE(uses[2].line, 4);
        QCOMPARE(uses[2].word, QStringLiteral("ISO 23725"));
        // A file that is not there is reported, not passed.
        QCOMPARE(findProtocolNames(dir.path(), {QStringLiteral("app/Gone.cpp")}).size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestIncludeRules)
#include "test_include_rules.moc"
