#pragma once
// The replay timeline: play/pause, reverse, step, speed 0.1x-16x, a slider over the whole
// recording with markers for alarms and commands (click one to jump there; hover for its text), and an exact
// time entry (HH:MM:SS[.mmm] UTC, seconds after the start, or ISO 8601). Keys (also when the window has the
// focus elsewhere, via the replay window's shortcuts): Space play/pause, + / - speed, Left/Right step,
// Home/End.
#include <QString>
#include <QVector>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;
class QSlider;
class QToolButton;

namespace ocu {

struct TimelineMarker {
    qint64 t = 0;
    bool command = false; // else an alarm
    bool bad = false;     // severity alarm+ / a command that did not reach every target
    QString text;
};

class TimelineMarkerStrip;

class ReplayTimeline : public QWidget {
    Q_OBJECT
public:
    explicit ReplayTimeline(QWidget* parent = nullptr);

    void setRange(qint64 startMs, qint64 endMs);
    void setMarkers(const QVector<TimelineMarker>& markers);
    // Parses what the time field accepts (ms since the epoch, or -1); set by the replay runtime.
    void setTimeParser(std::function<qint64(const QString&)> parse) { m_parse = std::move(parse); }

    QSlider* slider() const { return m_slider; }
    QToolButton* playButton() const { return m_play; }
    QToolButton* reverseButton() const { return m_reverse; }
    QToolButton* stepBackButton() const { return m_back; }
    QToolButton* stepForwardButton() const { return m_fwd; }
    QLineEdit* timeEdit() const { return m_time; }
    QComboBox* speedBox() const { return m_speed; }
    TimelineMarkerStrip* markerStrip() const { return m_strip; }
    qint64 position() const { return m_pos; }

public slots:
    void setPosition(qint64 t);
    void setPlaying(bool playing);
    void setSpeed(double speed);
    void setReverse(bool reverse);

signals:
    void seekRequested(qint64 t);
    void playToggled();
    void speedRequested(double speed);
    void reverseRequested(bool reverse);
    void stepRequested(int direction);

private:
    QString label(qint64 t) const;
    qint64 m_start = 0, m_end = 0, m_pos = 0;
    std::function<qint64(const QString&)> m_parse;
    QToolButton* m_play;
    QToolButton* m_reverse;
    QToolButton* m_back;
    QToolButton* m_fwd;
    QComboBox* m_speed;
    QSlider* m_slider;
    TimelineMarkerStrip* m_strip;
    QLineEdit* m_time;
    QLabel* m_elapsed;
    bool m_updating = false;
};

// The strip under the slider: one tick per marker (alarms amber/red above, commands blue/red below).
class TimelineMarkerStrip : public QWidget {
    Q_OBJECT
public:
    explicit TimelineMarkerStrip(QWidget* parent = nullptr);
    void setRange(qint64 startMs, qint64 endMs);
    void setMarkers(const QVector<TimelineMarker>& markers);
    void setPosition(qint64 t);
    const QVector<TimelineMarker>& markers() const { return m_markers; }
    // The marker nearest to x (within a few pixels), or -1.
    int markerAt(int x) const;
    int xOf(qint64 t) const;
    QSize sizeHint() const override { return {400, 22}; }

signals:
    void markerClicked(qint64 t);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;
    bool event(QEvent* e) override; // tooltips

private:
    qint64 m_start = 0, m_end = 1, m_pos = 0;
    QVector<TimelineMarker> m_markers;
};

} // namespace ocu
