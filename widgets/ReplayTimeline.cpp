#include "widgets/ReplayTimeline.h"

#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QHelpEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QToolTip>
#include <QVBoxLayout>

namespace ocu {

namespace {
constexpr int kSliderStepMs = 100; // the slider's resolution
const double kSpeeds[] = {0.1, 0.25, 0.5, 1, 2, 4, 8, 16};
} // namespace

ReplayTimeline::ReplayTimeline(QWidget* parent) : QWidget(parent) {
    auto* top = new QHBoxLayout;
    top->setContentsMargins(0, 0, 0, 0);
    auto button = [this, top](QStyle::StandardPixmap icon, const QString& tip) {
        auto* b = new QToolButton(this);
        b->setIcon(style()->standardIcon(icon));
        b->setToolTip(tip);
        b->setMinimumWidth(34);
        b->setFocusPolicy(Qt::NoFocus); // the keys belong to the window's shortcuts
        top->addWidget(b);
        return b;
    };
    m_back = button(QStyle::SP_MediaSkipBackward, tr("Step back (Left)"));
    m_reverse = button(QStyle::SP_MediaSeekBackward, tr("Play backwards"));
    m_reverse->setCheckable(true);
    m_play = button(QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
    m_fwd = button(QStyle::SP_MediaSkipForward, tr("Step forward (Right)"));
    m_speed = new QComboBox(this);
    m_speed->setFocusPolicy(Qt::NoFocus);
    for (double s : kSpeeds)
        m_speed->addItem(QStringLiteral("%1×").arg(s), s);
    m_speed->setCurrentIndex(3);
    m_speed->setToolTip(tr("Speed (+ / -)"));
    top->addWidget(m_speed);
    m_time = new QLineEdit(this);
    m_time->setPlaceholderText(tr("HH:MM:SS or seconds"));
    m_time->setToolTip(tr("Go to an exact time: HH:MM:SS[.mmm] (UTC), seconds after the start, or ISO 8601; "
                          "Enter"));
    m_time->setMaximumWidth(190);
    top->addWidget(m_time);
    m_elapsed = new QLabel(this);
    m_elapsed->setMinimumWidth(150);
    top->addWidget(m_elapsed);
    top->addStretch(0);

    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setFocusPolicy(Qt::NoFocus);
    m_strip = new TimelineMarkerStrip(this);
    auto* col = new QVBoxLayout;
    col->setSpacing(0);
    col->setContentsMargins(0, 0, 0, 0);
    col->addWidget(m_slider);
    col->addWidget(m_strip);
    auto* lay = new QHBoxLayout(this);
    lay->setContentsMargins(4, 2, 4, 2);
    lay->addLayout(top, 0);
    lay->addLayout(col, 1);

    connect(m_play, &QToolButton::clicked, this, &ReplayTimeline::playToggled);
    connect(m_reverse, &QToolButton::toggled, this, &ReplayTimeline::reverseRequested);
    connect(m_back, &QToolButton::clicked, this, [this] { emit stepRequested(-1); });
    connect(m_fwd, &QToolButton::clicked, this, [this] { emit stepRequested(+1); });
    connect(m_speed, &QComboBox::activated, this,
            [this](int i) { emit speedRequested(m_speed->itemData(i).toDouble()); });
    connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
        if (!m_updating)
            emit seekRequested(m_start + qint64(v) * kSliderStepMs);
    });
    connect(m_strip, &TimelineMarkerStrip::markerClicked, this, &ReplayTimeline::seekRequested);
    connect(m_time, &QLineEdit::returnPressed, this, [this] {
        const qint64 t = m_parse ? m_parse(m_time->text()) : -1;
        if (t < 0) {
            m_time->setStyleSheet(QStringLiteral("background: #f4b6b6;"));
            m_time->setToolTip(tr("Not a time: %1").arg(m_time->text()));
            return;
        }
        m_time->setStyleSheet({});
        m_time->clearFocus();
        emit seekRequested(t);
    });
}

void ReplayTimeline::setRange(qint64 startMs, qint64 endMs) {
    m_start = startMs;
    m_end = std::max(endMs, startMs);
    m_updating = true;
    m_slider->setRange(0, int((m_end - m_start) / kSliderStepMs));
    m_slider->setPageStep(std::max(1, int(10000 / kSliderStepMs)));
    m_updating = false;
    m_strip->setRange(m_start, m_end);
}

void ReplayTimeline::setMarkers(const QVector<TimelineMarker>& markers) {
    m_strip->setMarkers(markers);
}

QString ReplayTimeline::label(qint64 t) const {
    const qint64 rel = t - m_start, total = m_end - m_start;
    auto hms = [](qint64 ms) {
        ms = std::max<qint64>(0, ms);
        return QStringLiteral("%1:%2:%3")
            .arg(ms / 3600000)
            .arg((ms / 60000) % 60, 2, 10, QLatin1Char('0'))
            .arg((ms / 1000) % 60, 2, 10, QLatin1Char('0'));
    };
    return QStringLiteral("+%1 / %2").arg(hms(rel), hms(total));
}

void ReplayTimeline::setPosition(qint64 t) {
    m_pos = t;
    m_updating = true;
    m_slider->setValue(int((t - m_start) / kSliderStepMs));
    m_updating = false;
    m_strip->setPosition(t);
    if (!m_time->hasFocus())
        m_time->setText(QDateTime::fromMSecsSinceEpoch(t, Qt::UTC).toString(QStringLiteral("HH:mm:ss.zzz")));
    m_elapsed->setText(label(t));
}

void ReplayTimeline::setPlaying(bool playing) {
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void ReplayTimeline::setSpeed(double speed) {
    int best = 0;
    for (int i = 0; i < m_speed->count(); ++i)
        if (std::abs(m_speed->itemData(i).toDouble() - speed) <
            std::abs(m_speed->itemData(best).toDouble() - speed))
            best = i;
    m_speed->setCurrentIndex(best);
}

void ReplayTimeline::setReverse(bool reverse) {
    m_reverse->setChecked(reverse);
}

TimelineMarkerStrip::TimelineMarkerStrip(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(22);
    setMouseTracking(true);
    setCursor(Qt::PointingHandCursor);
}

void TimelineMarkerStrip::setRange(qint64 startMs, qint64 endMs) {
    m_start = startMs;
    m_end = std::max(endMs, startMs + 1);
    update();
}

void TimelineMarkerStrip::setMarkers(const QVector<TimelineMarker>& markers) {
    m_markers = markers;
    update();
}

void TimelineMarkerStrip::setPosition(qint64 t) {
    m_pos = t;
    update();
}

int TimelineMarkerStrip::xOf(qint64 t) const {
    // The slider's groove is inset by about half a handle on each side.
    const int inset = 8;
    const double f = double(t - m_start) / double(m_end - m_start);
    return inset + int(f * (width() - 2 * inset));
}

int TimelineMarkerStrip::markerAt(int x) const {
    int best = -1, bestD = 5;
    for (int i = 0; i < m_markers.size(); ++i) {
        const int d = std::abs(xOf(m_markers[i].t) - x);
        if (d <= bestD) {
            best = i;
            bestD = d;
        }
    }
    return best;
}

void TimelineMarkerStrip::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    const int h = height();
    p.setPen(palette().mid().color());
    p.drawLine(xOf(m_start), h / 2, xOf(m_end), h / 2);
    for (const TimelineMarker& m : m_markers) {
        const int x = xOf(m.t);
        QColor c = m.command ? (m.bad ? QColor(0xd3, 0x2f, 0x2f) : QColor(0x1e, 0x6f, 0xd9))
                             : (m.bad ? QColor(0xd3, 0x2f, 0x2f) : QColor(0xf0, 0xa0, 0x00));
        p.setPen(QPen(c, 2));
        if (m.command)
            p.drawLine(x, h / 2, x, h - 2);
        else
            p.drawLine(x, 2, x, h / 2);
    }
    p.setPen(QPen(palette().text().color(), 1));
    const int x = xOf(m_pos);
    p.drawLine(x, 0, x, h);
}

void TimelineMarkerStrip::mousePressEvent(QMouseEvent* e) {
    const int i = markerAt(int(e->position().x()));
    if (i >= 0)
        emit markerClicked(m_markers[i].t);
}

bool TimelineMarkerStrip::event(QEvent* e) {
    if (e->type() == QEvent::ToolTip) {
        auto* he = static_cast<QHelpEvent*>(e);
        const int i = markerAt(he->pos().x());
        if (i >= 0)
            QToolTip::showText(he->globalPos(),
                               QDateTime::fromMSecsSinceEpoch(m_markers[i].t, Qt::UTC)
                                       .toString(QStringLiteral("HH:mm:ss ")) +
                                   (m_markers[i].command ? tr("command: ") : tr("alarm: ")) +
                                   m_markers[i].text,
                               this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(e);
}

} // namespace ocu
