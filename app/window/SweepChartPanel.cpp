#include "SweepChartPanel.h"

#include "NoteLabel.h"
#include "SettingsSummary.h"

#include <QChart>
#include <QChartView>
#include <QCursor>
#include <QGraphicsLayout>
#include <QLabel>
#include <QLogValueAxis>
#include <QPushButton>
#include <QScatterSeries>
#include <QToolTip>
#include <QValueAxis>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

const QColor kVariationColor(52, 120, 190);
const QColor kCurrentColor(235, 120, 30);

} // namespace

SweepChartPanel::SweepChartPanel(QWidget* parent) : QGroupBox(parent)
{
    setTitle(tr("Error against frame time"));
    setObjectName(QStringLiteral("sweepGroup"));
    auto* layout = new QVBoxLayout(this);

    m_sweepButton = new QPushButton(tr("Sweep around current settings"));
    m_sweepButton->setObjectName(QStringLiteral("sweepButton"));
    m_sweepButton->setToolTip(tr("Measure error and frame time for each filter and its variations (PCF 1×1 to 7×7), half and double the map, "
                                 "bias halved, doubled and off, and front-face culling toggled"));
    layout->addWidget(m_sweepButton);

    createChart();

    auto* view = new QChartView(m_chart);
    view->setObjectName(QStringLiteral("sweepChart"));
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(240);
    view->setToolTip(tr("Misclassified pixels against the hard-shadow reference, and the median wall time of %1 "
                        "frames with the shadow map redrawn in each, at the measured size")
                         .arg(AccuracyController::kTimedFrames));
    view->setFrameShape(QFrame::NoFrame);
    view->setBackgroundBrush(Qt::NoBrush);
    // Scoped to the view: a bare "background: transparent" also reaches the tooltips shown
    // for it, which then draw as black bars where windows cannot be translucent.
    view->setStyleSheet(QStringLiteral("QChartView { background: transparent; }"));
    layout->addWidget(view, 1);

    m_pointInfo = noteLabel(QStringLiteral("pointInfo"));
    m_pointInfo->setText(tr("Each point is one change to the current settings. Hover for what changed; click to apply it."));
    layout->addWidget(m_pointInfo);
    connect(m_variations, &QScatterSeries::clicked, this, &SweepChartPanel::pointClicked);
    connect(m_currentMarker, &QScatterSeries::clicked, this, &SweepChartPanel::pointClicked);
    connect(m_variations, &QScatterSeries::hovered, this, &SweepChartPanel::pointHovered);
    connect(m_currentMarker, &QScatterSeries::hovered, this, &SweepChartPanel::pointHovered);
    connect(m_wrong, &QScatterSeries::clicked, this, &SweepChartPanel::pointClicked);
    connect(m_wrong, &QScatterSeries::hovered, this, &SweepChartPanel::pointHovered);
}

void SweepChartPanel::createChart()
{
    m_chart = new QChart;
    m_chart->setBackgroundVisible(false);
    m_chart->setPlotAreaBackgroundBrush(palette().base());
    m_chart->setPlotAreaBackgroundVisible(true);
    m_chart->setMargins(QMargins(0, 0, 0, 0));
    m_chart->layout()->setContentsMargins(0, 0, 0, 0);
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    m_chart->legend()->setFont(small);
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->legend()->setLabelColor(palette().text().color());

    m_variations = new QScatterSeries;
    m_variations->setName(tr("Variations"));
    m_variations->setMarkerSize(9.0);
    m_variations->setColor(kVariationColor);
    m_variations->setBorderColor(kVariationColor.darker(130));
    m_currentMarker = new QScatterSeries;
    m_currentMarker->setName(tr("Current settings"));
    m_currentMarker->setMarkerShape(QScatterSeries::MarkerShapeRotatedRectangle);
    m_currentMarker->setMarkerSize(15.0);
    m_currentMarker->setColor(kCurrentColor);
    m_currentMarker->setBorderColor(kCurrentColor.darker(140));
    // Rings over the points whose picture is visibly wrong: the count may look fine, the frame
    // does not (DSSIM over ReportAnalysis' kVisibleDssim).
    m_wrong = new QScatterSeries;
    m_wrong->setName(tr("Visibly wrong picture"));
    m_wrong->setMarkerSize(15.0);
    m_wrong->setColor(Qt::transparent);
    m_wrong->setBorderColor(QColor(200, 40, 40));
    m_wrong->setPen(QPen(QColor(200, 40, 40), 2.0));
    m_chart->addSeries(m_variations);
    m_chart->addSeries(m_currentMarker);
    m_chart->addSeries(m_wrong);
    createAxes(small);
}

void SweepChartPanel::createAxes(const QFont& small)
{
    m_timeAxis = new QValueAxis;
    m_timeAxis->setTitleText(tr("Frame time (ms)"));
    m_timeAxis->setLabelFormat(QStringLiteral("%.0f"));
    m_timeAxis->setTickCount(5);
    m_timeAxis->setRange(0.0, 40.0);
    // Log scale: a configuration with acne sits decades above the good ones, which a linear
    // axis would flatten onto zero.
    m_errorAxis = new QLogValueAxis;
    m_errorAxis->setTitleText(tr("Misclassified (%, log)"));
    m_errorAxis->setLabelFormat(QStringLiteral("%g"));
    m_errorAxis->setBase(10.0);
    m_errorAxis->setRange(0.01, 1.0);
    for (QAbstractAxis* axis : std::initializer_list<QAbstractAxis*>{m_timeAxis, m_errorAxis}) {
        axis->setLabelsFont(small);
        axis->setTitleFont(small);
        axis->setLabelsColor(palette().text().color());
        axis->setTitleBrush(palette().text());
    }
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_chart->addAxis(m_errorAxis, Qt::AlignLeft);
    for (QScatterSeries* series : {m_variations, m_currentMarker, m_wrong}) {
        series->attachAxis(m_timeAxis);
        series->attachAxis(m_errorAxis);
    }
}

void SweepChartPanel::startSweep(QSize size)
{
    m_timeAxis->setTitleText(tr("Frame time at %1×%2 (ms)").arg(size.width()).arg(size.height()));
}

void SweepChartPanel::setCurrentSettings(const Settings& settings)
{
    m_current = settings;
    updateCurrentMarker();
}

void SweepChartPanel::setPoints(const std::vector<AccuracyController::SweepPoint>& sweepPoints)
{
    m_points = sweepPoints;
    double maxTime = 0.0, minError = std::numeric_limits<double>::infinity(), maxError = 0.0;
    for (const AccuracyController::SweepPoint& p : m_points) {
        maxTime = std::max(maxTime, p.frameMs);
        if (p.misclassifiedPercent > 0.0) {
            minError = std::min(minError, p.misclassifiedPercent);
            maxError = std::max(maxError, p.misclassifiedPercent);
        }
    }
    // Time from zero, so the eye reads ratios of cost; error in whole decades.
    m_timeAxis->setRange(0.0, std::max(1.0, maxTime * 1.1));
    m_timeAxis->applyNiceNumbers();
    const double low = maxError > 0.0 ? std::pow(10.0, std::floor(std::log10(std::max(minError, 1e-4)))) : 0.01;
    const double high = maxError > 0.0 ? std::pow(10.0, std::ceil(std::log10(maxError))) : 1.0;
    // A hair below the decade, or rounding in pow() drops the lowest label.
    m_errorAxis->setRange(low * (1.0 - 1e-9), std::max(high, low * 10.0));

    QList<QPointF> points, wrong;
    for (const AccuracyController::SweepPoint& p : m_points) {
        points << plotted(p);
        if (!p.visiblyWrong.isEmpty())
            wrong << plotted(p);
    }
    m_variations->replace(points);
    m_wrong->replace(wrong);
    updateCurrentMarker();
}

QPointF SweepChartPanel::plotted(const AccuracyController::SweepPoint& point) const
{
    return {point.frameMs, std::max(point.misclassifiedPercent, m_errorAxis->min())};
}

int SweepChartPanel::sweepPointAt(const QPointF& point) const
{
    const QPointF target = m_chart->mapToPosition(point, m_variations);
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        const double d = QLineF(m_chart->mapToPosition(plotted(m_points[i]), m_variations), target).length();
        if (d < bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

void SweepChartPanel::pointClicked(const QPointF& point)
{
    const int index = sweepPointAt(point);
    if (index < 0 || m_points[std::size_t(index)].settings == m_current)
        return;
    emit applySettingsRequested(m_points[std::size_t(index)].settings);
}

void SweepChartPanel::pointHovered(const QPointF& point, bool state)
{
    const int index = state ? sweepPointAt(point) : -1;
    if (index < 0) {
        QToolTip::hideText();
        return;
    }
    const AccuracyController::SweepPoint& p = m_points[std::size_t(index)];
    const QString wrong = p.visiblyWrong.isEmpty() ? QString() : tr("Its picture is %1.").arg(p.visiblyWrong);
    const QString text = tr("<b>%1</b><br>%2 ms · %3 % misclassified<br>%4<small>%5</small>")
                             .arg(p.label.toHtmlEscaped())
                             .arg(p.frameMs, 0, 'f', 1)
                             .arg(p.misclassifiedPercent, 0, 'f', 2)
                             .arg(wrong.isEmpty() ? QString() : wrong.toHtmlEscaped() + QStringLiteral("<br>"))
                             .arg(settingsSummary(p.settings).toHtmlEscaped());
    QToolTip::showText(QCursor::pos(), text, this);
    m_pointInfo->setText(tr("%1: %2 ms, %3 % misclassified. %4Click to apply.")
                             .arg(p.label)
                             .arg(p.frameMs, 0, 'f', 1)
                             .arg(p.misclassifiedPercent, 0, 'f', 2)
                             .arg(wrong.isEmpty() ? QString() : wrong + QLatin1Char(' ')));
}

void SweepChartPanel::updateCurrentMarker()
{
    m_currentMarker->clear();
    for (const AccuracyController::SweepPoint& p : m_points) {
        if (p.settings == m_current) {
            m_currentMarker->append(plotted(p));
            return;
        }
    }
}

} // namespace shadowlab
