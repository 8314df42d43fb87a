#pragma once
// The log category of the console's ISO 23725 stack: one name, so that a site can filter the stack's lines.

namespace ocu::iso23725 {

inline constexpr const char* kLog = "ocu.iso";

} // namespace ocu::iso23725
