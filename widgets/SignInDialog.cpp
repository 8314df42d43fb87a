#include "widgets/SignInDialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace ocu {

SignInDialog::SignInDialog(const QString& title, const QString& prompt, const QString& fixedUser, Check check,
                           QWidget* parent)
    : QDialog(parent), m_check(std::move(check)) {
    setObjectName(QStringLiteral("sign-in-dialog"));
    setWindowTitle(title);
    setModal(true);
    auto* layout = new QVBoxLayout(this);
    auto* heading = new QLabel(title, this); // also where the window manager shows no title
    heading->setStyleSheet(QStringLiteral("font-size:16px; font-weight:bold;"));
    layout->addWidget(heading);
    auto* text = new QLabel(prompt, this);
    text->setWordWrap(true);
    layout->addWidget(text);
    auto* form = new QFormLayout;
    m_user = new QLineEdit(fixedUser, this);
    m_user->setObjectName(QStringLiteral("sign-in-user"));
    m_user->setReadOnly(!fixedUser.isEmpty());
    m_password = new QLineEdit(this);
    m_password->setObjectName(QStringLiteral("sign-in-password"));
    m_password->setEchoMode(QLineEdit::Password);
    form->addRow(tr("&User:"), m_user);
    form->addRow(tr("&Password:"), m_password);
    layout->addLayout(form);
    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("sign-in-error"));
    m_error->setStyleSheet(QStringLiteral("color:#c81e1e; font-weight:bold;"));
    m_error->setWordWrap(true);
    m_error->hide();
    layout->addWidget(m_error);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_signIn = buttons->addButton(tr("&Sign in"), QDialogButtonBox::AcceptRole);
    m_signIn->setDefault(true);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &SignInDialog::submit);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    (fixedUser.isEmpty() ? m_user : m_password)->setFocus();
    setMinimumWidth(380);
}

QString SignInDialog::user() const {
    return m_user->text().trimmed();
}

void SignInDialog::submit() {
    const QString why = m_check ? m_check(user(), m_password->text()) : tr("no check");
    m_password->clear();
    if (why.isEmpty()) {
        accept();
        return;
    }
    m_error->setText(why);
    m_error->show();
    m_password->setFocus();
}

} // namespace ocu
