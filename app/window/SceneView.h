#pragma once

#include "Settings.h"

#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>

#include <memory>
#include <optional>

class QOpenGLFramebufferObject;

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
    // The wipe: `other` (compare mode's side B) drawn over the same pixels right of a divider
    // that a drag moves, this view's own settings left of it; nullopt ends it. `other` is drawn
    // by a second renderer on this view's context, with caches of its own.
    void setWipe(const std::optional<Settings>& other);
    bool wiping() const { return m_wipe.has_value(); }
    // Where the divider stands, as a share of the width from the left.
    double wipePosition() const { return m_wipePosition; }
    void setWipePosition(double position);
    // The other side's error overlay, shown right of the divider while wiping.
    void setWipeOverlay(const QImage& image);
    // Freeze the shadow frustum: the light stays fitted to `camera` (culling, cascades, the fit)
    // while the view's own camera moves, so fitting and culling can be looked at from outside;
    // the frozen camera's frustum is drawn. nullopt follows the view's camera again.
    void setFrozenCamera(const std::optional<CameraSettings>& camera);
    const std::optional<CameraSettings>& frozenCamera() const { return m_frozenCamera; }

    // Null until the first initializeGL() and after the context goes away.
    const Renderer* renderer() const { return m_renderer.get(); }
    // The y of the scene's ground plane, which orbiting keeps the camera above (none: free).
    std::optional<double> groundHeight() const;
    // The settings of the image on screen (the last ones that rendered).
    const std::optional<Settings>& renderedSettings() const { return m_rendered; }
    int frameCount() const { return m_frameCount; }
    // Draws the frame again with the shadow map redrawn too, so the shadow pass is timed.
    void redrawForMeasurement();
    // shadow.cache=on-demand (or every-n between redraws): draws the moving casters where the
    // views are stale, once.
    void redrawCachedShadows();
    double lastFrameMs() const { return m_lastFrameMs; }

    // Its width over its height, what a model's camera is framed for (16:9 before it has a size).
    double aspect() const { return width() > 0 && height() > 0 ? double(width()) / height() : 16.0 / 9.0; }

    QSize minimumSizeHint() const override { return {0, 0}; }
    QSize sizeHint() const override { return {640, 480}; }

signals:
    void frameRendered();
    void renderFailed(const QString& key, const QString& message);
    void cameraEdited(const shadowlab::CameraSettings& camera);
    // Ctrl+drag: turn the light by these degrees of azimuth and elevation around its target.
    void lightTurned(double azimuthDegrees, double elevationDegrees);
    void activated();   // pressed: the window selects this view's side
    void wipeSideActivated();   // pressed right of the wipe's divider: the other side's pixels

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void cleanup();
    void renderFrame(const Settings& settings);
    void drawWipe();
    void paintWipeDivider();
    bool nearWipeDivider(const QPoint& position) const;

    Settings m_settings;
    std::optional<Settings> m_rendered;
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<LightGizmoPass> m_gizmo;
    bool m_showLightVolume = true;
    QImage m_errorOverlay;
    Loupe* m_loupe = nullptr;
    QImage m_loupeFrame;
    std::optional<CameraSettings> m_frozenCamera;
    std::optional<Settings> m_wipe;
    QImage m_wipeOverlay;
    std::unique_ptr<Renderer> m_wipeRenderer;
    std::unique_ptr<QOpenGLFramebufferObject> m_wipeTarget;
    double m_wipePosition = 0.5;
    bool m_draggingWipe = false;
    QPoint m_lastMouse;
    int m_frameCount = 0;
    double m_lastFrameMs = 0.0;
};

} // namespace shadowlab
