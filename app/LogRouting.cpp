#include "app/LogRouting.h"

#include "protocols/common/Log.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>

Q_LOGGING_CATEGORY(lcUi, "ocu.ui")
Q_LOGGING_CATEGORY(lcApp, "ocu.app")

namespace ocu {
namespace {

// Category names used by the protocol libraries, mapped onto the console's documented names.
std::string canonicalCategory(std::string_view c) {
    std::string s(c);
    if (s.rfind("ocu.", 0) == 0)
        s = s.substr(4);
    auto dot = s.find('.');
    std::string head = s.substr(0, dot);
    std::string tail = dot == std::string::npos ? std::string() : s.substr(dot);
    if (head == "iso23725" || head == "iso")
        head = "iso";
    return "ocu." + head + tail;
}

QLoggingCategory& categoryFor(std::string_view name) {
    static std::mutex mutex;
    // QLoggingCategory keeps the name pointer: the strings live as long as the map.
    static std::map<std::string, std::pair<std::unique_ptr<std::string>, std::unique_ptr<QLoggingCategory>>>
        categories;
    std::string key = canonicalCategory(name);
    std::lock_guard lock(mutex);
    auto it = categories.find(key);
    if (it == categories.end()) {
        auto str = std::make_unique<std::string>(key);
        auto cat = std::make_unique<QLoggingCategory>(str->c_str());
        it = categories.emplace(key, std::make_pair(std::move(str), std::move(cat))).first;
    }
    return *it->second.second;
}

} // namespace

void installLogRouting() {
    // Protocol libraries filter below Debug cheaply; Qt's rules then decide per category.
    setLogThreshold(LogLevel::Debug);
    setLogSink([](LogLevel level, std::string_view category, std::string_view message) {
        QLoggingCategory& cat = categoryFor(category);
        const QString text = QString::fromUtf8(message.data(), static_cast<qsizetype>(message.size()));
        switch (level) {
        case LogLevel::Debug:
            if (cat.isDebugEnabled())
                QMessageLogger(nullptr, 0, nullptr, cat.categoryName()).debug().noquote() << text;
            break;
        case LogLevel::Info:
            if (cat.isInfoEnabled())
                QMessageLogger(nullptr, 0, nullptr, cat.categoryName()).info().noquote() << text;
            break;
        case LogLevel::Warning:
            if (cat.isWarningEnabled())
                QMessageLogger(nullptr, 0, nullptr, cat.categoryName()).warning().noquote() << text;
            break;
        case LogLevel::Error:
            if (cat.isCriticalEnabled())
                QMessageLogger(nullptr, 0, nullptr, cat.categoryName()).critical().noquote() << text;
            break;
        }
    });
    // Debug output is opt-in (--log); info and above are shown.
    QLoggingCategory::setFilterRules(QStringLiteral("ocu.*.debug=false"));
}

void enableLogCategories(const QString& categories) {
    QString rules = QStringLiteral("ocu.*.debug=false\n");
    for (const QString& c : categories.split(QLatin1Char(','), Qt::SkipEmptyParts))
        rules += c.trimmed() + QStringLiteral(".debug=true\n");
    QLoggingCategory::setFilterRules(rules);
}

} // namespace ocu
