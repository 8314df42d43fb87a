#include "app/SiteLoader.h"

#include <QCoreApplication>
#include <QFile>

namespace ocu {

QString builtInSitePath() {
    return QStringLiteral(":/sites/simulated-site.json");
}

Result<SiteConfig> loadSite(const QString& configFile) {
    const QString path = configFile.isEmpty() ? builtInSitePath() : configFile;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return Error{QCoreApplication::translate("SiteLoader", "%1: cannot open the site configuration: %2")
                         .arg(path, f.errorString())
                         .toStdString()};
    if (f.size() > 64 * 1024 * 1024)
        return Error{
            QCoreApplication::translate("SiteLoader", "%1: larger than 64 MiB").arg(path).toStdString()};
    const QByteArray text = f.readAll();
    return parseSiteConfig(std::string_view(text.constData(), static_cast<std::size_t>(text.size())),
                           path.toStdString());
}

} // namespace ocu
