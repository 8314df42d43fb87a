#include "protocols/common/OperatorRoles.h"

#include <nlohmann/json.hpp>

#include <grp.h>
#include <pwd.h>
#include <unistd.h>

namespace ocu {

namespace {
constexpr std::array<std::string_view, 6> kRoleNames{"monitor",      "dispatcher", "site_manager",
                                                     "ugv_operator", "supervisor", "admin"};

std::vector<std::string> roleNameList() {
    return {kRoleNames.begin(), kRoleNames.end()};
}

// {"name": "role", ...}: every value one of the role names.
std::map<std::string, OperatorRole> readRoleMap(ConfigObject& section, std::string_view key) {
    std::map<std::string, OperatorRole> out;
    auto obj = section.object(key);
    if (!obj)
        return out;
    const nlohmann::json* raw = section.raw(key);
    if (raw && raw->is_object())
        for (const auto& [name, value] : raw->items()) {
            const std::string role = obj->choice(name, "monitor", roleNameList());
            if (name.empty())
                obj->error(name, "an empty name matches nobody");
            else if (auto r = roleFromName(role); r && value.is_string())
                out[name] = *r;
        }
    obj->finish();
    return out;
}
} // namespace

std::string_view roleName(OperatorRole role) {
    return kRoleNames[static_cast<std::size_t>(role)];
}

std::optional<OperatorRole> roleFromName(std::string_view name) {
    for (std::size_t i = 0; i < kRoleNames.size(); ++i)
        if (kRoleNames[i] == name)
            return kAllOperatorRoles[i];
    return std::nullopt;
}

OperatorRole RolesConfig::roleOf(const std::string& user, const std::vector<std::string>& userGroups) const {
    if (!configured)
        return OperatorRole::Admin;
    if (auto it = users.find(user); it != users.end())
        return it->second;
    OperatorRole best = OperatorRole::Monitor;
    for (const std::string& g : userGroups)
        if (auto it = groups.find(g); it != groups.end() && it->second > best)
            best = it->second;
    return best;
}

RolesConfig parseRolesConfig(ConfigObject& section) {
    RolesConfig c;
    c.configured = true;
    c.users = readRoleMap(section, "users");
    c.groups = readRoleMap(section, "groups");
    c.lockAfterIdleS = section.number("lock_after_idle_s", c.lockAfterIdleS, 0, 86400);
    if (auto a = section.object("authority")) {
        for (OperatorRole role : kAllOperatorRoles) {
            const std::string key(roleName(role));
            auto& slot = c.authority[static_cast<std::size_t>(role)];
            const auto v = a->integer(key, slot, 0, 254);
            // AEP-4818 §4.3.2: 0 (monitor) or an operator band; 1-204 belong to no OCU role.
            if (v > 0 && v < 205)
                a->error(key, "authority " + std::to_string(v) +
                                  " is in no OCU band (0 = monitor, 205-239 primary operator, 240-254 "
                                  "safety critical)");
            else
                slot = static_cast<int>(v);
        }
        a->finish();
    }
    section.finish();
    return c;
}

std::vector<std::string> groupsOfUser(const std::string& user) {
    std::vector<std::string> out;
    const passwd* pw = getpwnam(user.c_str());
    if (!pw)
        return out;
    int n = 64;
    std::vector<gid_t> gids(static_cast<std::size_t>(n));
    if (getgrouplist(user.c_str(), pw->pw_gid, gids.data(), &n) < 0) {
        gids.resize(static_cast<std::size_t>(n));
        if (getgrouplist(user.c_str(), pw->pw_gid, gids.data(), &n) < 0)
            return out;
    }
    gids.resize(static_cast<std::size_t>(n));
    for (gid_t g : gids)
        if (const group* gr = getgrgid(g))
            out.emplace_back(gr->gr_name);
    return out;
}

OsUser currentOsUser() {
    OsUser u;
    if (const passwd* pw = getpwuid(geteuid()))
        u.name = pw->pw_name;
    else
        u.name = "uid" + std::to_string(geteuid());
    u.groups = groupsOfUser(u.name);
    return u;
}

} // namespace ocu
