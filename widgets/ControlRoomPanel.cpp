#include "widgets/ControlRoomPanel.h"

#include "models/ControlRoomModel.h"
#include "widgets/ColumnFit.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QTime>
#include <QVBoxLayout>

namespace ocu {

ControlRoomPanel::ControlRoomPanel(ControlRoomModel* room, QWidget* parent)
    : QWidget(parent), m_table(new QTableView(this)), m_notice(new QLabel(this)) {
    setObjectName(QStringLiteral("control-room-panel"));
    m_notice->setObjectName(QStringLiteral("control-room-notice"));
    m_notice->setWordWrap(true);
    m_notice->setText(tr("Waiting for the control-room history…"));
    m_table->setObjectName(QStringLiteral("control-room"));
    m_table->setModel(room);
    useElidingHeader(m_table);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setTabKeyNavigation(false); // arrows move in the table, Tab leaves it (docs/keyboard.md)
    m_table->setTextElideMode(Qt::ElideRight);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(20);
    // The state ("not seen since 14:02") takes the remaining width; the names fit their content, capped, and
    // give up width (elided) first where the dock is narrow; the time of sign-in keeps its time of day.
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(ControlRoomModel::State, QHeaderView::Stretch);
    startColumnsAtHeaderWidth(m_table);
    setColumnFitCap(m_table, ControlRoomModel::Console, 160);
    setColumnFitCap(m_table, ControlRoomModel::Operator, 120);
    setColumnFitCap(m_table, ControlRoomModel::Role, 110);
    setColumnShrinkTier(m_table, ControlRoomModel::Since, 1,
                        m_table->fontMetrics().horizontalAdvance(QStringLiteral("00:00")) + 12);
    keepColumnsWithinWidth(m_table, 25);
    keepColumnsFitted(m_table);
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(2, 2, 2, 2);
    l->addWidget(m_notice);
    l->addWidget(m_table, 1);
}

void ControlRoomPanel::setConnected(bool connected, const QString& detail) {
    m_notice->setVisible(!connected);
    if (!connected)
        m_notice->setText(tr("Control-room history unavailable since %1: the room as last seen. %2")
                              .arg(QTime::currentTime().toString(QStringLiteral("HH:mm")), detail)
                              .trimmed());
}

} // namespace ocu
