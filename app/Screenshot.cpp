#include "app/Screenshot.h"

#include "app/MainWindow.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/Site3DView.h"
#endif

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QImageWriter>
#include <QPixmap>

#include <algorithm>

namespace ocu {

QString saveScreenshot(MainWindow& window, const QString& view, const QString& file) {
    QWidget* target = &window;
    // "all:<panel>": the whole window with that (tabbed) panel brought to the front.
    const bool whole = view.startsWith(QLatin1String("all:"));
    const QString panel = whole ? view.mid(4) : view;
    if (view != QLatin1String("all")) {
        target = nullptr;
        for (const QString& key : window.panelKeys()) {
            if (key == panel) {
                QDockWidget* d = window.dock(key);
                d->show();
                d->raise(); // a tabbed panel must be the visible tab to be painted
                // A little event loop: a panel may build its content on its first paint (the 3D view makes
                // its GL widget only once it is really on screen).
                QElapsedTimer t;
                t.start();
                while (t.elapsed() < 400)
                    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
#ifdef OCU_HAVE_OCU_VIEW3D
                // The 3D view's first frame can take longer than that on a loaded machine with a real X
                // server (GL context, first pipeline): wait for it, up to 10 s, rather than grab a blank
                // panel.
                if (auto* v3d = d->findChild<Site3DView*>())
                    while (v3d->renderCount() == 0 && t.elapsed() < 10000)
                        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
#endif
                target = whole ? static_cast<QWidget*>(&window) : d;
            }
        }
        if (!target)
            return QCoreApplication::translate("Screenshot", "unknown view \"%1\"").arg(view);
    }
    {
        // A widget that has not shown what it is about yet sets the property "screenshotPending": a video
        // view still connecting (its first frame), a map whose pass-count tiles are still owed to
        // its frame budget. Up to 10 s for them.
        const auto widgets = target->findChildren<QWidget*>();
        auto pending = [&widgets] {
            return std::any_of(widgets.begin(), widgets.end(), [](QWidget* w) {
                return w->isVisible() && w->property("screenshotPending").toBool();
            });
        };
        QElapsedTimer t;
        t.start();
        while (pending() && t.elapsed() < 10000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    const QPixmap pixmap = target->grab();
    if (pixmap.isNull())
        return QCoreApplication::translate("Screenshot", "nothing to grab for view \"%1\"").arg(view);
    QImageWriter writer(file, "png");
    if (!writer.write(pixmap.toImage()))
        return QCoreApplication::translate("Screenshot", "cannot write %1: %2")
            .arg(QFileInfo(file).absoluteFilePath(), writer.errorString());
    return {};
}

} // namespace ocu
