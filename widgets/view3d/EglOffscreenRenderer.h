#pragma once
// Headless rendering of a SiteSceneRenderer into a QImage (toolchain.md §4(b)): a Mesa EGL surfaceless
// context drives a vtkGenericOpenGLRenderWindow, so no X server is needed. When EGL is unavailable and
// DISPLAY is set, VTK's own X offscreen window is used instead; otherwise errorString() says why.
#include <QImage>
#include <QSize>
#include <QString>

#include <memory>

namespace ocu {

class SiteSceneRenderer;

class EglOffscreenRenderer {
public:
    enum class Backend { None, EglSurfaceless, XOffscreen };

    EglOffscreenRenderer();
    ~EglOffscreenRenderer();
    EglOffscreenRenderer(const EglOffscreenRenderer&) = delete;
    EglOffscreenRenderer& operator=(const EglOffscreenRenderer&) = delete;

    // Creates the context on first use; returns false (see errorString()) when no backend works.
    bool initialize();
    Backend backend() const;
    QString backendName() const;
    QString errorString() const;

    // Renders the scene at `size` device pixels. The scene's vtkRenderer is attached to this renderer's
    // window (a vtkRenderer can be in one window at a time). Returns a null image on failure.
    QImage render(SiteSceneRenderer& scene, QSize size);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
