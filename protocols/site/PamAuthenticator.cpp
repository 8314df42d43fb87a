#include "protocols/site/PamAuthenticator.h"

#include <security/pam_appl.h>

#include <cstdlib>
#include <cstring>

namespace ocu {

namespace {

struct Credentials {
    const std::string* user;
    const std::string* password;
};

// PAM's conversation: the password for a hidden prompt, the user name for a visible one; messages are
// not shown (the dialog says what went wrong from the result).
int converse(int count, const pam_message** messages, pam_response** responses, void* data) {
    if (count <= 0 || count > PAM_MAX_NUM_MSG)
        return PAM_CONV_ERR;
    const auto* c = static_cast<const Credentials*>(data);
    auto* out = static_cast<pam_response*>(std::calloc(std::size_t(count), sizeof(pam_response)));
    if (!out)
        return PAM_BUF_ERR;
    for (int i = 0; i < count; ++i) {
        switch (messages[i]->msg_style) {
        case PAM_PROMPT_ECHO_OFF:
            out[i].resp = strdup(c->password->c_str());
            break;
        case PAM_PROMPT_ECHO_ON:
            out[i].resp = strdup(c->user->c_str());
            break;
        default:
            break; // PAM_ERROR_MSG, PAM_TEXT_INFO: nothing to answer
        }
    }
    *responses = out;
    return PAM_SUCCESS;
}

// No wait after a wrong password: the caller is the console's GUI thread, which must keep STOP ALL at once.
void noFailDelay(int, unsigned, void*) {}

} // namespace

PamAuthenticator::PamAuthenticator(std::string service, std::string confDir)
    : m_service(std::move(service)), m_confDir(std::move(confDir)) {}

std::string PamAuthenticator::authenticate(const std::string& user, const std::string& password) const {
    if (user.empty())
        return "no user name";
    Credentials creds{&user, &password};
    const pam_conv conv{&converse, &creds};
    pam_handle_t* pamh = nullptr;
    int rc = pam_start_confdir(m_service.c_str(), user.c_str(), &conv,
                               m_confDir.empty() ? nullptr : m_confDir.c_str(), &pamh);
    if (rc != PAM_SUCCESS)
        return "PAM service \"" + m_service + "\" cannot start";
    pam_set_item(pamh, PAM_FAIL_DELAY, reinterpret_cast<const void*>(&noFailDelay));
    rc = pam_authenticate(pamh, PAM_SILENT | PAM_DISALLOW_NULL_AUTHTOK);
    if (rc == PAM_SUCCESS)
        rc = pam_acct_mgmt(pamh, PAM_SILENT);
    std::string why;
    if (rc == PAM_AUTH_ERR || rc == PAM_USER_UNKNOWN || rc == PAM_MAXTRIES)
        why = "wrong user name or password";
    else if (rc != PAM_SUCCESS)
        why = pam_strerror(pamh, rc);
    pam_end(pamh, rc);
    return why;
}

} // namespace ocu
