#include "widgets/CommandPermissionHint.h"

#include "models/CommandGate.h"

#include <QAction>
#include <QCoreApplication>
#include <QPointer>
#include <QWidget>

namespace ocu {

namespace {

// The refusal line last added to the object's tooltip (the panel may have set a new tooltip since).
const char* const kRefusalProperty = "ocuRefusalTip";

QString refusalOf(const CommandGate* gate, const QString& command) {
    QString why;
    if (gate == nullptr || gate->mayIssue(command, &why))
        return {};
    if (!gate->isLocked())
        why = gate->permissions().roleNeededText(command, gate->operatorIdentity().role);
    return why.isEmpty() ? QCoreApplication::translate("ocu::CommandPermissionHint", "Not permitted") : why;
}

template <typename T> bool showWhy(T* object, const CommandGate* gate, const QString& command) {
    QString own = object->toolTip();
    const QString last = object->property(kRefusalProperty).toString();
    if (!last.isEmpty() && own.endsWith(last)) {
        own.chop(last.size());
        if (own.endsWith(QLatin1Char('\n')))
            own.chop(1);
    }
    const QString why = refusalOf(gate, command);
    const QString tip = why.isEmpty() ? own : own.isEmpty() ? why : own + QLatin1Char('\n') + why;
    object->setProperty(kRefusalProperty, why.isEmpty() ? QVariant() : QVariant(why));
    if (tip != object->toolTip())
        object->setToolTip(tip);
    return why.isEmpty();
}

} // namespace

bool permittedShowingWhy(QWidget* widget, const CommandGate* gate, const QString& command) {
    return showWhy(widget, gate, command);
}

bool permittedShowingWhy(QAction* action, const CommandGate* gate, const QString& command) {
    return showWhy(action, gate, command);
}

void enableWhilePermitted(QWidget* widget, CommandGate* gate, const QString& command) {
    const auto apply = [widget, gate = QPointer<CommandGate>(gate), command] {
        widget->setEnabled(permittedShowingWhy(widget, gate, command));
    };
    if (gate != nullptr)
        QObject::connect(gate, &CommandGate::permissionsChanged, widget, apply);
    apply();
}

} // namespace ocu
