#pragma once

#include "AccuracyController.h"

#include <QGroupBox>

#include <vector>

class QChart;
class QLabel;
class QLogValueAxis;
class QPushButton;
class QScatterSeries;
class QValueAxis;

namespace shadowlab {

// The sweep's chart: error against frame time, one point per variation of the current
// settings, the current settings marked; hovering tells what changed, a click asks to apply it.
class SweepChartPanel : public QGroupBox {
    Q_OBJECT

public:
    explicit SweepChartPanel(QWidget* parent = nullptr);

    QPushButton* sweepButton() const { return m_sweepButton; }
    // A sweep at `size` begins: the time axis says at what size.
    void startSweep(QSize size);
    void setPoints(const std::vector<AccuracyController::SweepPoint>& points);
    // Marks the point whose settings these are, if any.
    void setCurrentSettings(const Settings& settings);

signals:
    void applySettingsRequested(const shadowlab::Settings& settings);

private:
    // The chart with its two series (the variations, the current settings) and its axes.
    void createChart();
    void createAxes(const QFont& small);
    // Where a point sits on the chart: on the log axis, no error sits on its floor.
    QPointF plotted(const AccuracyController::SweepPoint& point) const;
    // The sweep point plotted nearest to `point` (chart coordinates), -1 when there are none.
    int sweepPointAt(const QPointF& point) const;
    void pointClicked(const QPointF& point);
    void pointHovered(const QPointF& point, bool state);
    void updateCurrentMarker();

    std::vector<AccuracyController::SweepPoint> m_points;
    Settings m_current;
    QPushButton* m_sweepButton = nullptr;
    QChart* m_chart = nullptr;
    QScatterSeries* m_variations = nullptr;
    QScatterSeries* m_currentMarker = nullptr;
    QScatterSeries* m_wrong = nullptr;      // rings over the variations whose picture is visibly wrong
    QValueAxis* m_timeAxis = nullptr;
    QLogValueAxis* m_errorAxis = nullptr;
    QLabel* m_pointInfo = nullptr;
};

} // namespace shadowlab
