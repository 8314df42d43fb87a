#pragma once
// The protocol stacks speak std::string (no Qt below models/); the bridges show it in Qt's strings.
#include <QString>

#include <string>

namespace ocu {

inline QString toQString(const std::string& s) {
    return QString::fromStdString(s);
}

} // namespace ocu
