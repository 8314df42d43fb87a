#include "app/LinkIndicator.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>

namespace ocu {

LinkIndicator::LinkIndicator(const QString& protocolName, QWidget* parent)
    : QWidget(parent), m_protocol(protocolName), m_lamp(new QLabel(this)), m_label(new QLabel(this)),
      m_note(new QLabel(this)) {
    auto* l = new QHBoxLayout(this);
    l->setContentsMargins(4, 0, 4, 0);
    l->setSpacing(4);
    m_lamp->setFixedSize(12, 12);
    l->addWidget(m_lamp);
    l->addWidget(m_label);
    // Amber like a degraded lamp: the stack works, with less than it should have.
    m_note->setStyleSheet(QStringLiteral("color:#b36b00; font-weight:bold;"));
    m_note->setObjectName(QStringLiteral("link-note"));
    m_note->hide();
    l->addWidget(m_note);
    auto* timer = new QTimer(this);
    connect(timer, &QTimer::timeout, this, [this] {
        if (m_bridge)
            m_counters = m_bridge->linkCounters();
        refresh();
    });
    timer->start(1000);
    setObjectName(QStringLiteral("link-") + protocolName.toLower());
    refresh();
}

void LinkIndicator::setState(State state, const QString& detail) {
    m_state = state;
    m_detail = detail;
    refresh();
}

void LinkIndicator::setNote(const QString& note) {
    m_noteText = note;
    m_note->setText(note);
    m_note->setVisible(!note.isEmpty());
    refresh();
}

void LinkIndicator::setLinkCounters(const QVector<LinkCounters>& counters) {
    m_counters = counters;
    refresh();
}

void LinkIndicator::watchBridge(FleetBridge* bridge) {
    m_bridge = bridge;
    if (bridge)
        setLinkCounters(bridge->linkCounters());
}

void LinkIndicator::dataReceived() {
    m_sinceData.restart();
    m_ageOffsetMs = 0;
}

void LinkIndicator::setDataAgeMs(qint64 ageMs) {
    m_sinceData.restart();
    m_ageOffsetMs = ageMs;
    refresh();
}

qint64 LinkIndicator::dataAgeMs() const {
    if (m_ageOffsetMs < 0 || !m_sinceData.isValid())
        return -1;
    return m_ageOffsetMs + m_sinceData.elapsed();
}

QString LinkIndicator::text() const {
    return m_label->text();
}

void LinkIndicator::refresh() {
    QString stateText;
    QColor colour;
    switch (m_state) {
    case State::NotConfigured:
        stateText = tr("off");
        colour = QColor(140, 140, 140);
        break;
    case State::Up:
        stateText = tr("up");
        colour = QColor(40, 170, 60);
        break;
    case State::Degraded:
        stateText = tr("degraded");
        colour = QColor(235, 160, 0);
        break;
    case State::Down:
        stateText = tr("down");
        colour = QColor(210, 40, 40);
        break;
    }
    QString t = m_protocol + QLatin1Char(' ') + stateText;
    const qint64 age = dataAgeMs();
    if (m_state != State::NotConfigured && age >= 0)
        t += QStringLiteral(" · ") +
             (age < 10000 ? tr("%1 s").arg(age / 1000.0, 0, 'f', 1) : tr("%1 s").arg(age / 1000));
    m_label->setText(t);
    m_lamp->setStyleSheet(
        QStringLiteral("background:%1; border-radius:6px; border:1px solid #333;").arg(colour.name()));
    QString tip = m_detail.isEmpty() ? t : t + QLatin1Char('\n') + m_detail;
    if (!m_noteText.isEmpty())
        tip += QLatin1Char('\n') + m_noteText;
    // Rejected input per link and reason: an operator sees a peer misbehave without reading logs.
    for (const LinkCounters& c : std::as_const(m_counters)) {
        if (c.rejected.isEmpty()) {
            tip += QLatin1Char('\n') + tr("%1: no input rejected").arg(c.link);
            continue;
        }
        tip += QLatin1Char('\n') + tr("%1: %2 inputs rejected").arg(c.link).arg(c.rejectedTotal());
        for (auto it = c.rejected.begin(); it != c.rejected.end(); ++it)
            tip += QStringLiteral("\n    %1: %2").arg(it.key()).arg(it.value());
    }
    setToolTip(tip);
}

} // namespace ocu
