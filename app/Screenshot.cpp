#include "app/Screenshot.h"

#include "app/MainWindow.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QImageWriter>
#include <QPixmap>

namespace ocu {

QString saveScreenshot(MainWindow& window, const QString& view, const QString& file) {
    QWidget* target = &window;
    if (view != QLatin1String("all")) {
        target = nullptr;
        for (Panel p : MainWindow::panels()) {
            if (MainWindow::panelKey(p) == view) {
                QDockWidget* d = window.dock(p);
                d->show();
                d->raise(); // a tabbed panel must be the visible tab to be painted
                // A little event loop: a panel may build its content on its first paint (the 3D view makes
                // its GL widget only once it is really on screen).
                QElapsedTimer t;
                t.start();
                while (t.elapsed() < 400)
                    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
                target = d;
            }
        }
        if (!target)
            return QCoreApplication::translate("Screenshot", "unknown view \"%1\"").arg(view);
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
