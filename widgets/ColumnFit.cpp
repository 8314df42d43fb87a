#include "widgets/ColumnFit.h"

#include <QAbstractItemModel>
#include <QHeaderView>
#include <QStyle>
#include <QStyleOptionHeader>
#include <QTableView>
#include <QTimer>
#include <QVariantMap>

namespace ocu {

int headerTextWidth(const QHeaderView* header, int section) {
    // What QHeaderView::sectionSizeFromContents (protected) computes: the style's size for the title, the
    // margins and room for the sort indicator.
    QStyleOptionHeader opt;
    opt.initFrom(header);
    opt.section = section;
    opt.text = header->model()->headerData(section, header->orientation(), Qt::DisplayRole).toString();
    opt.fontMetrics = header->fontMetrics();
    if (header->isSortIndicatorShown())
        opt.sortIndicator = QStyleOptionHeader::SortDown;
    QSize size = header->style()->sizeFromContents(QStyle::CT_HeaderSection, &opt, QSize(), header);
    if (header->isSortIndicatorShown())
        size.rwidth() += header->style()->pixelMetric(QStyle::PM_HeaderMarkSize, &opt, header) +
                         header->style()->pixelMetric(QStyle::PM_HeaderMargin, &opt, header);
    return size.width();
}

static const char* const kCapsProperty = "ocuColumnFitCaps";

static bool isFitted(const QHeaderView* header, int c, int columns) {
    return !header->isSectionHidden(c) && header->sectionResizeMode(c) != QHeaderView::Stretch &&
           !(header->stretchLastSection() && c == columns - 1);
}

void setColumnFitCap(QTableView* view, int column, int maxPx) {
    QVariantMap caps = view->property(kCapsProperty).toMap();
    caps.insert(QString::number(column), maxPx);
    view->setProperty(kCapsProperty, caps);
}

void startColumnsAtHeaderWidth(QTableView* view) {
    if (view == nullptr || view->model() == nullptr)
        return;
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model()->columnCount();
    for (int c = 0; c < columns; ++c)
        if (isFitted(header, c, columns))
            header->resizeSection(c, qMax(header->minimumSectionSize(), headerTextWidth(header, c)));
}

int fitColumnsToContent(QTableView* view) {
    if (view == nullptr || view->model() == nullptr)
        return 0;
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model()->columnCount();
    const QVariantMap caps = view->property(kCapsProperty).toMap();
    int widened = 0;
    for (int c = 0; c < columns; ++c) {
        if (!isFitted(header, c, columns))
            continue;
        // sizeHintForColumn measures the rows in view (QTableView) with the delegate; the header's own
        // hint covers the title and the sort indicator.
        const int title = headerTextWidth(header, c);
        int want = qMax(static_cast<const QAbstractItemView*>(view)->sizeHintForColumn(c), title);
        const int cap = caps.value(QString::number(c), -1).toInt();
        if (cap > 0)
            want = qMax(title, qMin(want, cap));
        if (want > header->sectionSize(c)) {
            header->resizeSection(c, want);
            ++widened;
        }
    }
    return widened;
}

void keepColumnsFitted(QTableView* view) {
    auto* timer = new QTimer(view);
    timer->setSingleShot(true);
    timer->setInterval(1000);
    QObject::connect(timer, &QTimer::timeout, view, [view] {
        if (view->isVisible())
            fitColumnsToContent(view);
    });
    auto schedule = [timer] {
        if (!timer->isActive())
            timer->start();
    };
    QAbstractItemModel* model = view->model();
    QObject::connect(model, &QAbstractItemModel::rowsInserted, timer, schedule);
    QObject::connect(model, &QAbstractItemModel::modelReset, timer, schedule);
    QObject::connect(model, &QAbstractItemModel::layoutChanged, timer, schedule);
    fitColumnsToContent(view);
}

} // namespace ocu
