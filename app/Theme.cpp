#include "app/Theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyle>
#include <QStyleFactory>

namespace ocu {

void applyTheme(QApplication& app, Theme theme) {
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QPalette p;
    if (theme == Theme::Night) {
        // Dim, low-blue palette: readable without ruining night vision; status colours stay saturated.
        const QColor window(37, 37, 40), base(24, 24, 27), text(214, 214, 210), disabled(120, 120, 120);
        p.setColor(QPalette::Window, window);
        p.setColor(QPalette::WindowText, text);
        p.setColor(QPalette::Base, base);
        p.setColor(QPalette::AlternateBase, QColor(32, 32, 36));
        p.setColor(QPalette::ToolTipBase, window);
        p.setColor(QPalette::ToolTipText, text);
        p.setColor(QPalette::Text, text);
        p.setColor(QPalette::Button, QColor(48, 48, 52));
        p.setColor(QPalette::ButtonText, text);
        p.setColor(QPalette::BrightText, QColor(255, 90, 90));
        p.setColor(QPalette::Link, QColor(110, 160, 220));
        p.setColor(QPalette::Highlight, QColor(60, 100, 150));
        p.setColor(QPalette::HighlightedText, QColor(240, 240, 240));
        p.setColor(QPalette::PlaceholderText, disabled);
        p.setColor(QPalette::Disabled, QPalette::Text, disabled);
        p.setColor(QPalette::Disabled, QPalette::ButtonText, disabled);
        p.setColor(QPalette::Disabled, QPalette::WindowText, disabled);
    } else {
        p = app.style()->standardPalette();
    }
    app.setPalette(p);
    app.setProperty("ocuTheme", theme == Theme::Night ? "night" : "day");
}

} // namespace ocu
