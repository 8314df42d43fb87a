#include "widgets/ColumnFit.h"

#include <QAbstractItemModel>
#include <QEvent>
#include <QHeaderView>
#include <QMap>
#include <QScrollBar>
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
static const char* const kWithinProperty = "ocuColumnFitWithin";       // stretchPercent; absent: not kept
static const char* const kPreferredProperty = "ocuColumnFitPreferred"; // column -> width before shrinking
static const char* const kTiersProperty = "ocuColumnFitTiers";         // column -> [tier, floor]

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

static bool keptWithinWidth(const QTableView* view) {
    return view->property(kWithinProperty).isValid();
}

static void applyWithinWidth(QTableView* view);

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
        if (keptWithinWidth(view)) { // the width it would like; applyWithinWidth shares the view's out
            QVariantMap preferred = view->property(kPreferredProperty).toMap();
            if (want > preferred.value(QString::number(c), header->sectionSize(c)).toInt()) {
                preferred.insert(QString::number(c), want);
                view->setProperty(kPreferredProperty, preferred);
                ++widened;
            }
        } else if (want > header->sectionSize(c)) {
            header->resizeSection(c, want);
            ++widened;
        }
    }
    if (widened > 0 && keptWithinWidth(view))
        applyWithinWidth(view);
    return widened;
}

namespace {

class ElidingHeader : public QHeaderView {
public:
    using QHeaderView::QHeaderView;

protected:
    void initStyleOptionForIndex(QStyleOptionHeader* option, int logicalIndex) const override {
        QHeaderView::initStyleOptionForIndex(option, logicalIndex);
        // The title's own width less what the section lacks of the width the whole title needs.
        const int missing = headerTextWidth(this, logicalIndex) - sectionSize(logicalIndex);
        if (missing > 0)
            option->text =
                fontMetrics().elidedText(option->text, Qt::ElideRight,
                                         qMax(0, fontMetrics().horizontalAdvance(option->text) - missing));
    }
};

// Shares the view's width out again when it is resized.
class WithinWidth : public QObject {
public:
    // The viewport's resize: the view's own comes before the viewport has its new width.
    explicit WithinWidth(QTableView* view) : QObject(view), m_view(view) {
        view->viewport()->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == m_view->viewport() &&
            (event->type() == QEvent::Resize || event->type() == QEvent::Show))
            applyWithinWidth(m_view);
        return QObject::eventFilter(watched, event);
    }

private:
    QTableView* m_view;
};

} // namespace

namespace {

struct Fitted {
    int column, want, floor;
    int tier; // a higher tier gives up width only once the lower ones are at their floors
};

// The widest columns give up width first: each gets what it wants up to a common ceiling (never below its
// floor), the highest ceiling that keeps their sum within the budget.
void shareOut(QList<Fitted*>& group, int budget, QMap<int, int>& width) {
    const auto sumAt = [&group](int ceiling) {
        int sum = 0;
        for (const Fitted* f : group)
            sum += qMax(f->floor, qMin(f->want, ceiling));
        return sum;
    };
    int lo = 0, hi = 0;
    for (const Fitted* f : group)
        hi = qMax(hi, f->want);
    while (lo < hi) { // the largest ceiling whose sum fits (0 when even the floors do not)
        const int mid = (lo + hi + 1) / 2;
        if (sumAt(mid) <= budget)
            lo = mid;
        else
            hi = mid - 1;
    }
    for (const Fitted* f : group)
        width[f->column] = qMax(f->floor, qMin(f->want, lo));
}

} // namespace

static void applyWithinWidth(QTableView* view) {
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model() ? view->model()->columnCount() : 0;
    // The width the columns have: the viewport's, and that of a vertical scroll bar that is not shown yet
    // (rows arriving would show it and take it from the columns).
    int available = view->viewport()->width();
    if (!view->verticalScrollBar()->isVisible())
        available -= view->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, view);
    if (columns == 0 || available <= 0)
        return;
    const QVariantMap preferred = view->property(kPreferredProperty).toMap();
    const QVariantMap tiers = view->property(kTiersProperty).toMap(); // column -> [tier, floor]
    const int floorPx = qMax(header->minimumSectionSize(),
                             header->fontMetrics().horizontalAdvance(QStringLiteral("Mm…")) + 8);
    QList<Fitted> fitted;
    QMap<int, int> width;
    int stretched = 0; // the width the stretched columns keep at least
    for (int c = 0; c < columns; ++c) {
        if (header->isSectionHidden(c))
            continue;
        if (!isFitted(header, c, columns)) {
            // A stretched last section is never narrower than the default size (QHeaderView keeps it).
            stretched += header->stretchLastSection() && c == columns - 1 ? header->defaultSectionSize()
                                                                          : header->minimumSectionSize();
            continue;
        }
        const int w = preferred.value(QString::number(c), header->sectionSize(c)).toInt();
        const QVariantList t = tiers.value(QString::number(c)).toList();
        const int ownFloor = t.value(1).toInt();
        fitted.push_back({c, w, qMin(w, ownFloor > 0 ? ownFloor : floorPx), t.value(0).toInt()});
        width[c] = w;
    }
    const int stretchPercent = view->property(kWithinProperty).toInt();
    const int budget = available - (stretched > 0 ? qMax(stretched, available * stretchPercent / 100) : 0);
    // What they want when it fits; else tier by tier, the lowest first, each down to its floors.
    int total = 0;
    QMap<int, QList<Fitted*>> byTier;
    for (Fitted& f : fitted) {
        total += f.want;
        byTier[f.tier] << &f;
    }
    for (auto it = byTier.begin(); it != byTier.end() && total > budget; ++it) {
        int want = 0, floors = 0;
        for (const Fitted* f : *it) {
            want += f->want;
            floors += f->floor;
        }
        if (total - want + floors <= budget) {
            shareOut(*it, budget - (total - want), width);
            break;
        }
        for (const Fitted* f : *it)
            width[f->column] = f->floor;
        total += floors - want;
    }
    for (auto it = width.cbegin(); it != width.cend(); ++it)
        if (header->sectionSize(it.key()) != it.value())
            header->resizeSection(it.key(), it.value());
}

void keepColumnsWithinWidth(QTableView* view, int stretchPercent) {
    if (view == nullptr || keptWithinWidth(view))
        return;
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model() ? view->model()->columnCount() : 0;
    QVariantMap preferred = view->property(kPreferredProperty).toMap();
    for (int c = 0; c < columns; ++c)
        if (!preferred.contains(QString::number(c)))
            preferred.insert(QString::number(c), header->sectionSize(c));
    view->setProperty(kPreferredProperty, preferred);
    view->setProperty(kWithinProperty, stretchPercent);
    view->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    new WithinWidth(view);
    applyWithinWidth(view);
}

void useElidingHeader(QTableView* view) {
    auto* header = new ElidingHeader(Qt::Horizontal, view);
    header->setSectionsClickable(view->horizontalHeader()->sectionsClickable());
    header->setHighlightSections(view->horizontalHeader()->highlightSections());
    view->setHorizontalHeader(header);
}

void setColumnShrinkTier(QTableView* view, int column, int tier, int minPx) {
    QVariantMap tiers = view->property(kTiersProperty).toMap();
    tiers.insert(QString::number(column), QVariantList{tier, minPx});
    view->setProperty(kTiersProperty, tiers);
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
