#pragma once
// The 3D site panel. At run time it picks how to draw:
//  - normal platforms (xcb, wayland...): a VtkOpenGLWidget (interactive VTK in a QOpenGLWidget);
//  - offscreen/minimal platforms (headless, --screenshot): never a QOpenGLWidget (Qt 6.4 crashes there); the
//    scene is rendered through EglOffscreenRenderer (Mesa EGL surfaceless, X fallback) into an image that a
//    plain QWidget paints, so QWidget::grab() of the main window contains the 3D picture.
// Camera-mode buttons sit in a small toolbar; the pass-count legend is an overlay in the top-right corner.
#include "widgets/view3d/Scene3D.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <vector>

namespace ocu {

class SiteSceneRenderer;

class Site3DView : public QWidget {
    Q_OBJECT
public:
    enum class Backend { OpenGLWidget, OffscreenImage };

    explicit Site3DView(QWidget* parent = nullptr);
    ~Site3DView() override;

    // Call once in main() before constructing QApplication (OpenGL 3.2 core default format for VTK).
    static void prepareDefaultFormat();
    // True when the current platform cannot host a QOpenGLWidget (offscreen, minimal) or OCU_VIEW3D_IMAGE=1.
    static bool useOffscreenImage();

    Backend backend() const;
    // Empty when the view can draw; otherwise why not (e.g. no EGL and no DISPLAY). Also shown in the panel.
    QString statusMessage() const;

    void setScene(const Scene3D& scene);                         // full rebuild
    void updateMachines(const std::vector<Machine3D>& machines); // fast path, no rebuild
    void setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend);
    void setSelectedMachine(const QString& id);
    QString selectedMachine() const;
    void setCameraMode(CameraMode mode);
    CameraMode cameraMode() const;
    void resetCamera();

    // A picture of the 3D scene at `size` device pixels (EGL path headless; the GL widget's framebuffer
    // otherwise).
    QImage renderImage(QSize size);

    SiteSceneRenderer& sceneRenderer();
    // Redraw soon (after a change made directly on sceneRenderer().renderer(), e.g. an overlay's actor).
    void refresh() { scheduleRender(); }

    // Size of the drawing area in device pixels (what pick/project coordinates refer to).
    QSize viewPixelSize() const;
    // The widget that shows the 3D picture (the QOpenGLWidget or the image widget); for tests and event
    // filters. The QOpenGLWidget is created on the first show (or by this call).
    QWidget* viewWidget() const;
    // Frames of the 3D scene drawn so far (any backend). It does not move while the panel is hidden.
    std::uint64_t renderCount() const;

signals:
    // A machine was clicked in the 3D view (it is also selected locally). Connect to the shared selection.
    void machinePicked(const QString& id);
    // A machine was double-clicked: selected (machinePicked too) and the camera follows it.
    void machineActivated(const QString& id);
    void cameraModeChanged(ocu::CameraMode mode);
    // The panel was shown (true) or hidden (false), e.g. its tab was raised or another tab covered it.
    void visibilityChanged(bool visible);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void activateMachine(const QString& id);
    void scheduleRender();
    void syncModeButtons();
    QWidget* ensureCanvas() const;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
