#include "widgets/jaus/TeleopVideoPane.h"

#include "models/video/VideoPlayer.h"
#include "widgets/OnScreenWatcher.h"
#include "widgets/video/VideoView.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace ocu {

namespace {

// The detached video: full screen, Esc returns to the panel; other keys go to the panel's filter (driving,
// pan-tilt, Space = emergency stop).
class FullScreenVideo : public QWidget {
public:
    FullScreenVideo(VideoView* view, QWidget* parent) : QWidget(parent, Qt::Window) {
        setObjectName(QStringLiteral("video-fullscreen"));
        setWindowTitle(TeleopVideoPane::tr("Teleoperation video"));
        setAttribute(Qt::WA_DeleteOnClose);
        setFocusPolicy(Qt::StrongFocus);
        auto* l = new QVBoxLayout(this);
        l->setContentsMargins(0, 0, 0, 0);
        l->addWidget(view);
        view->setFocusProxy(this);
    }

protected:
    void keyPressEvent(QKeyEvent* e) override {
        if (e->key() == Qt::Key_Escape) {
            close();
            return;
        }
        QWidget::keyPressEvent(e);
    }
};

} // namespace

TeleopVideoPane::TeleopVideoPane(QWidget* parent)
    : QWidget(parent), m_player(new VideoPlayer(this)), m_view(new VideoView(this)),
      m_cameraBox(new QComboBox(this)), m_stream(new QLabel(this)),
      m_fullButton(new QPushButton(tr("Full screen"), this)),
      m_resume(new QPushButton(tr("Resume driving"), this)), m_timer(new QTimer(this)) {
    setObjectName(QStringLiteral("teleop-video"));
    m_view->setPlayer(m_player);
    // Played only while in front of the operator: a hidden tab, a closed dock or a minimised window costs
    // nothing (a dock tab behind another gets no hide event, hence the watcher).
    auto* onScreen = new OnScreenWatcher(this);
    connect(onScreen, &OnScreenWatcher::changed, this, [this](bool on) {
        m_shown = on;
        updatePlayback();
    });
    // In a narrow or short dock the picture keeps 16:9 of the width; the controls below scroll.
    m_view->setHeightFollowsWidth(true, 480);
    m_view->setPlaceholder(tr("No camera on this vehicle"));
    m_cameraBox->setObjectName(QStringLiteral("combo-camera"));
    m_cameraBox->setToolTip(tr("Camera shown (announced by the vehicle or configured for it)"));
    m_fullButton->setObjectName(QStringLiteral("button-video-fullscreen"));
    m_fullButton->setToolTip(tr("Show the video full screen (Esc returns); driving keys keep working there"));
    m_resume->setObjectName(QStringLiteral("button-resume-driving"));
    m_resume->setToolTip(tr("The video watchdog stopped driving: resume once the video is back"));
    m_resume->setEnabled(false);
    m_stream->setObjectName(QStringLiteral("label-video-stream"));

    // Narrow docks: the camera names may be cut rather than widen the panel; Resume gets a row of its own
    // (only while the watchdog holds driving).
    m_cameraBox->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_cameraBox->setMinimumContentsLength(8);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Camera"), this));
    bar->addWidget(m_cameraBox, 1);
    bar->addWidget(m_fullButton);
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(0, 0, 0, 0);
    l->addLayout(bar);
    l->addWidget(m_resume);
    l->addWidget(m_view, 1);
    // The stream line (state, resolution, rate, frame age) under the picture, for narrow docks too.
    m_stream->setWordWrap(true);
    l->addWidget(m_stream);

    connect(m_cameraBox, &QComboBox::activated, this, [this](int) {
        play();
        emit cameraChanged();
    });
    connect(m_fullButton, &QPushButton::clicked, this, &TeleopVideoPane::openFullScreen);
    connect(m_view, &VideoView::doubleClicked, this, &TeleopVideoPane::openFullScreen);
    connect(m_resume, &QPushButton::clicked, this, [this] {
        if (m_watchdog.resume()) {
            checkWatchdog();
            emit resumed();
        }
    });
    connect(m_player, &VideoPlayer::stateChanged, this, &TeleopVideoPane::checkWatchdog);
    connect(m_timer, &QTimer::timeout, this, &TeleopVideoPane::checkWatchdog);
    m_timer->start(100);
    updateStatus();
}

TeleopVideoPane::~TeleopVideoPane() {
    if (m_window) {
        disconnect(m_window, nullptr, this, nullptr); // no playback decisions while going away
        delete m_window.data();
    }
}

void TeleopVideoPane::setCameras(const QVector<JausVideoEndpoint>& cameras) {
    if (cameras == m_cameras)
        return;
    const auto current = currentCamera();
    m_cameras = cameras;
    m_cameraBox->clear();
    int keep = cameras.isEmpty() ? -1 : 0;
    for (int i = 0; i < cameras.size(); ++i) {
        const JausVideoEndpoint& c = cameras[i];
        QString name = c.name.isEmpty() ? tr("camera %1").arg(c.sensorId) : c.name;
        if (c.configured)
            name += tr(" (configured)");
        m_cameraBox->addItem(name, c.url);
        m_cameraBox->setItemData(
            i,
            c.panTilt ? tr("%1 — pan-tilt: J/L/I/K, the stick's camera mode or the joystick hat").arg(c.url)
                      : c.url,
            Qt::ToolTipRole);
        if (current && current->url == c.url)
            keep = i;
    }
    m_cameraBox->setEnabled(cameras.size() > 1);
    if (keep >= 0)
        m_cameraBox->setCurrentIndex(keep);
    if (!current || keep < 0 || cameras[keep].url != current->url)
        play();
}

std::optional<JausVideoEndpoint> TeleopVideoPane::currentCamera() const {
    const int i = m_cameraBox->currentIndex();
    if (i < 0 || i >= m_cameras.size())
        return std::nullopt;
    return m_cameras[i];
}

void TeleopVideoPane::selectCamera(int index) {
    if (index < 0 || index >= m_cameras.size() || index == m_cameraBox->currentIndex())
        return;
    m_cameraBox->setCurrentIndex(index);
    play();
    emit cameraChanged();
}

void TeleopVideoPane::play() {
    // A new stream: the watchdog waits for its first frame without latching on the way; a trip already
    // there stays until the operator resumes (another camera does not clear it).
    m_watchdog.restartStream();
    const auto cam = currentCamera();
    if (!cam) {
        m_player->stop();
        m_player->setUrl({});
    } else {
        m_player->setUrl(cam->url);
        if (wantsVideo() && !m_player->isActive())
            m_player->play();
    }
    checkWatchdog();
}

void TeleopVideoPane::updatePlayback() {
    const bool want = wantsVideo() && currentCamera();
    if (want == m_player->isActive())
        return;
    // Not shown: nothing received or decoded. Driving is not possible meanwhile (the panel releases its
    // controls when hidden, and the watchdog waits for video again); an existing trip is kept.
    m_watchdog.restartStream();
    if (want)
        m_player->play();
    else
        m_player->stop();
    checkWatchdog();
}

void TeleopVideoPane::setOverlay(const QStringList& lines) {
    m_overlay = lines;
    m_view->setOverlay(lines);
    if (m_windowView)
        m_windowView->setOverlay(lines);
}

void TeleopVideoPane::checkWatchdog() {
    m_watchdog.setRequired(!m_cameras.isEmpty());
    const VideoFrame f = m_player->currentFrame();
    std::optional<std::int64_t> frameMs;
    if (f.number)
        frameMs = f.captureUs.value_or(f.arrivalUs) / 1000;
    m_watchdog.setClock(m_player->clock()); // the frame times are on the player's clock
    m_watchdog.setStream(m_player->state(), frameMs);
    m_watchdog.check();
    const bool allows = m_watchdog.allowsDriving(), tripped = m_watchdog.tripped(),
               good = m_watchdog.videoGood();
    updateStatus();
    if (allows != m_lastAllows || tripped != m_lastTripped || good != m_lastGood) {
        m_lastAllows = allows;
        m_lastTripped = tripped;
        m_lastGood = good;
        emit watchdogChanged();
    }
}

void TeleopVideoPane::updateStatus() {
    m_resume->setEnabled(m_watchdog.tripped() && m_watchdog.videoGood());
    m_resume->setVisible(m_watchdog.tripped());
    const QString alert = m_watchdog.tripped() ? m_watchdog.reason() : QString();
    m_view->setAlert(alert);
    if (m_windowView)
        m_windowView->setAlert(alert);
    m_stream->setText(m_cameras.isEmpty() ? tr("no camera") : m_view->streamText());
}

void TeleopVideoPane::openFullScreen() {
    if (m_window) {
        m_window->raise();
        m_window->activateWindow();
        return;
    }
    m_windowView = new VideoView;
    m_windowView->setPlayer(m_player);
    m_windowView->setOverlay(m_overlay);
    m_windowView->setPlaceholder(tr("No camera on this vehicle"));
    auto* w = new FullScreenVideo(m_windowView, this);
    if (m_keyFilter)
        w->installEventFilter(m_keyFilter);
    connect(w, &QObject::destroyed, this, [this] {
        m_windowView = nullptr;
        m_window = nullptr;
        updatePlayback();
    });
    m_window = w;
    updatePlayback();
    updateStatus();
    w->showFullScreen();
    w->activateWindow();
    w->setFocus();
}

void TeleopVideoPane::closeFullScreen() {
    if (m_window)
        m_window->close();
}

} // namespace ocu
