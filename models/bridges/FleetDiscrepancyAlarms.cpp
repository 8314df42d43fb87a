#include "models/bridges/FleetDiscrepancyAlarms.h"

#include <QCoreApplication>
#include <QLocale>

#include <map>

namespace ocu {

using iso23725::DiscrepancyCause;

namespace {

// Details are bounded: the alarm names the count exactly, the list keeps the first this many machines.
constexpr int kMaxDetails = 5000;

QString groupText(DiscrepancyCause cause, const QString& count, const QString& link) {
    switch (cause) {
    case DiscrepancyCause::MissingFromAhs:
        return QCoreApplication::translate(
                   "ocu::FleetDiscrepancyAlarms",
                   "%1 autonomous machines of the FMS fleet are missing from the AHS fleet on %2")
            .arg(count, link);
    case DiscrepancyCause::ListedByBoth:
        return QCoreApplication::translate(
                   "ocu::FleetDiscrepancyAlarms",
                   "%1 machines are listed by both the FMS (manned) and the AHS on %2")
            .arg(count, link);
    case DiscrepancyCause::HidDiffers:
        return QCoreApplication::translate("ocu::FleetDiscrepancyAlarms",
                                           "%1 machines have a different HID at the AHS and the FMS on %2")
            .arg(count, link);
    case DiscrepancyCause::TypeDiffers:
        return QCoreApplication::translate("ocu::FleetDiscrepancyAlarms",
                                           "%1 machines have a different type at the AHS and the FMS on %2")
            .arg(count, link);
    case DiscrepancyCause::DimensionsDiffer:
        return QCoreApplication::translate(
                   "ocu::FleetDiscrepancyAlarms",
                   "%1 machines have different dimensions at the AHS and the FMS on %2")
            .arg(count, link);
    case DiscrepancyCause::NotInFms:
        break;
    }
    return QCoreApplication::translate("ocu::FleetDiscrepancyAlarms",
                                       "%1 machines of the AHS are not in the FMS fleet on %2")
        .arg(count, link);
}

} // namespace

QVector<FleetEvent> fleetDiscrepancyAlarms(const std::string& link,
                                           const std::vector<iso23725::FleetDiscrepancy>& items) {
    std::map<DiscrepancyCause, std::vector<const iso23725::FleetDiscrepancy*>> byCause;
    for (const auto& i : items)
        byCause[i.cause].push_back(&i);
    const QString l = QString::fromStdString(link);
    QLocale locale;
    locale.setNumberOptions({}); // "1,000", with the group separator
    QVector<FleetEvent> out;
    for (const auto& [cause, list] : byCause) {
        const int n = int(list.size());
        const QString one = QString::fromStdString(list.front()->text);
        FleetEvent ev =
            makeEvent(EventSeverity::Warning, EventKind::Discrepancy, {},
                      n == 1 ? QCoreApplication::translate("ocu::FleetDiscrepancyAlarms",
                                                           "Fleet definition discrepancy on %1: %2")
                                   .arg(l, one)
                             : groupText(cause, locale.toString(n), l),
                      QStringLiteral("iso23725"));
        // No machine id, even for one: the key (cause, link, source) must not depend on how many machines.
        ev.cause = QString::fromLatin1(iso23725::causeId(cause));
        ev.group = l;
        ev.itemCount = n;
        ev.priority = AlarmPriority::Medium; // the fleet plan is wrong; nothing moves unsafely because of it
        ev.details.reserve(std::min(n, kMaxDetails));
        for (int k = 0; k < n && k < kMaxDetails; ++k)
            ev.details << QString::fromStdString(list[std::size_t(k)]->text);
        if (n > kMaxDetails)
            ev.details << QCoreApplication::translate("ocu::FleetDiscrepancyAlarms", "… and %1 more")
                              .arg(locale.toString(n - kMaxDetails));
        out.push_back(std::move(ev));
    }
    return out;
}

} // namespace ocu
