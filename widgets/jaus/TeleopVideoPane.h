#pragma once
// The teleop panel's video: the selected vehicle's cameras (announced through its IOP
// services or configured) with a switcher, the picture with its overlays, a detachable full-screen window
// (Esc returns), and the video watchdog that holds driving while the video is lost or too old, until the
// operator deliberately resumes.
#include "models/jaus/JausVehicle.h"
#include "models/video/VideoWatchdog.h"

#include <QPointer>
#include <QVector>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTimer;

namespace ocu {

class VideoPlayer;
class VideoView;

class TeleopVideoPane : public QWidget {
    Q_OBJECT
public:
    explicit TeleopVideoPane(QWidget* parent = nullptr);
    ~TeleopVideoPane() override;

    // The vehicle's cameras; the current one keeps playing when it is still among them. Empty = no video.
    // The stream is played (received and decoded) only while the pane is shown or its full-screen window is
    // open: a teleop panel in a hidden tab, a closed dock or a minimised window costs nothing.
    void setCameras(const QVector<JausVideoEndpoint>& cameras);
    QVector<JausVideoEndpoint> cameras() const { return m_cameras; }
    // The camera shown (nullopt without cameras); selectCamera switches by index.
    std::optional<JausVideoEndpoint> currentCamera() const;
    void selectCamera(int index);
    void setOverlay(const QStringList& lines);

    VideoPlayer* player() const { return m_player; }
    VideoView* view() const { return m_view; }
    VideoWatchdog& watchdog() { return m_watchdog; }
    const VideoWatchdog& watchdog() const { return m_watchdog; }
    // Evaluates the watchdog now (also done 10 times a second); emits watchdogChanged on a change.
    void checkWatchdog();
    QComboBox* cameraBox() const { return m_cameraBox; }
    QPushButton* resumeButton() const { return m_resume; }
    QPushButton* fullScreenButton() const { return m_fullButton; }

    // The full-screen window (created on demand; Esc closes it). Keys typed there go through `keyFilter`.
    void openFullScreen();
    void closeFullScreen();
    QWidget* fullScreenWindow() const { return m_window; }
    void setKeyFilter(QObject* filter) { m_keyFilter = filter; }
    // Whether the stream is wanted now: the pane is in front of the operator (shown, and not in a dock tab
    // behind another: OnScreenWatcher), or its full-screen window is open.
    bool wantsVideo() const { return m_shown || m_window; }

signals:
    // The watchdog's verdict (allowsDriving, tripped or videoGood) changed.
    void watchdogChanged();
    // The operator pressed Resume driving and the watchdog let go.
    void resumed();
    // The operator picked another camera.
    void cameraChanged();

private:
    void play();
    // Starts or stops the player as the pane's visibility (or the full-screen window) asks.
    void updatePlayback();
    void updateStatus();

    VideoPlayer* m_player;
    VideoView* m_view;
    VideoWatchdog m_watchdog;
    QComboBox* m_cameraBox;
    QLabel* m_stream;
    QPushButton* m_fullButton;
    QPushButton* m_resume;
    QTimer* m_timer;
    QVector<JausVideoEndpoint> m_cameras;
    QPointer<QWidget> m_window;
    VideoView* m_windowView = nullptr;
    QPointer<QObject> m_keyFilter;
    QStringList m_overlay;
    bool m_lastAllows = true, m_lastTripped = false, m_lastGood = false;
    bool m_shown = false;
};

} // namespace ocu
