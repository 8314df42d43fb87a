#include "tests/ProtocolNames.h"

#include <QFile>
#include <QRegularExpression>

namespace ocu::rules {

QStringList protocolNeutralFiles() {
    return {QStringLiteral("app/MainWindow.h"), QStringLiteral("app/MainWindow.cpp"),
            QStringLiteral("app/SiteRuntime.h"), QStringLiteral("app/SiteRuntime.cpp"),
            QStringLiteral("app/ReplayRuntime.h"), QStringLiteral("app/ReplayRuntime.cpp"),
            QStringLiteral("app/HeadlessMonitor.h"), QStringLiteral("app/HeadlessMonitor.cpp"),
            QStringLiteral("app/HeadlessCommands.h"), QStringLiteral("app/HeadlessCommands.cpp"),
            QStringLiteral("app/sim_main.cpp"),
            // The workspaces are laid out from the kinds the panels declare (the one table of jobs and kinds,
            // app/WorkspaceLayout.cpp, names the jobs: Dispatch, UGV, crew messages).
            QStringLiteral("app/MainWindowWorkspaces.cpp"), QStringLiteral("app/WorkspaceBar.h"),
            QStringLiteral("app/WorkspaceBar.cpp")};
}

QVector<ProtocolNameUse> findProtocolNames(const QString& root, const QStringList& files) {
    static const QRegularExpression names(
        QStringLiteral(R"(jaus|osyris|iso[ _-]?23725|\bahs\b|\bfms\b|\bugvs?\b|\bcrew|dispatch|teleop)"),
        QRegularExpression::CaseInsensitiveOption);
    QVector<ProtocolNameUse> out;
    for (const QString& rel : files) {
        QFile f(root + QLatin1Char('/') + rel);
        if (!f.open(QIODevice::ReadOnly)) {
            out.push_back({rel, 0, QStringLiteral("(cannot read the file)")});
            continue;
        }
        int line = 0;
        while (!f.atEnd()) {
            const QString text = QString::fromUtf8(f.readLine());
            ++line;
            for (auto it = names.globalMatch(text); it.hasNext();)
                out.push_back({rel, line, it.next().captured()});
        }
    }
    return out;
}

} // namespace ocu::rules
