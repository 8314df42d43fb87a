#include "widgets/view3d/Site3DView.h"

#include "widgets/view3d/EglOffscreenRenderer.h"
#include "widgets/view3d/SiteSceneRenderer.h"
#include "widgets/view3d/VtkOpenGLWidget.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QEvent>
#include <QGuiApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QSurfaceFormat>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>

#include <functional>
#include <utility>

namespace ocu {

namespace {

// Headless stand-in for the GL widget: paints the last EGL-rendered image. The image is re-rendered lazily in
// paintEvent when the scene changed, so a grab() always shows the current scene.
class ImageView : public QWidget {
public:
    std::function<QImage(QSize)> render;
    std::function<void(QPointF)> clicked;
    std::function<void(QPointF)> doubleClicked; // double-click selects (and follows)
    std::function<void(QPointF)> dragged;       // left-button drag, device pixels since the last move
    std::function<void(double)> wheeled;        // wheel steps (+ = away from the user = zoom in)
    QString message;

    explicit ImageView(QWidget* parent) : QWidget(parent) {
        setMinimumSize(64, 64);
        setAttribute(Qt::WA_OpaquePaintEvent);
    }
    void markDirty() { m_dirty = true; }
    QSize pixelSize() const {
        const qreal dpr = devicePixelRatioF();
        return {qMax(1, qRound(width() * dpr)), qMax(1, qRound(height() * dpr))};
    }

protected:
    void paintEvent(QPaintEvent*) override {
        const QSize want = pixelSize();
        if ((m_dirty || m_image.size() != want) && render) {
            m_image = render(want);
            m_image.setDevicePixelRatio(devicePixelRatioF());
            m_dirty = false;
        }
        QPainter p(this);
        if (m_image.isNull()) {
            p.fillRect(rect(), QColor(60, 60, 60));
            p.setPen(Qt::white);
            p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
                       message.isEmpty() ? tr("3D view unavailable") : message);
            return;
        }
        p.drawImage(QPointF(0, 0), m_image);
    }
    void resizeEvent(QResizeEvent*) override { m_dirty = true; }
    void mousePressEvent(QMouseEvent* e) override { m_press = m_last = e->position(); }
    void mouseMoveEvent(QMouseEvent* e) override {
        if (!(e->buttons() & Qt::LeftButton) || !dragged)
            return;
        const QPointF delta = (e->position() - m_last) * devicePixelRatioF();
        m_last = e->position();
        dragged(delta);
    }
    void wheelEvent(QWheelEvent* e) override {
        if (wheeled && e->angleDelta().y() != 0)
            wheeled(e->angleDelta().y() / 120.0);
        e->accept();
    }
    void mouseDoubleClickEvent(QMouseEvent* e) override {
        if (e->button() == Qt::LeftButton && doubleClicked)
            doubleClicked(e->position() * devicePixelRatioF());
    }
    void mouseReleaseEvent(QMouseEvent* e) override {
        if (e->button() == Qt::LeftButton && (e->position() - m_press).manhattanLength() <= 4 && clicked) {
            const qreal dpr = devicePixelRatioF();
            clicked(e->position() * dpr);
        }
    }

private:
    QImage m_image;
    bool m_dirty = true;
    QPointF m_press;
    QPointF m_last;
};

// Stands in for the GL widget until the panel is painted for the first time (really on screen).
class CanvasPlaceholder : public QWidget {
public:
    CanvasPlaceholder(QWidget* parent, std::function<void()> firstPaint)
        : QWidget(parent), m_firstPaint(std::move(firstPaint)) {}

protected:
    void paintEvent(QPaintEvent*) override {
        if (m_firstPaint)
            QTimer::singleShot(0, parentWidget(), std::exchange(m_firstPaint, {}));
    }

private:
    std::function<void()> m_firstPaint;
};

// Pass-count legend in the top-right corner of its parent (the GL widget or the image view).
class LegendOverlay : public QWidget {
public:
    explicit LegendOverlay(QWidget* parent) : QWidget(parent) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        parent->installEventFilter(this);
        hide();
    }
    void setEntries(const std::vector<LegendEntry>& entries) {
        m_entries = entries;
        const QFontMetrics fm(font());
        int w = 0;
        for (const LegendEntry& e : m_entries)
            w = qMax(w, fm.horizontalAdvance(e.label));
        // The title too ("Überfahrten" is wider than any entry): nothing cut off.
        w = qMax(w, fm.horizontalAdvance(title()) - kSwatch - kGap);
        resize(w + 2 * kPad + kSwatch + kGap, static_cast<int>(m_entries.size()) * kRow + 2 * kPad + kRow);
        setVisible(!m_entries.empty());
        place();
        update();
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == parentWidget() && event->type() == QEvent::Resize)
            place();
        return false;
    }
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 215));
        p.drawRoundedRect(rect().adjusted(0, 0, -1, -1), 4, 4);
        p.setPen(Qt::black);
        p.drawText(QRect(kPad, kPad, width() - 2 * kPad, kRow), Qt::AlignVCenter, title());
        int y = kPad + kRow;
        for (const LegendEntry& e : m_entries) {
            p.fillRect(QRect(kPad, y + 3, kSwatch, kRow - 6), QColor(e.colour.r, e.colour.g, e.colour.b));
            p.drawText(QRect(kPad + kSwatch + kGap, y, width(), kRow), Qt::AlignVCenter, e.label);
            y += kRow;
        }
    }

private:
    static QString title() {
        return QCoreApplication::translate("ocu::LegendOverlay",
                                           "Passes"); // no Q_OBJECT: tr() would use "QWidget"
    }
    void place() {
        if (parentWidget() != nullptr)
            move(parentWidget()->width() - width() - 8, 8);
    }
    static constexpr int kPad = 6, kSwatch = 16, kGap = 6, kRow = 18;
    std::vector<LegendEntry> m_entries;
};

} // namespace

struct Site3DView::Impl {
    SiteSceneRenderer scene;
    Backend backend = Backend::OpenGLWidget;
    VtkOpenGLWidget* gl = nullptr;
    ImageView* image = nullptr;
    std::unique_ptr<EglOffscreenRenderer> egl;
    LegendOverlay* legend = nullptr;
    std::vector<LegendEntry> legendEntries;
    QVBoxLayout* layout = nullptr;
    QWidget* placeholder = nullptr; // stands in for the GL widget until the panel is first shown
    QTimer renderTimer;
    QAction* orbit = nullptr;
    QAction* follow = nullptr;
    QAction* top = nullptr;
    QString status;
};

Site3DView::Site3DView(QWidget* parent) : QWidget(parent), m_impl(std::make_unique<Impl>()) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    auto* toolbar = new QToolBar(this);
    toolbar->setObjectName(QStringLiteral("view3dToolbar"));
    auto* group = new QActionGroup(this);
    m_impl->orbit = toolbar->addAction(tr("Orbit"));
    m_impl->orbit->setToolTip(tr("Free orbit camera (drag to rotate, wheel to zoom)"));
    m_impl->follow = toolbar->addAction(tr("Follow"));
    m_impl->follow->setToolTip(tr("Keep the selected machine in the centre"));
    m_impl->top = toolbar->addAction(tr("Top"));
    m_impl->top->setToolTip(tr("Top-down view, north up"));
    for (QAction* a : {m_impl->orbit, m_impl->follow, m_impl->top}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    m_impl->orbit->setChecked(true);
    toolbar->addSeparator();
    QAction* reset = toolbar->addAction(tr("Reset view"));
    connect(m_impl->orbit, &QAction::triggered, this, [this] { setCameraMode(CameraMode::FreeOrbit); });
    connect(m_impl->follow, &QAction::triggered, this, [this] { setCameraMode(CameraMode::FollowSelected); });
    connect(m_impl->top, &QAction::triggered, this, [this] { setCameraMode(CameraMode::TopDown); });
    connect(reset, &QAction::triggered, this, [this] { resetCamera(); });
    layout->addWidget(toolbar);

    m_impl->layout = layout;
    if (useOffscreenImage()) {
        m_impl->backend = Backend::OffscreenImage;
        m_impl->egl = std::make_unique<EglOffscreenRenderer>();
        m_impl->image = new ImageView(this);
        m_impl->image->render = [this](QSize size) {
            QImage img = m_impl->egl->render(m_impl->scene, size);
            m_impl->status =
                img.isNull() ? tr("3D view unavailable: %1").arg(m_impl->egl->errorString()) : QString();
            m_impl->image->message = m_impl->status;
            return img;
        };
        m_impl->image->clicked = [this](QPointF px) {
            const QString id = m_impl->scene.pick(px.x(), px.y());
            if (!id.isEmpty()) {
                setSelectedMachine(id);
                emit machinePicked(id);
            }
        };
        m_impl->image->doubleClicked = [this](QPointF px) {
            activateMachine(m_impl->scene.pick(px.x(), px.y()));
        };
        // Same feel as the GL widget's trackball: a quarter degree per pixel, 10 % per wheel step.
        m_impl->image->dragged = [this](QPointF delta) {
            m_impl->scene.orbit(-delta.x() * 0.25, delta.y() * 0.25);
            scheduleRender();
        };
        m_impl->image->wheeled = [this](double steps) {
            m_impl->scene.zoom(std::pow(1.1, steps));
            scheduleRender();
        };
        if (!m_impl->egl->initialize()) {
            m_impl->status = tr("3D view unavailable: %1").arg(m_impl->egl->errorString());
            m_impl->image->message = m_impl->status;
        }
        // Throttle: scene changes within 50 ms are drawn once (at most 20 renders per second).
        m_impl->renderTimer.setSingleShot(true);
        m_impl->renderTimer.setInterval(50);
        connect(&m_impl->renderTimer, &QTimer::timeout, m_impl->image, qOverload<>(&QWidget::update));
        m_impl->image->setObjectName(QStringLiteral("view3dCanvas"));
        layout->addWidget(m_impl->image, 1);
        m_impl->legend = new LegendOverlay(m_impl->image);
    } else {
        // The QOpenGLWidget is created when the panel is first shown (ensureCanvas): a window that has never
        // held one composes its widgets without OpenGL, so a console whose 3D tab stays closed pays nothing
        // for it.
        m_impl->backend = Backend::OpenGLWidget;
        m_impl->placeholder = new CanvasPlaceholder(this, [this] { ensureCanvas(); });
        layout->addWidget(m_impl->placeholder, 1);
    }
}

QWidget* Site3DView::ensureCanvas() const {
    if (m_impl->image != nullptr)
        return m_impl->image;
    if (m_impl->gl == nullptr) {
        auto* self = const_cast<Site3DView*>(this);
        m_impl->gl = new VtkOpenGLWidget(&m_impl->scene, self);
        connect(m_impl->gl, &VtkOpenGLWidget::machinePicked, self, [self](const QString& id) {
            self->setSelectedMachine(id);
            emit self->machinePicked(id);
        });
        connect(m_impl->gl, &VtkOpenGLWidget::machineDoubleClicked, self, &Site3DView::activateMachine);
        m_impl->gl->setObjectName(QStringLiteral("view3dCanvas"));
        m_impl->layout->replaceWidget(m_impl->placeholder, m_impl->gl);
        m_impl->placeholder->deleteLater();
        m_impl->placeholder = nullptr;
        m_impl->legend = new LegendOverlay(m_impl->gl);
        m_impl->legend->setEntries(m_impl->legendEntries);
    }
    return m_impl->gl;
}

void Site3DView::showEvent(QShowEvent* event) {
    // Not at once: a QMainWindow shows every dock when it is first shown and only then hides the tabs that
    // are not current; the GL widget is made once the panel is still shown after that (and then at once
    // when it is really raised).
    if (m_impl->image == nullptr && m_impl->gl == nullptr)
        QTimer::singleShot(0, this, [this] {
            if (isVisible() && !visibleRegion().isEmpty())
                ensureCanvas();
        });
    QWidget::showEvent(event);
    // Changes that arrived while hidden were not drawn: draw the current state once.
    if (m_impl->image != nullptr)
        m_impl->image->markDirty();
    emit visibilityChanged(true);
}

void Site3DView::hideEvent(QHideEvent* event) {
    QWidget::hideEvent(event);
    emit visibilityChanged(false);
}

std::uint64_t Site3DView::renderCount() const {
    return m_impl->scene.renderCount();
}

Site3DView::~Site3DView() {
    // The GL widget holds the scene's renderer; delete it before the scene (a member of m_impl) goes away.
    delete m_impl->gl;
    m_impl->gl = nullptr;
}

void Site3DView::prepareDefaultFormat() {
    QSurfaceFormat::setDefaultFormat(VtkOpenGLWidget::defaultFormat());
}

bool Site3DView::useOffscreenImage() {
    if (qEnvironmentVariableIntValue("OCU_VIEW3D_IMAGE") == 1)
        return true;
    const QString platform = QGuiApplication::platformName();
    return platform == QLatin1String("offscreen") || platform == QLatin1String("minimal");
}

Site3DView::Backend Site3DView::backend() const {
    return m_impl->backend;
}

QString Site3DView::statusMessage() const {
    return m_impl->status;
}

void Site3DView::scheduleRender() {
    if (m_impl->gl != nullptr) {
        if (isVisible())
            m_impl->gl->requestRender(); // Qt coalesces repaints
        return;
    }
    if (m_impl->image == nullptr)
        return; // no canvas yet: the first show draws the current scene
    m_impl->image->markDirty();
    if (isVisible() && !m_impl->renderTimer.isActive())
        m_impl->renderTimer.start();
}

void Site3DView::setScene(const Scene3D& scene) {
    m_impl->scene.setScene(scene);
    m_impl->legendEntries = scene.legend;
    if (m_impl->legend != nullptr)
        m_impl->legend->setEntries(scene.legend);
    scheduleRender();
}

void Site3DView::updateMachines(const std::vector<Machine3D>& machines) {
    m_impl->scene.updateMachines(machines);
    scheduleRender();
}

void Site3DView::setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend) {
    m_impl->scene.setPassCount(raster, legend);
    m_impl->legendEntries = legend;
    if (m_impl->legend != nullptr)
        m_impl->legend->setEntries(legend);
    scheduleRender();
}

void Site3DView::setSelectedMachine(const QString& id) {
    if (id == m_impl->scene.selectedMachine())
        return;
    m_impl->scene.setSelectedMachine(id);
    scheduleRender();
}

QString Site3DView::selectedMachine() const {
    return m_impl->scene.selectedMachine();
}

void Site3DView::setCameraMode(CameraMode mode) {
    const bool changed = mode != m_impl->scene.cameraMode();
    m_impl->scene.setCameraMode(mode);
    syncModeButtons();
    scheduleRender();
    if (changed)
        emit cameraModeChanged(mode);
}

CameraMode Site3DView::cameraMode() const {
    return m_impl->scene.cameraMode();
}

void Site3DView::resetCamera() {
    m_impl->scene.resetCamera();
    scheduleRender();
}

void Site3DView::syncModeButtons() {
    switch (m_impl->scene.cameraMode()) {
    case CameraMode::FreeOrbit:
        m_impl->orbit->setChecked(true);
        break;
    case CameraMode::FollowSelected:
        m_impl->follow->setChecked(true);
        break;
    case CameraMode::TopDown:
        m_impl->top->setChecked(true);
        break;
    }
}

QImage Site3DView::renderImage(QSize size) {
    if (size.isEmpty())
        size = viewPixelSize();
    if (m_impl->egl) {
        QImage img = m_impl->egl->render(m_impl->scene, size);
        m_impl->image->markDirty(); // the shared window now has `size`; repaint the panel at its own size
        m_impl->image->update();
        return img;
    }
    ensureCanvas();
    const QImage frame = m_impl->gl->grabFramebuffer();
    if (frame.isNull() || frame.size() == size)
        return frame;
    return frame.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

SiteSceneRenderer& Site3DView::sceneRenderer() {
    return m_impl->scene;
}

QSize Site3DView::viewPixelSize() const {
    const QWidget* v = viewWidget();
    const qreal dpr = v->devicePixelRatioF();
    return {qMax(1, qRound(v->width() * dpr)), qMax(1, qRound(v->height() * dpr))};
}

QWidget* Site3DView::viewWidget() const {
    return ensureCanvas();
}

void Site3DView::activateMachine(const QString& id) {
    // A double-click selects in every view: as on the 2D map (select and centre), the machine
    // becomes the selection and the camera follows it.
    if (id.isEmpty())
        return;
    setSelectedMachine(id);
    emit machinePicked(id);
    setCameraMode(CameraMode::FollowSelected);
    emit machineActivated(id);
}

} // namespace ocu
