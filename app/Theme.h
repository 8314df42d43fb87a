#pragma once
// Fusion style with a day palette (bright site office) and a night palette (cab or control room at night).
class QApplication;

namespace ocu {

enum class Theme { Day, Night };

void applyTheme(QApplication& app, Theme theme);

} // namespace ocu
