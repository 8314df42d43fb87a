#pragma once
// Panels grey out what the operator's role may not do: a control whose command the command gate would refuse
// is disabled, its tooltip naming the role needed, and enabled again when another operator or role may.
// Stops are never greyed: the gate allows them to everyone, signed in or locked.
#include <QString>

class QAction;
class QWidget;

namespace ocu {

class CommandGate;

// Whether the operator at the console may issue `command` (commandName) now; no gate: yes. While not, the
// widget's tooltip says why below its own text; once it may, its own text alone again.
bool permittedShowingWhy(QWidget* widget, const CommandGate* gate, const QString& command);
bool permittedShowingWhy(QAction* action, const CommandGate* gate, const QString& command);

// For a control with no other condition: enabled exactly while the operator may issue `command`, checked
// again on every change of operator, role or lock.
void enableWhilePermitted(QWidget* widget, CommandGate* gate, const QString& command);

} // namespace ocu
