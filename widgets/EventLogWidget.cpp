#include "widgets/EventLogWidget.h"

#include "models/AlarmModel.h"
#include "widgets/ColumnFit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QVBoxLayout>

namespace ocu {

EventLogWidget::EventLogWidget(AlarmModel* alarms, QWidget* parent)
    : QWidget(parent), m_alarms(alarms), m_proxy(new AlarmFilterProxy(this)), m_view(new QTableView(this)),
      m_search(new QLineEdit(this)), m_severity(new QComboBox(this)),
      m_unackOnly(new QCheckBox(tr("Unacknowledged"), this)), m_ack(new QPushButton(tr("Acknowledge"), this)),
      m_ackAll(new QPushButton(tr("Acknowledge all"), this)),
      m_export(new QPushButton(tr("Export CSV…"), this)), m_unackLabel(new QLabel(this)) {
    m_proxy->setSourceModel(alarms);
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
    bar->addWidget(m_export);
    bar->addWidget(m_unackLabel);
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->addLayout(bar);
    lay->addWidget(m_view, 1);

    m_view->setModel(m_proxy);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setStretchLastSection(false);
    m_view->horizontalHeader()->setSectionResizeMode(AlarmModel::ColText, QHeaderView::Stretch);
    keepColumnsFitted(m_view); // issue 19 §6: headers and cells in view never elided

    connect(m_search, &QLineEdit::textChanged, m_proxy, &AlarmFilterProxy::setText);
    connect(m_severity, &QComboBox::currentIndexChanged, this,
            [this] { m_proxy->setMinimumSeverity(EventSeverity(m_severity->currentData().toInt())); });
    connect(m_unackOnly, &QCheckBox::toggled, m_proxy, &AlarmFilterProxy::setUnacknowledgedOnly);
    connect(m_ack, &QPushButton::clicked, this, &EventLogWidget::acknowledgeSelected);
    connect(m_ackAll, &QPushButton::clicked, alarms, &AlarmModel::acknowledgeAll);
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
