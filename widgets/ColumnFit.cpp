#include "widgets/ColumnFit.h"

#include <QAbstractItemModel>
#include <QAction>
#include <QEvent>
#include <QHeaderView>
#include <QHelpEvent>
#include <QMap>
#include <QMenu>
#include <QScrollBar>
#include <QStyle>
#include <QStyleOptionHeader>
#include <QTableView>
#include <QTimer>
#include <QToolTip>
#include <QVariantMap>

#include <algorithm>

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
static const char* const kDroppableProperty = "ocuColumnFitDroppable"; // column -> priority
static const char* const kChosenProperty = "ocuColumnFitChosen";       // column -> shown (the header menu)
static const char* const kApplyingProperty = "ocuColumnFitApplying";   // hiding a column resizes the view

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
    const QVariantMap tiers = view->property(kTiersProperty).toMap();
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
        want = qMax(want, tiers.value(QString::number(c)).toList().value(1).toInt()); // never below its floor
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

// Hides the droppable columns the width has no room for (the lowest priority first) and shows again those it
// has room for: room is every column at its wanted width and the stretched column at its share.
static void dropForWidth(QTableView* view, int available) {
    const QVariantMap droppable = view->property(kDroppableProperty).toMap();
    if (droppable.isEmpty())
        return;
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model()->columnCount();
    const QVariantMap chosen = view->property(kChosenProperty).toMap();
    const QVariantMap preferred = view->property(kPreferredProperty).toMap();
    QList<int> candidates; // droppable and not chosen in the menu, the first to go first
    int want = 0, stretched = 0;
    for (int c = 0; c < columns; ++c) {
        const QString key = QString::number(c);
        const bool isDroppable = droppable.contains(key) && !chosen.contains(key);
        if (!isDroppable && header->isSectionHidden(c))
            continue;
        if (isDroppable)
            candidates << c;
        if (header->sectionResizeMode(c) == QHeaderView::Stretch ||
            (header->stretchLastSection() && c == columns - 1))
            stretched += header->stretchLastSection() && c == columns - 1 ? header->defaultSectionSize()
                                                                          : header->minimumSectionSize();
        else
            want += preferred.value(key, header->sectionSize(c)).toInt();
    }
    std::stable_sort(candidates.begin(), candidates.end(), [&droppable](int a, int b) {
        return droppable.value(QString::number(a)).toInt() < droppable.value(QString::number(b)).toInt();
    });
    const int stretchPercent = view->property(kWithinProperty).toInt();
    const int budget = available - (stretched > 0 ? qMax(stretched, available * stretchPercent / 100) : 0);
    QList<int> dropped;
    for (int c : std::as_const(candidates)) {
        if (want <= budget)
            break;
        want -= preferred.value(QString::number(c), header->sectionSize(c)).toInt();
        dropped << c;
    }
    for (int c : std::as_const(candidates))
        if (header->isSectionHidden(c) != dropped.contains(c))
            header->setSectionHidden(c, dropped.contains(c));
}

static void applyWithinWidth(QTableView* view) {
    QHeaderView* header = view->horizontalHeader();
    const int columns = view->model() ? view->model()->columnCount() : 0;
    // The width the columns have: the viewport's, and that of a vertical scroll bar that is not shown yet
    // (rows arriving would show it and take it from the columns).
    int available = view->viewport()->width();
    if (!view->verticalScrollBar()->isVisible())
        available -= view->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, view);
    if (columns == 0 || available <= 0 || view->property(kApplyingProperty).toBool())
        return;
    view->setProperty(kApplyingProperty, true);
    dropForWidth(view, available);
    view->setProperty(kApplyingProperty, false);
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

void setColumnDroppable(QTableView* view, int column, int priority) {
    QVariantMap droppable = view->property(kDroppableProperty).toMap();
    droppable.insert(QString::number(column), priority);
    view->setProperty(kDroppableProperty, droppable);
}

void addColumnMenu(QTableView* view) {
    QHeaderView* header = view->horizontalHeader();
    header->setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(header, &QHeaderView::customContextMenuRequested, view, [view](const QPoint& pos) {
        QHeaderView* h = view->horizontalHeader();
        QAbstractItemModel* model = view->model();
        if (model == nullptr)
            return;
        QMenu menu(view);
        int shown = 0;
        for (int c = 0; c < model->columnCount(); ++c)
            shown += h->isSectionHidden(c) ? 0 : 1;
        for (int c = 0; c < model->columnCount(); ++c) {
            const QString title = model->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
            QAction* a = menu.addAction(title.isEmpty() ? QString::number(c + 1) : title);
            a->setCheckable(true);
            a->setChecked(!h->isSectionHidden(c));
            a->setEnabled(h->isSectionHidden(c) || shown > 1); // the last column shown stays
            QObject::connect(a, &QAction::toggled, view, [view, c](bool on) {
                QVariantMap chosen = view->property(kChosenProperty).toMap();
                chosen.insert(QString::number(c), on);
                view->setProperty(kChosenProperty, chosen);
                view->horizontalHeader()->setSectionHidden(c, !on);
                if (on)
                    fitColumnsToContent(view);
                if (keptWithinWidth(view))
                    applyWithinWidth(view);
            });
        }
        menu.exec(h->viewport()->mapToGlobal(pos));
    });
}

namespace {

// Shows the whole text of an elided cell as its tooltip, the model's own tooltip below it.
class ElidedTooltips : public QObject {
public:
    explicit ElidedTooltips(QTableView* view) : QObject(view), m_view(view) {
        view->viewport()->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched != m_view->viewport() || event->type() != QEvent::ToolTip)
            return QObject::eventFilter(watched, event);
        auto* help = static_cast<QHelpEvent*>(event);
        const QModelIndex index = m_view->indexAt(help->pos());
        const QString text = index.data(Qt::DisplayRole).toString();
        const QRect rect = m_view->visualRect(index);
        if (!index.isValid() || text.isEmpty() || m_view->indexWidget(index) != nullptr)
            return QObject::eventFilter(watched, event);
        // The room the delegate gives the text: the cell less its margins and a decoration.
        const int margin = m_view->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, m_view) + 1;
        int room = rect.width() - 2 * margin;
        if (index.data(Qt::DecorationRole).isValid())
            room -= m_view->iconSize().isValid()
                        ? m_view->iconSize().width() + margin
                        : m_view->style()->pixelMetric(QStyle::PM_SmallIconSize) + margin;
        if (m_view->fontMetrics().horizontalAdvance(text) <= room)
            return QObject::eventFilter(watched, event);
        QString tip = text;
        const QString own = index.data(Qt::ToolTipRole).toString();
        if (!own.isEmpty() && own != text)
            tip += QLatin1Char('\n') + own;
        QToolTip::showText(help->globalPos(), tip, m_view->viewport(), rect);
        return true;
    }

private:
    QTableView* m_view;
};

} // namespace

void showElidedTextInTooltips(QTableView* view) {
    new ElidedTooltips(view);
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
