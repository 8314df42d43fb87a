#pragma once
// Shows a VideoPlayer's current frame, scaled to fit with its aspect kept, with the stream's
// state and the measured age of the frame, the caller's overlay lines (speed, heading, drive state) and an
// alert banner (the video watchdog). Painting only copies a reference to the newest QImage: decoding stays
// on GStreamer's threads. The overlays keep clear of the frame's top rows (the capture time code, read back
// by bench_video from the rendered widget).
#include "models/video/VideoPlayer.h"

#include <QPointer>
#include <QStringList>
#include <QWidget>

namespace ocu {

class VideoView : public QWidget {
    Q_OBJECT
public:
    explicit VideoView(QWidget* parent = nullptr);

    void setPlayer(VideoPlayer* player); // not owned
    VideoPlayer* player() const { return m_player; }
    // Lines drawn at the bottom left of the picture.
    void setOverlay(const QStringList& lines);
    // A red banner across the middle (empty = none).
    void setAlert(const QString& text);
    QString alert() const { return m_alert; }
    // Shown instead of a picture when there is no player or no frame yet.
    void setPlaceholder(const QString& text);
    // Where the last frame was drawn (widget coordinates); empty before the first.
    QRect frameRect() const { return m_frameRect; }
    // Number (VideoFrame::number) of the frame last painted; 0 before the first.
    quint64 paintedFrame() const { return m_paintedFrame; }
    // The stream line as drawn ("playing · 1280×720 · 30 fps · frame age 85 ms").
    QString streamText() const;

    QSize sizeHint() const override { return {640, 360}; }
    QSize minimumSizeHint() const override { return {160, 90}; }
    // In a panel (the teleop dock, which may be narrow and scrolls), the picture's height follows its width
    // (16:9, up to maxHeight) rather than a fixed 360 px hint: no tall black bars in a narrow column, no
    // postage stamp either. Off by default (a full-screen window takes what it gets).
    void setHeightFollowsWidth(bool on, int maxHeight = 400);
    bool hasHeightForWidth() const override { return m_hfwMax > 0; }
    int heightForWidth(int w) const override;

signals:
    void doubleClicked();
    // Emitted after a frame was painted.
    void framePainted(quint64 number);

protected:
    void paintEvent(QPaintEvent*) override;
    void mouseDoubleClickEvent(QMouseEvent*) override;

private:
    QPointer<VideoPlayer> m_player;
    QStringList m_overlay;
    QString m_alert;
    QString m_placeholder;
    QRect m_frameRect;
    quint64 m_paintedFrame = 0;
    int m_hfwMax = 0;
};

} // namespace ocu
