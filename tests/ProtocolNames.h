#pragma once
// The seam between the console and its protocols, checked by name: the shared app files (the window, the
// runtime, the replay, ocu-sim's main) name no protocol and no protocol's feature, in code or comments. A
// protocol's part lives in its module (app/modules/, sim/modules/). test_include_rules runs it on this
// repository and on a synthetic tree that breaks it.
#include <QString>
#include <QStringList>
#include <QVector>

namespace ocu::rules {

// The files that must name no protocol, relative to the repository root.
QStringList protocolNeutralFiles();

struct ProtocolNameUse {
    QString file; // relative to the root
    int line = 0; // 1-based
    QString word; // as written
    QString toString() const { return QStringLiteral("%1:%2: names \"%3\"").arg(file).arg(line).arg(word); }
};

// Every protocol name (JAUS, ISO 23725, OSYRIS) or protocol feature (dispatch, crew messages, teleop, the
// AHS, UGVs) in `files` under `root`; a file that cannot be read is reported with line 0.
QVector<ProtocolNameUse> findProtocolNames(const QString& root, const QStringList& files);

} // namespace ocu::rules
