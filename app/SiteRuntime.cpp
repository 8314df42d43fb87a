#include "SiteRuntime.h"

#include "MainWindow.h"

#include <QApplication>
#include <QLabel>
#include <QTimer>

namespace ocu {

struct SiteRuntime::Impl {};

SiteRuntime::SiteRuntime(SiteConfig config, QObject* parent)
    : QObject(parent), m_config(std::move(config)), m_impl(std::make_unique<Impl>()) {}

SiteRuntime::~SiteRuntime() { stop(); }

QString SiteRuntime::start() { return {}; }

void SiteRuntime::stop() {}

void SiteRuntime::populate(MainWindow& window) {
    for (Panel p : MainWindow::panels()) {
        auto* l = new QLabel(tr("%1: no stack connected").arg(window.panelTitle(p)));
        l->setAlignment(Qt::AlignCenter);
        window.setPanelWidget(p, l);
    }
}

int SiteRuntime::runHeadless(QApplication& app, double durationSeconds) {
    if (durationSeconds > 0)
        QTimer::singleShot(static_cast<int>(durationSeconds * 1000), &app, &QApplication::quit);
    return app.exec();
}

} // namespace ocu
