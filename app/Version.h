#pragma once
// The build's version (cmake/OcuVersion.cmake: from `git describe` at configure time). Generated into one
// small source file so a new version recompiles that file only.
#include <QString>

namespace ocu {

QString versionString();

} // namespace ocu
