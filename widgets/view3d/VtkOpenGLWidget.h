#pragma once
// Hosts VTK (vtkGenericOpenGLRenderWindow) inside a Qt 6 QOpenGLWidget without VTK's Qt-5-only modules,
// following toolchain.md §4(a). Never create this under the offscreen/minimal platforms (Qt crashes there);
// Site3DView chooses the EGL image path instead.
#include <QOpenGLWidget>
#include <QPoint>
#include <QSurfaceFormat>

#include <memory>

namespace ocu {

class SiteSceneRenderer;

class VtkOpenGLWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    // `scene` must outlive the widget; its vtkRenderer is attached to this widget's render window.
    explicit VtkOpenGLWidget(SiteSceneRenderer* scene, QWidget* parent = nullptr);
    ~VtkOpenGLWidget() override;

    // OpenGL 3.2 core, RGBA8, depth 24, no multisampling: what VTK 9.1 needs. Set it as the application
    // default (QSurfaceFormat::setDefaultFormat) before the QApplication is created.
    static QSurfaceFormat defaultFormat();

    // Schedules a repaint; VTK renders inside paintGL (render on demand, coalesced by Qt).
    void requestRender();
    bool isInitialized() const;

signals:
    // Left click (press and release within a few pixels) on a machine.
    void machinePicked(const QString& id);
    void machineDoubleClicked(const QString& id); // left double-click on a machine
    // The user moved the camera with the mouse, wheel or keys.
    void cameraInteracted();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;

private:
    void releaseVtkGraphics(); // Qt's context is about to go: free VTK's GL objects first
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    QPoint m_pressPos;
    bool m_pressed = false;
};

} // namespace ocu
