#pragma once
// The dependency rule of the source tree (docs/architecture.md, "Folders and what they may include"), checked
// by path on every #include of a source tree. test_include_rules runs it on this repository and on
// synthetic trees that break each rule.
//
// Folders (relative to the repository root, the one include root):
//   protocols/common/        includes protocols/common/ only.
//   protocols/<stack>/       includes protocols/common/ and protocols/<stack>/ only (jaus, iso23725, osyris,
//   ...).
//                            Not protocols/site/: the site configuration aggregates every stack's
//                            configuration, so a stack that included it would depend on the other stacks (and
//                            on itself).
//   protocols/site/          includes protocols/common/, protocols/site/ and the configuration header of each
//                            stack, protocols/<stack>/<Name>Config.h (nothing else of a stack).
//   sim/<stack>/             includes protocols/ (common, site, its own stack) and sim/<stack>/.
//   sim/ (top level files) and sim/modules/
//                            include protocols/ and sim/ (they compose the simulators into one site).
//   protocols/, sim/         include no Qt and nothing from models/, widgets/, app/.
//   models/                  includes models/ and protocols/; nothing from widgets/, app/, sim/.
//   widgets/                 includes widgets/, models/ and protocols/common/ only, and never reaches a stack
//                            header (protocols/<stack>/, protocols/site/) through the headers it includes,
//                            e.g. a models/ header that includes a stack header.
//   app/                     may include everything.
//   tests/, bench/           are not checked.
// Everywhere: a quoted include names its folder from the repository root ("models/FleetModel.h"), except
// generated files (*.moc, moc_*, ui_*).
#include <QString>
#include <QVector>

namespace ocu::rules {

struct IncludeViolation {
    QString file;    // relative to the root
    int line = 0;    // 1-based
    QString include; // as written
    QString rule;    // which rule, in words
    QString chain;   // for transitive violations: file -> header -> ... -> offending header
    QString toString() const;
};

// Checks every .h/.hpp/.cpp/.cc under protocols/, sim/, models/, widgets/ and app/ of `root`.
QVector<IncludeViolation> checkIncludeRules(const QString& root);

} // namespace ocu::rules
