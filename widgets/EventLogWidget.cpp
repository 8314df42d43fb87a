#include "widgets/EventLogWidget.h"

#include "models/AlarmModel.h"
#include "models/DisplayText.h"
#include "widgets/ColumnFit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QResizeEvent>
#include <QScrollBar>
#include <QSplitter>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace ocu {

EventLogWidget::EventLogWidget(AlarmModel* alarms, QWidget* parent)
    : QWidget(parent), m_alarms(alarms), m_proxy(new AlarmFilterProxy(this)), m_view(new QTableView(this)),
      m_search(new QLineEdit(this)), m_severity(new QComboBox(this)),
      m_unackOnly(new QCheckBox(tr("Unacknowledged"), this)), m_ack(new QPushButton(tr("Acknowledge"), this)),
      m_ackAll(new QPushButton(tr("Acknowledge all"), this)),
      m_export(new QPushButton(tr("Export CSV…"), this)), m_unackLabel(new QLabel(this)),
      m_showShelved(new QCheckBox(tr("Shelved"), this)), m_shelveFor(new QComboBox(this)),
      m_shelve(new QPushButton(tr("Shelve"), this)), m_unshelve(new QPushButton(tr("Unshelve"), this)),
      m_rateLabel(new QLabel(this)), m_details(new QPlainTextEdit(this)) {
    m_proxy->setSourceModel(alarms);
    buildLayout();
    setupTable();
    connectSignals(alarms);
}

// Filter bar, alarm management row (shelving, counts, rate), the table over the details pane.
void EventLogWidget::buildLayout() {
    m_search->setPlaceholderText(tr("Search events…"));
    m_search->setClearButtonEnabled(true);
    m_severity->addItem(tr("All severities"), int(EventSeverity::Info));
    m_severity->addItem(tr("Warning and above"), int(EventSeverity::Warning));
    m_severity->addItem(tr("Alarms only"), int(EventSeverity::Alarm));
    auto* bar = new QHBoxLayout;
    bar->addWidget(m_search, 1);
    bar->addWidget(m_severity);
    bar->addWidget(m_unackOnly);
    bar->addWidget(m_ack);
    bar->addWidget(m_ackAll);
    // Alarm management row: shelving (ISA-18.2 §11.4, always with an expiry) and the alarm rate.
    m_shelveFor->addItem(tr("15 min"), 15);
    m_shelveFor->addItem(tr("1 h"), 60);
    m_shelveFor->addItem(tr("8 h (shift)"), 8 * 60);
    m_shelve->setToolTip(
        tr("Shelve the selected alarms: hidden and not annunciated until the time runs out"));
    m_showShelved->setToolTip(tr("Show shelved alarms too"));
    m_rateLabel->setToolTip(tr("New alarms in the last 10 minutes (EEMUA 191: more than 10 is a flood)"));
    auto* shelfRow = new QHBoxLayout;
    shelfRow->addWidget(m_showShelved);
    shelfRow->addWidget(m_shelveFor);
    shelfRow->addWidget(m_shelve);
    shelfRow->addWidget(m_unshelve);
    shelfRow->addWidget(m_export); // on the first row it was cut off in an 800-px dock (1366 x 768)
    shelfRow->addStretch(1);
    // The open-alarm count sits with the rate: on the first row it was cut off at 1366 px.
    auto* countsRow = new QHBoxLayout;
    countsRow->addStretch(1);
    countsRow->addWidget(m_unackLabel);
    countsRow->addSpacing(12);
    countsRow->addWidget(m_rateLabel);
    // Beside the shelving buttons where there is room, on a row of their own in a narrow dock (German texts
    // in the 1366-px laptop's default layout); resizeEvent() switches.
    m_bar2 = new QBoxLayout(QBoxLayout::LeftToRight);
    m_bar2->addLayout(shelfRow, 1);
    m_bar2->addLayout(countsRow);
    m_details->setReadOnly(true);
    m_details->setPlaceholderText(
        tr("Select an alarm to see its details: the grouped machines, who acknowledged "
           "or shelved it, and when."));
    m_details->setMaximumBlockCount(2000);
    auto* split = m_split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_view);
    split->addWidget(m_details);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setCollapsible(0, false);
    // The details pane opens (four lines) when an alarm is selected and folds away when none is, so the table
    // keeps the rows of a short bottom dock (1366 x 768: 3 rows were left); the operator drags it taller for
    // a long list. The hint of what to do is the table's tooltip and the pane's placeholder.
    m_details->setMinimumHeight(m_details->fontMetrics().lineSpacing() * 2);
    split->setCollapsible(1, true);
    split->setSizes({400, 0});
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->addLayout(bar);
    lay->addLayout(m_bar2);
    lay->addWidget(split, 1);
    // The narrow form's width (counts on their own row), so a dock narrower than the one-row form can hold
    // it.
    setMinimumWidth(std::max(
        {bar->minimumSize().width(), shelfRow->minimumSize().width(), countsRow->minimumSize().width()}));
}

namespace {

// A narrowed time column keeps the time of day ("…01:24:42"): elided at the left, the date first.
class TimeOfDayDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override {
        QStyledItemDelegate::initStyleOption(option, index);
        option->textElideMode = Qt::ElideLeft;
        option->features &= ~QStyleOptionViewItem::WrapText; // one line: wrapped, the date would stay
    }
};

} // namespace

void EventLogWidget::setupTable() {
    m_view->setModel(m_proxy);
    useElidingHeader(m_view);
    m_view->setToolTip(m_details->placeholderText());
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setTabKeyNavigation(false); // arrows move in the table, Tab leaves it (docs/keyboard.md)
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setStretchLastSection(false);
    m_view->horizontalHeader()->setSectionResizeMode(AlarmModel::ColText, QHeaderView::Stretch);
    // The message takes the remaining width, at least kMessagePercent of it; the other columns fit their
    // content from their title up, the long ones capped, and give up width (elided: the tooltip shows the
    // full text) where the view is narrower than they want, so a 1366-px laptop keeps the message. The time
    // keeps its time of day.
    startColumnsAtHeaderWidth(m_view);
    setColumnFitCap(m_view, AlarmModel::ColKind, 130);
    setColumnFitCap(m_view, AlarmModel::ColMachine, 120);
    setColumnFitCap(m_view, AlarmModel::ColAck, 130);
    // The long columns (kind, machine, acknowledged by) give up width first, then the time (its time of day
    // stays), the short ones last.
    m_view->setItemDelegateForColumn(AlarmModel::ColTime, new TimeOfDayDelegate(m_view));
    setColumnShrinkTier(m_view, AlarmModel::ColTime, 1,
                        m_view->fontMetrics().horizontalAdvance(QStringLiteral("…00:00:00")) + 12);
    for (int c : {int(AlarmModel::ColSeverity), int(AlarmModel::ColPriority), int(AlarmModel::ColCount)})
        setColumnShrinkTier(m_view, c, 2);
    keepColumnsWithinWidth(m_view, kMessagePercent);
    keepColumnsFitted(m_view);
}

void EventLogWidget::connectSignals(AlarmModel* alarms) {
    connect(m_search, &QLineEdit::textChanged, m_proxy, &AlarmFilterProxy::setText);
    connect(m_severity, &QComboBox::currentIndexChanged, this,
            [this] { m_proxy->setMinimumSeverity(EventSeverity(m_severity->currentData().toInt())); });
    connect(m_unackOnly, &QCheckBox::toggled, m_proxy, &AlarmFilterProxy::setUnacknowledgedOnly);
    connect(m_ack, &QPushButton::clicked, this, &EventLogWidget::acknowledgeSelected);
    connect(m_ackAll, &QPushButton::clicked, alarms, &AlarmModel::acknowledgeAll);
    connect(m_shelve, &QPushButton::clicked, this, &EventLogWidget::shelveSelected);
    connect(m_unshelve, &QPushButton::clicked, this, &EventLogWidget::unshelveSelected);
    connect(m_showShelved, &QCheckBox::toggled, m_proxy, &AlarmFilterProxy::setShowShelved);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &EventLogWidget::showDetails);
    connect(alarms, &QAbstractItemModel::dataChanged, this, &EventLogWidget::showDetails);
    auto updateRate = [this](int n, bool flood) {
        m_rateLabel->setText(flood ? tr("<b style='color:#d01010'>ALARM FLOOD: %1 alarms / 10 min</b>").arg(n)
                                   : tr("%1 alarms / 10 min").arg(n));
    };
    connect(alarms, &AlarmModel::alarmRateChanged, this, updateRate);
    updateRate(alarms->alarmRate(), alarms->isFlood());
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export events"), QStringLiteral("events.csv"), tr("CSV files (*.csv)"));
        if (!path.isEmpty())
            exportShown(path);
    });
    auto updateCount = [this](int n) {
        m_unackLabel->setText(n > 0 ? tr("<b style='color:#d01010'>%1 unacknowledged</b>").arg(n)
                                    : tr("no open alarms"));
    };
    connect(alarms, &AlarmModel::unacknowledgedCountChanged, this, updateCount);
    updateCount(alarms->unacknowledgedCount());
    // Keep the newest entry in view unless the operator scrolled away.
    connect(m_proxy, &QAbstractItemModel::rowsInserted, this, [this] {
        if (m_view->verticalScrollBar()->value() >= m_view->verticalScrollBar()->maximum() - 2)
            m_view->scrollToBottom();
    });
}

void EventLogWidget::acknowledgeSelected() {
    if (!m_alarms)
        return;
    for (const QModelIndex& idx : m_view->selectionModel()->selectedRows(0))
        m_alarms->acknowledge(m_proxy->mapToSource(idx).row());
}

QStringList EventLogWidget::selectedKeys() const {
    QStringList keys;
    if (!m_alarms)
        return keys;
    for (const QModelIndex& idx : m_view->selectionModel()->selectedRows(0)) {
        const int row = m_proxy->mapToSource(idx).row();
        if (m_alarms->eventAt(row).requiresAck && !keys.contains(m_alarms->keyAt(row)))
            keys << m_alarms->keyAt(row);
    }
    return keys;
}

void EventLogWidget::shelveSelected() {
    if (!m_alarms)
        return;
    const qint64 ms = qint64(m_shelveFor->currentData().toInt()) * 60 * 1000;
    for (const QString& k : selectedKeys())
        m_alarms->shelve(k, ms > 0 ? ms : 15 * 60 * 1000);
}

void EventLogWidget::unshelveSelected() {
    if (!m_alarms)
        return;
    for (const QString& k : selectedKeys())
        m_alarms->unshelve(k);
}

bool EventLogWidget::detailsShown() const {
    return m_split->sizes().value(1) > 0;
}

void EventLogWidget::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    int oneRow = 0; // the shelving row beside the counts
    for (QWidget* w : std::initializer_list<QWidget*>{m_showShelved, m_shelveFor, m_shelve, m_unshelve,
                                                      m_export, m_unackLabel, m_rateLabel})
        oneRow += w->sizeHint().width() + 6;
    const auto dir = width() < oneRow + 12 ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight;
    if (m_bar2->direction() != dir)
        m_bar2->setDirection(dir);
}

void EventLogWidget::showDetails() {
    if (!m_alarms)
        return;
    const QModelIndexList rows = m_view->selectionModel()->selectedRows(0);
    const int total = m_split->sizes().value(0) + m_split->sizes().value(1);
    if (rows.isEmpty()) {
        m_details->clear();
        if (detailsShown())
            m_split->setSizes({total, 0});
        return;
    }
    if (!detailsShown()) {
        const int pane = m_details->fontMetrics().lineSpacing() * 4 + 8;
        m_split->setSizes({std::max(0, total - pane), pane});
        m_view->scrollTo(rows.front());
    }
    const int row = m_proxy->mapToSource(rows.front()).row();
    if (row < 0 || row >= m_alarms->rowCount())
        return;
    const FleetEvent& e = m_alarms->eventAt(row);
    auto time = [](qint64 ms) {
        return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC)
            .toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'"));
    };
    QStringList lines;
    lines << e.text;
    if (e.requiresAck) {
        lines << tr("Priority: %1 · raised %2 · %n time(s)", nullptr, m_alarms->occurrencesAt(row))
                     .arg(DisplayText::priority(effectivePriority(e)), time(e.timeMs));
        if (m_alarms->isAcknowledged(row))
            lines << tr("Acknowledged by %1 at %2")
                         .arg(m_alarms->acknowledgedByAt(row), time(m_alarms->acknowledgedAtMs(row)));
        if (m_alarms->isShelved(row)) {
            const auto s = m_alarms->shelf(m_alarms->keyAt(row));
            lines << tr("Shelved by %1 until %2").arg(s.by, time(s.untilMs));
        }
        lines << tr("Key: %1").arg(m_alarms->keyAt(row));
    }
    if (!e.details.isEmpty()) {
        lines << tr("%1 items:").arg(QLocale().toString(e.itemCount));
        lines += e.details;
    }
    m_details->setPlainText(lines.join(QLatin1Char('\n')));
}

bool EventLogWidget::exportShown(const QString& path) const {
    if (!m_alarms)
        return false;
    QVector<int> rows;
    for (int i = 0; i < m_proxy->rowCount(); ++i)
        rows.push_back(m_proxy->mapToSource(m_proxy->index(i, 0)).row());
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    if (rows.isEmpty()) {
        // An empty filter result exports just the header (exportCsv treats an empty list as "all").
        return f.write("time,severity,kind,machine,source,text,acknowledged\r\n") > 0;
    }
    return m_alarms->exportCsv(&f, rows);
}

} // namespace ocu
