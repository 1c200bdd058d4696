#pragma once

#include "DepthViewPass.h"
#include "GlObject.h"

#include <glm/mat4x4.hpp>

#include <QIcon>
#include <QOpenGLWidget>
#include <QPointF>
#include <QPointer>
#include <QRectF>

#include <array>
#include <memory>
#include <optional>

namespace shadowlab {

class SceneView;

// The light's shadow map in its own QOpenGLWidget. Its context shares textures with the scene
// views' (Qt::AA_ShareOpenGLContexts), so it samples the source view's map directly, with its
// own DepthViewPass, and draws it as DepthMapPicture lays it out: a colour ramp stretched to
// the depths the map holds, at the light volume's aspect, with the volume's and the camera's
// outlines and a legend. The map is fitted to the pane; wheel zooms around the cursor, drag
// pans, double-click or Home fits again, F frames the camera's footprint with it. Hovering
// reports the texel under the cursor.
class DepthMapView : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit DepthMapView(QWidget* parent = nullptr);
    ~DepthMapView() override;

    // The scene view whose shadow map is shown; redrawn whenever that map is re-rendered.
    void setSource(SceneView* source);
    SceneView* source() const { return m_source; }

    // Fits the whole map to the pane (Home, 0, double-click), the default.
    void resetZoom();
    // Frames the map together with what the camera sees of the scene (F).
    void frameFootprint();
    // The icons of the pane's two framing buttons: the map's square filling the frame
    // (resetZoom()), or the small square inside the camera's orange footprint (frameFootprint()).
    static QIcon framingIcon(bool withFootprint);
    double zoom() const { return m_zoom; }
    // The part of the map shown, in map coordinates ([0, 1]^2 is the whole map, y up).
    QRectF visibleRect() const;
    int frameCount() const { return m_frameCount; }
    // The depths the colour ramp is stretched over, as the legend says (nullopt: none drawn).
    std::optional<DepthSpan> shownSpan() const;

    QSize minimumSizeHint() const override { return {0, 0}; }
    QSize sizeHint() const override { return {400, 400}; }

signals:
    void frameRendered();
    // "texel 1021, 388 · depth 0.73104 · 5.46 from the light", or empty when off the map.
    void texelHovered(const QString& text);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void cleanup();
    void onSourceFrame();
    bool hasMap() const;
    QPointF mapPoint(QPointF widgetPosition) const;
    void reportTexel(QPointF widgetPosition);
    std::optional<float> readDepth(int x, int y);
    // The four stored moments of a moments map's texel (moment techniques).
    std::optional<std::array<float, 4>> readMoments(int x, int y);
    // Whether the source's last frame used a moment technique (the view then shows its moments).
    bool showsMoments() const;

    QPointer<SceneView> m_source;
    QMetaObject::Connection m_sourceConnection;
    GlFunctions* m_gl = nullptr;
    std::unique_ptr<DepthViewPass> m_pass;
    GlFramebuffer m_readFramebuffer;     // the shared map attached, for reading one texel
    int m_seenMapGeneration = -1;
    std::optional<glm::dmat4> m_seenCamera;
    int m_spanMapGeneration = -1;        // the map generation m_span was measured at
    std::optional<DepthSpan> m_span;
    bool m_seenShadowsEnabled = false;
    int m_seenMomentView = 0;       // filter.mode * 8 + moments.view of the last frame shown
    // Until the user zooms or pans, the pane keeps framing the map (or the map with the camera's
    // footprint) as both change; then it stays where it was put.
    enum class Framing { Map, Footprint, Free };
    Framing m_framing = Framing::Map;
    // The region the framing holds in view, for the current map and camera.
    QRectF framedRegion() const;
    double m_zoom = 1.0;                 // 1: the whole map fits the pane
    QPointF m_center{0.5, 0.5};          // map coordinates at the pane's centre
    // Leaves the home framing for a fixed one at the same place, before a zoom or pan.
    void leaveHome();
    QPointF m_lastMouse;
    std::optional<QPointF> m_pointer;    // the map point under the pointer, while it is over the pane
    int m_frameCount = 0;
};

} // namespace shadowlab
