#include "widgets/view3d/EglOffscreenRenderer.h"

#include "widgets/view3d/SiteSceneRenderer.h"

#include "protocols/common/Log.h"

// GLEW first (it must precede any GL header); VTK uses the system GLEW on Debian.
#include <vtk_glew.h>

// Keep X11's macros (None, Bool, Status...) out of this file: the EGL path does not use X at all.
#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <QFileInfo>
#include <QtGlobal>

#include <cstring>

namespace ocu {

namespace {

// Debian's GLEW is built for GLX: with an EGL context glewInit() loads every entry point and then reports
// GLEW_ERROR_NO_GLX_DISPLAY. VTK would treat that as fatal and log an error on every frame
// (toolchain.md §4(b)), so this window accepts that result and marks the context as initialised itself.
class EglGenericRenderWindow : public vtkGenericOpenGLRenderWindow {
public:
    static EglGenericRenderWindow* New();
    vtkTypeMacro(EglGenericRenderWindow, vtkGenericOpenGLRenderWindow);

    void OpenGLInitContext() override {
        if (!this->Initialized) {
            const GLenum result = glewInit();
            if (result != GLEW_OK && result != GLEW_ERROR_NO_GLX_DISPLAY) {
                vtkErrorMacro("GLEW could not be initialized: " << glewGetErrorString(result));
                return;
            }
            if (!GLEW_VERSION_3_2) {
                vtkErrorMacro("EGL context does not provide OpenGL 3.2");
                return;
            }
            this->GlewInitValid = true;
            this->Initialized = true;
            GLfloat range[2] = {1.0f, 1.0f};
            glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
            this->MaximumHardwareLineWidth = glGetError() == GL_NO_ERROR ? range[1] : 1.0f;
        }
        // With Initialized set, the base class only stamps the context creation time.
        this->Superclass::OpenGLInitContext();
    }

    bool contextReady() const { return this->Initialized && this->GlewInitValid; }

protected:
    EglGenericRenderWindow() = default;
    ~EglGenericRenderWindow() override = default;
};
vtkStandardNewMacro(EglGenericRenderWindow);

// One EGLDisplay per process for the surfaceless platform: eglGetPlatformDisplay returns the same handle each
// time, so eglTerminate is only called when the last user goes away.
int g_eglDisplayUsers = 0;

bool localXServerReachable(const QString& display) {
    // ":N" or ":N.S" -> /tmp/.X11-unix/XN. VTK aborts (not a catchable error) on a bad X connection, so check
    // first; remote displays ("host:N") are trusted as given.
    if (display.isEmpty())
        return false;
    if (!display.startsWith(QLatin1Char(':')))
        return true;
    const QString number = display.mid(1).section(QLatin1Char('.'), 0, 0);
    return QFileInfo::exists(QStringLiteral("/tmp/.X11-unix/X") + number);
}

} // namespace

struct EglOffscreenRenderer::Impl {
    Backend backend = Backend::None;
    bool tried = false;
    QString error;
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    vtkSmartPointer<vtkRenderWindow> window;
    vtkNew<vtkUnsignedCharArray> pixels;

    static void onMakeCurrent(vtkObject*, unsigned long, void* clientData, void*) {
        auto* self = static_cast<Impl*>(clientData);
        eglMakeCurrent(self->display, EGL_NO_SURFACE, EGL_NO_SURFACE, self->context);
    }
    static void onIsCurrent(vtkObject*, unsigned long, void* clientData, void* callData) {
        auto* self = static_cast<Impl*>(clientData);
        *static_cast<bool*>(callData) = eglGetCurrentContext() == self->context;
    }

    bool initEgl() {
        const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (clientExt == nullptr || std::strstr(clientExt, "EGL_MESA_platform_surfaceless") == nullptr) {
            error = QStringLiteral("EGL: the Mesa surfaceless platform is not available");
            return false;
        }
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (getPlatformDisplay == nullptr) {
            error = QStringLiteral("EGL: eglGetPlatformDisplayEXT is missing");
            return false;
        }
        display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || eglInitialize(display, &major, &minor) != EGL_TRUE) {
            error = QStringLiteral("EGL: cannot initialise the surfaceless display (0x%1)")
                        .arg(eglGetError(), 0, 16);
            display = EGL_NO_DISPLAY;
            return false;
        }
        ++g_eglDisplayUsers;
        if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
            error = QStringLiteral("EGL: desktop OpenGL API not available");
            return false;
        }
        const EGLint configAttribs[] = {EGL_SURFACE_TYPE,
                                        EGL_PBUFFER_BIT,
                                        EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT,
                                        EGL_RED_SIZE,
                                        8,
                                        EGL_GREEN_SIZE,
                                        8,
                                        EGL_BLUE_SIZE,
                                        8,
                                        EGL_ALPHA_SIZE,
                                        8,
                                        EGL_DEPTH_SIZE,
                                        24,
                                        EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (eglChooseConfig(display, configAttribs, &config, 1, &count) != EGL_TRUE || count < 1) {
            error = QStringLiteral("EGL: no OpenGL config with RGBA8/depth 24");
            return false;
        }
        // VTK 9.1 needs a 3.2 core context (toolchain.md §4(a)).
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         2,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
        if (context == EGL_NO_CONTEXT) {
            error = QStringLiteral("EGL: cannot create an OpenGL 3.2 core context (0x%1)")
                        .arg(eglGetError(), 0, 16);
            return false;
        }
        if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
            error = QStringLiteral("EGL: surfaceless make-current failed (0x%1)").arg(eglGetError(), 0, 16);
            return false;
        }
        vtkNew<EglGenericRenderWindow> rw;
        vtkNew<vtkCallbackCommand> makeCurrent;
        makeCurrent->SetCallback(&Impl::onMakeCurrent);
        makeCurrent->SetClientData(this);
        vtkNew<vtkCallbackCommand> isCurrent;
        isCurrent->SetCallback(&Impl::onIsCurrent);
        isCurrent->SetClientData(this);
        rw->AddObserver(vtkCommand::WindowMakeCurrentEvent, makeCurrent);
        rw->AddObserver(vtkCommand::WindowIsCurrentEvent, isCurrent);
        rw->SetOwnContext(0);
        rw->SetFrameBlitModeToNoBlit();
        rw->SetMultiSamples(0);
        rw->SetForceMaximumHardwareLineWidth(1);
        rw->SetReadyForRendering(true);
        rw->SetSize(64, 64);
        rw->OpenGLInit(); // glewInit (via the override above) and VTK's initial GL state, inside our context
        if (!rw->contextReady()) {
            error = QStringLiteral("EGL: VTK could not initialise the OpenGL context");
            return false;
        }
        window = rw;
        backend = Backend::EglSurfaceless;
        return true;
    }

    bool initX() {
        const QString display = qEnvironmentVariable("DISPLAY");
        if (!localXServerReachable(display))
            return false;
        window = vtkSmartPointer<vtkRenderWindow>::New(); // vtkXOpenGLRenderWindow in Debian's build
        window->SetOffScreenRendering(1);
        window->SetMultiSamples(0);
        window->SetSize(64, 64);
        backend = Backend::XOffscreen;
        return true;
    }

    void releaseEgl() {
        if (display != EGL_NO_DISPLAY) {
            if (context != EGL_NO_CONTEXT) {
                eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                eglDestroyContext(display, context);
            }
            if (--g_eglDisplayUsers == 0)
                eglTerminate(display);
        }
        display = EGL_NO_DISPLAY;
        context = EGL_NO_CONTEXT;
    }

    ~Impl() {
        if (window) {
            window
                ->Finalize(); // releases GL resources of every attached renderer while our context is current
            vtkRendererCollection* renderers = window->GetRenderers();
            while (renderers->GetNumberOfItems() > 0)
                window->RemoveRenderer(renderers->GetFirstRenderer());
            window = nullptr;
        }
        releaseEgl();
    }
};

EglOffscreenRenderer::EglOffscreenRenderer() : m_impl(std::make_unique<Impl>()) {}
EglOffscreenRenderer::~EglOffscreenRenderer() = default;

bool EglOffscreenRenderer::initialize() {
    if (m_impl->tried)
        return m_impl->backend != Backend::None;
    m_impl->tried = true;
    // OCU_VIEW3D_NO_EGL=1 skips EGL (diagnosis, and tests of the fallback paths).
    if (qEnvironmentVariableIntValue("OCU_VIEW3D_NO_EGL") == 1)
        m_impl->error = QStringLiteral("EGL disabled by OCU_VIEW3D_NO_EGL=1");
    else if (m_impl->initEgl())
        return true;
    const QString eglError = m_impl->error;
    m_impl->window = nullptr;
    m_impl->releaseEgl();
    if (m_impl->initX()) {
        m_impl->error.clear();
        return true;
    }
    m_impl->error = eglError + (qEnvironmentVariable("DISPLAY").isEmpty()
                                    ? QStringLiteral("; no X server for the fallback (DISPLAY is not set)")
                                    : QStringLiteral("; the X server in DISPLAY is not reachable"));
    logWarning("ocu.view3d", m_impl->error.toStdString());
    return false;
}

EglOffscreenRenderer::Backend EglOffscreenRenderer::backend() const {
    return m_impl->backend;
}

QString EglOffscreenRenderer::backendName() const {
    switch (m_impl->backend) {
    case Backend::EglSurfaceless:
        return QStringLiteral("EGL surfaceless");
    case Backend::XOffscreen:
        return QStringLiteral("X offscreen");
    case Backend::None:
        break;
    }
    return QStringLiteral("none");
}

QString EglOffscreenRenderer::errorString() const {
    return m_impl->error;
}

QImage EglOffscreenRenderer::render(SiteSceneRenderer& scene, QSize size) {
    if (!initialize() || size.isEmpty())
        return {};
    vtkRenderWindow* rw = m_impl->window;
    vtkRenderer* renderer = scene.renderer();
    if (!rw->HasRenderer(renderer)) {
        if (vtkRenderWindow* other = renderer->GetRenderWindow(); other != nullptr && other != rw)
            other->RemoveRenderer(renderer);
        rw->AddRenderer(renderer);
    }
    rw->SetSize(size.width(), size.height());
    renderer->ResetCameraClippingRange();
    rw->Render();
    const int w = size.width(), h = size.height();
    // RGBA is the framebuffer's own layout (a plain copy in Mesa; RGB would be converted pixel by pixel).
    // The background's alpha is 0 (toolchain.md pitfall), so the image format ignores alpha.
    if (rw->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, m_impl->pixels) != 1 /* VTK_OK */) {
        m_impl->error = QStringLiteral("reading the rendered pixels failed");
        return {};
    }
    // RGBX promises 255 in the fourth byte, and some of Qt's copies keep the byte as it is: a screenshot of
    // the 3D panel alone had a transparent sky. The scene is opaque: the alpha bytes are set.
    std::uint8_t* px = m_impl->pixels->GetPointer(0);
    for (std::size_t i = 3, n = std::size_t(w) * std::size_t(h) * 4; i < n; i += 4)
        px[i] = 255;
    // VTK's origin is bottom-left; mirrored() also makes the deep copy.
    const QImage wrapped(px, w, h, w * 4, QImage::Format_RGBX8888);
    return wrapped.mirrored(false, true);
}

} // namespace ocu
