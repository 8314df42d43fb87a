#include "widgets/view3d/VtkOpenGLWidget.h"

#include "widgets/view3d/SiteSceneRenderer.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

namespace ocu {

struct VtkOpenGLWidget::Impl {
    VtkOpenGLWidget* q = nullptr;
    SiteSceneRenderer* scene = nullptr;
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    vtkNew<vtkCallbackCommand> makeCurrentCmd;
    vtkNew<vtkCallbackCommand> isCurrentCmd;
    vtkNew<vtkCallbackCommand> frameCmd;
    bool initialized = false;
    bool inPaint = false;

    // QOpenGLContext::makeCurrent, not QOpenGLWidget::makeCurrent: the latter re-binds the widget's FBO
    // behind VTK's state cache and corrupts both framebuffers (toolchain.md §4(a), "the trap").
    static void onMakeCurrent(vtkObject*, unsigned long, void* clientData, void*) {
        auto* self = static_cast<Impl*>(clientData);
        if (QOpenGLContext* ctx = self->q->context();
            ctx != nullptr && QOpenGLContext::currentContext() != ctx)
            ctx->makeCurrent(ctx->surface());
    }
    static void onIsCurrent(vtkObject*, unsigned long, void* clientData, void* callData) {
        auto* self = static_cast<Impl*>(clientData);
        *static_cast<bool*>(callData) =
            self->q->context() != nullptr && QOpenGLContext::currentContext() == self->q->context();
    }
    // A render that VTK starts by itself (outside paintGL) must still reach the screen.
    static void onFrame(vtkObject*, unsigned long, void* clientData, void*) {
        auto* self = static_cast<Impl*>(clientData);
        if (!self->inPaint)
            self->q->update();
    }

    void finalize() {
        if (!initialized)
            return;
        q->makeCurrent();
        window->Finalize(); // frees VTK's GL objects while Qt's context is still alive
        q->doneCurrent();
        initialized = false;
    }
};

VtkOpenGLWidget::VtkOpenGLWidget(SiteSceneRenderer* scene, QWidget* parent)
    : QOpenGLWidget(parent), m_impl(std::make_unique<Impl>()) {
    m_impl->q = this;
    m_impl->scene = scene;
    setFormat(defaultFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(64, 64);

    m_impl->makeCurrentCmd->SetCallback(&Impl::onMakeCurrent);
    m_impl->makeCurrentCmd->SetClientData(m_impl.get());
    m_impl->isCurrentCmd->SetCallback(&Impl::onIsCurrent);
    m_impl->isCurrentCmd->SetClientData(m_impl.get());
    m_impl->frameCmd->SetCallback(&Impl::onFrame);
    m_impl->frameCmd->SetClientData(m_impl.get());
    m_impl->window->AddObserver(vtkCommand::WindowMakeCurrentEvent, m_impl->makeCurrentCmd);
    m_impl->window->AddObserver(vtkCommand::WindowIsCurrentEvent, m_impl->isCurrentCmd);
    m_impl->window->AddObserver(vtkCommand::WindowFrameEvent, m_impl->frameCmd);
    m_impl->window->SetMultiSamples(0);
    m_impl->window->AddRenderer(scene->renderer());

    m_impl->interactor->SetRenderWindow(m_impl->window);
    m_impl->interactor->SetInteractorStyle(m_impl->style);
    // Enable(), never Initialize(): Initialize() renders before Qt has a context (segfault, toolchain.md
    // §4(a)).
    m_impl->interactor->Enable();
    // The style's own Render() calls are suppressed; every forwarded event schedules a Qt repaint instead.
    m_impl->interactor->EnableRenderOff();
}

VtkOpenGLWidget::~VtkOpenGLWidget() {
    m_impl->finalize();
    // QOpenGLWidget's destructor (which runs after m_impl is gone) destroys the context; its
    // aboutToBeDestroyed must not reach releaseVtkGraphics then (a crash seen 1 in 5 runs of test_view3d_gl
    // under load).
    if (QOpenGLContext* c = context())
        disconnect(c, nullptr, this, nullptr);
    m_impl->window->RemoveRenderer(m_impl->scene->renderer());
    m_impl->window->RemoveAllObservers();
}

QSurfaceFormat VtkOpenGLWidget::defaultFormat() {
    QSurfaceFormat f;
    f.setRenderableType(QSurfaceFormat::OpenGL);
    f.setVersion(3, 2);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setRedBufferSize(8);
    f.setGreenBufferSize(8);
    f.setBlueBufferSize(8);
    f.setAlphaBufferSize(8);
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(0);
    f.setSamples(0);
    f.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    return f;
}

void VtkOpenGLWidget::requestRender() {
    update();
}

void VtkOpenGLWidget::releaseVtkGraphics() {
    m_impl->finalize();
}

bool VtkOpenGLWidget::isInitialized() const {
    return m_impl->initialized;
}

void VtkOpenGLWidget::initializeGL() {
    vtkGenericOpenGLRenderWindow* rw = m_impl->window;
    rw->SetOwnContext(0);
    rw->SetReadyForRendering(true);
    rw->SetForceMaximumHardwareLineWidth(1);
    // Default blit mode (BlitToCurrent): VTK copies its result into the FBO Qt has bound for paintGL.
    rw->OpenGLInitContext(); // glewInit inside Qt's context
    m_impl->initialized = true;
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkOpenGLWidget::releaseVtkGraphics,
            Qt::UniqueConnection);
    resizeGL(width(), height());
}

void VtkOpenGLWidget::resizeGL(int, int) {
    const qreal dpr = devicePixelRatioF();
    const int w = qMax(1, qRound(width() * dpr));
    const int h = qMax(1, qRound(height() * dpr));
    m_impl->interactor->UpdateSize(w, h); // also sets the render window size
    m_impl->window->SetSize(w, h);
}

void VtkOpenGLWidget::paintGL() {
    if (!m_impl->initialized)
        return;
    m_impl->inPaint = true;
    m_impl->scene->renderer()->ResetCameraClippingRange();
    m_impl->window->Render(); // pushes/pops VTK's GL state cache itself
    m_impl->inPaint = false;
    // Force alpha to 1 like VTK's own adapter does, or grabs under Mesa come out transparent.
    QOpenGLFunctions* f = context()->functions();
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

namespace {

void setEventInfo(vtkRenderWindowInteractor* iren, QPointF pos, qreal dpr, Qt::KeyboardModifiers mods,
                  int repeat = 0) {
    iren->SetEventInformationFlipY(qRound(pos.x() * dpr), qRound(pos.y() * dpr),
                                   (mods & Qt::ControlModifier) ? 1 : 0, (mods & Qt::ShiftModifier) ? 1 : 0,
                                   0, repeat);
    iren->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
}

unsigned long buttonEvent(Qt::MouseButton b, bool press) {
    switch (b) {
    case Qt::LeftButton:
        return press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
        return press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
        return press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    default:
        return vtkCommand::NoEvent;
    }
}

} // namespace

void VtkOpenGLWidget::mousePressEvent(QMouseEvent* event) {
    setEventInfo(m_impl->interactor, event->position(), devicePixelRatioF(), event->modifiers());
    if (const unsigned long e = buttonEvent(event->button(), true); e != vtkCommand::NoEvent)
        m_impl->interactor->InvokeEvent(e);
    if (event->button() == Qt::LeftButton) {
        m_pressPos = event->position().toPoint();
        m_pressed = true;
    }
    event->accept();
}

void VtkOpenGLWidget::mouseReleaseEvent(QMouseEvent* event) {
    setEventInfo(m_impl->interactor, event->position(), devicePixelRatioF(), event->modifiers());
    if (const unsigned long e = buttonEvent(event->button(), false); e != vtkCommand::NoEvent)
        m_impl->interactor->InvokeEvent(e);
    if (event->button() == Qt::LeftButton && m_pressed) {
        m_pressed = false;
        if ((event->position().toPoint() - m_pressPos).manhattanLength() <= 4) {
            const qreal dpr = devicePixelRatioF();
            const QString id = m_impl->scene->pick(event->position().x() * dpr, event->position().y() * dpr);
            if (!id.isEmpty())
                emit machinePicked(id);
        } else {
            emit cameraInteracted();
        }
    }
    update();
    event->accept();
}

void VtkOpenGLWidget::mouseMoveEvent(QMouseEvent* event) {
    setEventInfo(m_impl->interactor, event->position(), devicePixelRatioF(), event->modifiers());
    m_impl->interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
    if (event->buttons() != Qt::NoButton)
        update();
    event->accept();
}

void VtkOpenGLWidget::mouseDoubleClickEvent(QMouseEvent* event) {
    setEventInfo(m_impl->interactor, event->position(), devicePixelRatioF(), event->modifiers(), 1);
    if (const unsigned long e = buttonEvent(event->button(), true); e != vtkCommand::NoEvent)
        m_impl->interactor->InvokeEvent(e);
    if (event->button() == Qt::LeftButton) {
        const qreal dpr = devicePixelRatioF();
        const QString id = m_impl->scene->pick(event->position().x() * dpr, event->position().y() * dpr);
        if (!id.isEmpty())
            emit machineDoubleClicked(id);
    }
    event->accept();
}

void VtkOpenGLWidget::wheelEvent(QWheelEvent* event) {
    setEventInfo(m_impl->interactor, event->position(), devicePixelRatioF(), event->modifiers());
    const int delta = event->angleDelta().y();
    if (delta > 0)
        m_impl->interactor->InvokeEvent(vtkCommand::MouseWheelForwardEvent);
    else if (delta < 0)
        m_impl->interactor->InvokeEvent(vtkCommand::MouseWheelBackwardEvent);
    emit cameraInteracted();
    update();
    event->accept();
}

void VtkOpenGLWidget::keyPressEvent(QKeyEvent* event) {
    // Only 'r' (reset camera) is forwarded: 'e'/'q' would ask VTK to quit, 'w'/'s' switch every actor to
    // wireframe/surface (including the selection outline), 'f' flies, 'p' picks with VTK's picker.
    const QString text = event->text().toLower();
    if (text == QLatin1String("r")) {
        const QByteArray key = text.toLatin1();
        m_impl->interactor->SetKeyEventInformation((event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                                   (event->modifiers() & Qt::ShiftModifier) ? 1 : 0, key[0],
                                                   event->isAutoRepeat() ? 1 : 0, key.constData());
        m_impl->interactor->InvokeEvent(vtkCommand::KeyPressEvent);
        m_impl->interactor->InvokeEvent(vtkCommand::CharEvent);
        emit cameraInteracted();
        update();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void VtkOpenGLWidget::keyReleaseEvent(QKeyEvent* event) {
    if (event->text().toLower() == QLatin1String("r")) {
        m_impl->interactor->InvokeEvent(vtkCommand::KeyReleaseEvent);
        event->accept();
        return;
    }
    QOpenGLWidget::keyReleaseEvent(event);
}

} // namespace ocu
