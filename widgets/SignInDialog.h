#pragma once
// A person signs in with user name and password: "Switch operator…" (any user) and unlocking a locked
// console (the user given, fixed). The check runs when the person presses Sign in; its refusal is shown in
// the dialog, which stays open (and clears the password) until a check passes or the person cancels.
#include <QDialog>

#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace ocu {

class SignInDialog : public QDialog {
    Q_OBJECT
public:
    // Empty when the person is in, else what to show.
    using Check = std::function<QString(const QString& user, const QString& password)>;
    // `fixedUser` non-empty: that user only (unlock).
    SignInDialog(const QString& title, const QString& prompt, const QString& fixedUser, Check check,
                 QWidget* parent = nullptr);

    QString user() const;
    QLineEdit* userField() const { return m_user; }
    QLineEdit* passwordField() const { return m_password; }
    QLabel* errorLabel() const { return m_error; }
    // Runs the check as the Sign in button does (tests, keyboard).
    void submit();

private:
    Check m_check;
    QLineEdit* m_user = nullptr;
    QLineEdit* m_password = nullptr;
    QLabel* m_error = nullptr;
    QPushButton* m_signIn = nullptr;
};

} // namespace ocu
