#pragma once
// Who may do what at a console: the operator roles, the site configuration's "roles" section that maps
// operating-system users and groups to them, and the JAUS authority code each role commands with
// (docs/roles.md). Plain C++: the site configuration reads it, the console's command gate decides with it.
#include "protocols/common/ConfigReader.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocu {

// In rank order: a user in several configured groups gets the highest of their roles.
enum class OperatorRole { Monitor, Dispatcher, SiteManager, UgvOperator, Supervisor, Admin };
inline constexpr std::array<OperatorRole, 6> kAllOperatorRoles{
    OperatorRole::Monitor,     OperatorRole::Dispatcher, OperatorRole::SiteManager,
    OperatorRole::UgvOperator, OperatorRole::Supervisor, OperatorRole::Admin};

// "monitor", "dispatcher", "site_manager", "ugv_operator", "supervisor", "admin".
std::string_view roleName(OperatorRole role);
std::optional<OperatorRole> roleFromName(std::string_view name);

struct RolesConfig {
    // False when the site has no "roles" section: roles are not managed, every operator is an admin
    // (the console as it was before roles; docs/roles.md).
    bool configured = false;
    std::map<std::string, OperatorRole> users;  // OS user name -> role
    std::map<std::string, OperatorRole> groups; // OS group name -> role
    // JAUS authority per role (AEP-4818 §4.3.2: 0 = monitor, 205-239 primary operator, 240-254 safety
    // critical), indexed by OperatorRole.
    std::array<int, 6> authority{0, 0, 0, 205, 220, 230};
    // The console locks after this long without keyboard or mouse activity (seconds; 0 = never).
    double lockAfterIdleS = 0;

    // The role of a user who belongs to `groups`: their own entry, else the highest role of their groups,
    // else monitor. Admin when roles are not configured.
    OperatorRole roleOf(const std::string& user, const std::vector<std::string>& groups) const;
    int authorityOf(OperatorRole role) const { return authority[static_cast<std::size_t>(role)]; }
};

// Reads the "roles" object strictly (unknown users' roles, authorities outside the bands: errors with
// file:line). Calls section.finish().
RolesConfig parseRolesConfig(ConfigObject& section);

// The operating-system user running this process (getpwuid(geteuid())) and the groups it belongs to.
struct OsUser {
    std::string name;
    std::vector<std::string> groups;
};
OsUser currentOsUser();
// The groups of a named user (its primary group first); empty when the user is unknown.
std::vector<std::string> groupsOfUser(const std::string& user);

} // namespace ocu
