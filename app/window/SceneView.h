#pragma once

#include "Settings.h"

#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>

#include <memory>
#include <optional>

namespace shadowlab {

class LightGizmoPass;
class Loupe;
class Renderer;

// The lit scene in a QOpenGLWidget: one Renderer on this widget's context, drawn only when
// the settings change or the widget needs repainting. Mouse input does not move the camera
// itself: it asks for a new camera (cameraEdited) so the window can share it between views.
//   left drag: orbit · right or middle drag: pan · wheel: zoom · R or Home: reset the camera
class SceneView : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    // `settings` must have passed validate(). If the driver still refuses them (a map larger
    // than it allows), renderFailed() says why and the last settings that worked are drawn.
    void setSettings(const Settings& settings);
    const Settings& settings() const { return m_settings; }
    void setShowLightVolume(bool show);
    // An image painted over the scene, stretched to the view (the accuracy dock's error image);
    // a null image removes it.
    void setErrorOverlay(const QImage& image);
    const QImage& errorOverlay() const { return m_errorOverlay; }
    bool showLightVolume() const { return m_showLightVolume; }
    // The loupe: the pixels under the pointer magnified beside it, from the last frame (read
    // back after each frame while it is on; moving the pointer redraws no frame).
    void setLoupe(bool on);
    bool loupe() const { return m_loupe != nullptr; }
    // The last frame as read back for the loupe (null while it is off).
    const QImage& loupeFrame() const { return m_loupeFrame; }

    // Null until the first initializeGL() and after the context goes away.
    const Renderer* renderer() const { return m_renderer.get(); }
    // The y of the scene's ground plane, which orbiting keeps the camera above (none: free).
    std::optional<double> groundHeight() const;
    // The settings of the image on screen (the last ones that rendered).
    const std::optional<Settings>& renderedSettings() const { return m_rendered; }
    int frameCount() const { return m_frameCount; }
    // Draws the frame again with the shadow map redrawn too, so the shadow pass is timed.
    void redrawForMeasurement();
    double lastFrameMs() const { return m_lastFrameMs; }

    QSize minimumSizeHint() const override { return {0, 0}; }
    QSize sizeHint() const override { return {640, 480}; }

signals:
    void frameRendered();
    void renderFailed(const QString& key, const QString& message);
    void cameraEdited(const shadowlab::CameraSettings& camera);
    // Ctrl+drag: turn the light by these degrees of azimuth and elevation around its target.
    void lightTurned(double azimuthDegrees, double elevationDegrees);
    void activated();   // pressed: the window selects this view's side

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void cleanup();
    void renderFrame(const Settings& settings);

    Settings m_settings;
    std::optional<Settings> m_rendered;
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<LightGizmoPass> m_gizmo;
    bool m_showLightVolume = true;
    QImage m_errorOverlay;
    Loupe* m_loupe = nullptr;
    QImage m_loupeFrame;
    QPoint m_lastMouse;
    int m_frameCount = 0;
    double m_lastFrameMs = 0.0;
};

} // namespace shadowlab
