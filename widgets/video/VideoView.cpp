#include "widgets/video/VideoView.h"

#include "models/video/VideoPlayer.h"

#include <QPainter>
#include <QTimer>

#include <algorithm>

namespace ocu {

VideoView::VideoView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("video-view"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    // The frame's age grows between frames (and when they stop): redraw the text a few times a second.
    auto* t = new QTimer(this);
    connect(t, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    t->start(250);
}

void VideoView::setHeightFollowsWidth(bool on, int maxHeight) {
    m_hfwMax = on ? std::max(90, maxHeight) : 0;
    QSizePolicy p = sizePolicy();
    p.setHeightForWidth(on);
    setSizePolicy(p);
    updateGeometry();
}

int VideoView::heightForWidth(int w) const {
    if (m_hfwMax <= 0)
        return QWidget::heightForWidth(w);
    return std::clamp(w * 9 / 16, 90, m_hfwMax);
}

void VideoView::setPlayer(VideoPlayer* player) {
    setProperty("screenshotPending", false);
    if (m_player)
        disconnect(m_player, nullptr, this, nullptr);
    m_player = player;
    if (player) {
        connect(player, &VideoPlayer::frameReady, this, qOverload<>(&QWidget::update));
        connect(player, &VideoPlayer::stateChanged, this, qOverload<>(&QWidget::update));
    }
    update();
}

void VideoView::setOverlay(const QStringList& lines) {
    if (lines == m_overlay)
        return;
    m_overlay = lines;
    update();
}

void VideoView::setAlert(const QString& text) {
    if (text == m_alert)
        return;
    m_alert = text;
    update();
}

void VideoView::setPlaceholder(const QString& text) {
    m_placeholder = text;
    update();
}

QString VideoView::streamText() const {
    if (!m_player)
        return m_placeholder;
    const VideoStatus s = m_player->status();
    QStringList parts{videoStateText(s.state)};
    if (s.frames) {
        parts << QStringLiteral("%1×%2").arg(s.resolution.width()).arg(s.resolution.height());
        parts << tr("%1 fps").arg(s.fps, 0, 'f', 0);
        if (s.frameAgeMs)
            parts << (s.ageFromTimeCode ? tr("frame age %1 ms") : tr("frame age %1 ms (since arrival)"))
                         .arg(*s.frameAgeMs);
    }
    return parts.join(QStringLiteral(" · "));
}

void VideoView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(16, 16, 16));
    VideoFrame f;
    VideoStatus st;
    if (m_player) {
        f = m_player->currentFrame();
        st = m_player->status();
    }
    QFont small = font();
    small.setPointSizeF(std::max(8.0, small.pointSizeF()));
    p.setFont(small);
    const QFontMetrics fm(small);
    if (!f.image.isNull()) {
        const QSize s = f.image.size().scaled(size(), Qt::KeepAspectRatio);
        m_frameRect = QRect(QPoint((width() - s.width()) / 2, (height() - s.height()) / 2), s);
        p.drawImage(m_frameRect, f.image);
        m_paintedFrame = f.number;
    } else {
        m_frameRect = {};
        p.setPen(QColor(200, 200, 200));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                   m_player && st.state != VideoState::Idle ? streamText() : m_placeholder);
    }
    const QRect area = m_frameRect.isEmpty() ? rect() : m_frameRect;
    auto box = [&](const QStringList& lines, bool right, const QColor& colour) {
        if (lines.isEmpty())
            return;
        int w = 0;
        for (const QString& l : lines)
            w = std::max(w, fm.horizontalAdvance(l));
        const int h = fm.height() * int(lines.size()) + 8;
        QRect r(right ? area.right() - w - 16 : area.left() + 6, area.bottom() - h - 6, w + 10, h);
        p.fillRect(r, QColor(0, 0, 0, 160));
        p.setPen(colour);
        int y = r.top() + 4 + fm.ascent();
        for (const QString& l : lines) {
            p.drawText(r.left() + 5, y, l);
            y += fm.height();
        }
    };
    // Bottom left: the caller's lines (speed, heading, drive state); bottom right: the stream.
    box(m_overlay, false, Qt::white);
    // The stream box only where it does not run into the caller's lines (a narrow dock: the pane shows the
    // same line under the picture).
    int overlayWidth = 0;
    for (const QString& l : m_overlay)
        overlayWidth = std::max(overlayWidth, fm.horizontalAdvance(l));
    const bool roomForStream =
        m_overlay.isEmpty() || overlayWidth + fm.horizontalAdvance(streamText()) + 40 <= area.width();
    if (m_player && !f.image.isNull() && roomForStream) {
        const bool good = st.state == VideoState::Playing;
        box({streamText()}, true, good ? QColor(140, 255, 140) : QColor(255, 120, 120));
    }
    if (!m_alert.isEmpty()) {
        QFont big = font();
        big.setBold(true);
        big.setPointSizeF(big.pointSizeF() * 1.4);
        p.setFont(big);
        const QRect band(area.left(), area.center().y() - QFontMetrics(big).height(), area.width(),
                         QFontMetrics(big).height() * 2 + 8);
        p.fillRect(band, QColor(200, 30, 30, 210));
        p.setPen(Qt::white);
        p.drawText(band.adjusted(8, 0, -8, 0), Qt::AlignCenter | Qt::TextWordWrap, m_alert);
    }
    // Screenshots (app/Screenshot.cpp) wait while a view that is connecting has painted no frame yet.
    setProperty("screenshotPending",
                m_player && (st.state == VideoState::Connecting || st.state == VideoState::Reconnecting) &&
                    !f.number);
    if (f.number)
        emit framePainted(f.number);
}

void VideoView::mouseDoubleClickEvent(QMouseEvent*) {
    emit doubleClicked();
}

} // namespace ocu
