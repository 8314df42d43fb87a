#pragma once
// Checks a person's password through PAM (service "ocu", /etc/pam.d/ocu; docs/roles.md): signing in at a
// shared console, switching operator and unlocking. pam_start_confdir lets tests use a throwaway service
// folder instead of the machine's /etc/pam.d. Plain C++, no Qt; blocking (PAM modules may wait a moment
// after a wrong password), so callers keep it off time-critical threads.
#include <string>

namespace ocu {

class PamAuthenticator {
public:
    // `confDir` empty: the system's PAM configuration.
    explicit PamAuthenticator(std::string service = "ocu", std::string confDir = {});

    // Empty when `user` proved `password` and the account may be used now (pam_authenticate then
    // pam_acct_mgmt), else why not, for people.
    std::string authenticate(const std::string& user, const std::string& password) const;

private:
    std::string m_service;
    std::string m_confDir;
};

} // namespace ocu
