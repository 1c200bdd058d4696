#include "AccuracyDock.h"

#include "AccuracyController.h"
#include "AccuracyMetricsPanel.h"
#include "NoteLabel.h"
#include "SettingsKeys.h"
#include "SweepChartPanel.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>
#include <QScrollArea>
#include <QVBoxLayout>

#include <utility>

namespace shadowlab {

AccuracyDock::AccuracyDock(QWidget* parent) : QDockWidget(tr("Accuracy"), parent), m_controller(new AccuracyController(this))
{
    setObjectName(QStringLiteral("accuracyDock"));

    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    addMeasureRows(layout);
    m_metrics = new AccuracyMetricsPanel;
    layout->addWidget(m_metrics);
    m_chart = new SweepChartPanel;
    layout->addWidget(m_chart, 1);
    addTuningRows(layout);

    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    setWidget(scroll);

    connectController();
    m_metrics->showMeasurement(*m_controller);
    updateButtons();
}

AccuracyDock::~AccuracyDock() = default;

void AccuracyDock::addMeasureRows(QVBoxLayout* layout)
{
    m_compareButton = new QPushButton(tr("Compare with reference"));
    m_compareButton->setObjectName(QStringLiteral("compareButton"));
    m_compareButton->setToolTip(tr("Measure the current view against a ray-traced reference (traced once, then reused "
                                   "while scene, camera, view size and light placement stay the same)"));
    layout->addWidget(m_compareButton);

    auto* progressRow = new QHBoxLayout;
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(m_progress->fontMetrics().height());
    m_cancelButton = new QPushButton(tr("Cancel"));
    m_cancelButton->setObjectName(QStringLiteral("cancelButton"));
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_cancelButton);
    layout->addLayout(progressRow);

    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
}

void AccuracyDock::addTuningRows(QVBoxLayout* layout)
{
    auto* tuneRow = new QHBoxLayout;
    m_tuneButton = new QPushButton(tr("Tune bias"));
    m_tuneButton->setObjectName(QStringLiteral("tuneButton"));
    m_tuneButton->setToolTip(tr("Search bias.slope x bias.min (in the unit of bias.space) for the fewest pixels misclassified against "
                                "the hard reference, over this view and six light directions around the current one"));
    m_applyTuningButton = new QPushButton(tr("Apply tuned bias"));
    m_applyTuningButton->setObjectName(QStringLiteral("applyTuningButton"));
    m_applyTuningButton->setEnabled(false);
    tuneRow->addWidget(m_tuneButton);
    tuneRow->addWidget(m_applyTuningButton);
    layout->addLayout(tuneRow);
    m_tuneOnOpen = new QCheckBox(tr("Tune when a model opens"));
    m_tuneOnOpen->setObjectName(QStringLiteral("tuneOnOpen"));
    m_tuneOnOpen->setToolTip(tr("When a model file opens, tune its bias against the ray-traced reference in the background and set "
                                "the result as one undo step where it is clearly better than the model's defaults"));
    m_tuneOnOpen->setChecked(QSettings().value(QStringLiteral("accuracy/tuneOnOpen"), true).toBool());
    connect(m_tuneOnOpen, &QCheckBox::toggled, this, [](bool on) { QSettings().setValue(QStringLiteral("accuracy/tuneOnOpen"), on); });
    layout->addWidget(m_tuneOnOpen);
    m_tuningChart = new QChartView;
    m_tuningChart->setObjectName(QStringLiteral("tuningChart"));
    m_tuningChart->setRenderHint(QPainter::Antialiasing);
    m_tuningChart->setMinimumHeight(240);
    m_tuningChart->setVisible(false);
    layout->addWidget(m_tuningChart);
    m_tuningResult = noteLabel(QStringLiteral("tuningResult"));
    m_tuningResult->setVisible(false);
    layout->addWidget(m_tuningResult);
}

void AccuracyDock::connectController()
{
    connect(m_compareButton, &QPushButton::clicked, m_controller, &AccuracyController::compare);
    connect(m_chart->sweepButton(), &QPushButton::clicked, m_controller, &AccuracyController::sweep);
    connect(m_cancelButton, &QPushButton::clicked, m_controller, &AccuracyController::cancel);
    connect(m_tuneButton, &QPushButton::clicked, this, [this] {
        m_tuningForOpen = false;
        m_controller->tuneBias();
    });
    // A tuning that ends without a result (cancelled, failed) applies nothing later.
    connect(m_controller, &AccuracyController::busyChanged, this, [this](bool busy) {
        if (!busy && !m_controller->tuning())
            m_tuningForOpen = false;
    });
    connect(m_controller, &AccuracyController::tuningFinished, this, &AccuracyDock::showTuning);
    connect(m_applyTuningButton, &QPushButton::clicked, this, [this] {
        if (m_controller->tuning())
            emit applySettingsRequested(tunedSettings());
    });
    connect(m_metrics, &AccuracyMetricsPanel::overlayToggled, this, &AccuracyDock::updateOverlay);
    connect(m_chart, &SweepChartPanel::applySettingsRequested, this, &AccuracyDock::applySettingsRequested);

    connect(m_controller, &AccuracyController::busyChanged, this, &AccuracyDock::updateButtons);
    connect(m_controller, &AccuracyController::progressChanged, this, [this](int value, int maximum) {
        m_progress->setRange(0, maximum);
        m_progress->setValue(value);
    });
    connect(m_controller, &AccuracyController::statusChanged, this, &AccuracyDock::setStatus);
    connect(m_controller, &AccuracyController::measurementChanged, this, [this] {
        m_metrics->showMeasurement(*m_controller);
        updateOverlay();
    });
    connect(m_controller, &AccuracyController::sweepStarted, m_chart, &SweepChartPanel::startSweep);
    connect(m_controller, &AccuracyController::sweepPointsChanged, this,
            [this] { m_chart->setPoints(m_controller->sweepPoints()); });
}

void AccuracyDock::setSettings(const Settings& settings)
{
    setSides(settings, std::nullopt, 0);
}

void AccuracyDock::setSides(const Settings& a, const std::optional<Settings>& b, int selected)
{
    std::vector<Settings> sides{a};
    if (b)
        sides.push_back(*b);
    const std::size_t chosen = std::size_t(std::clamp(selected, 0, int(sides.size()) - 1));
    if (sides.size() == m_controller->sideCount() && chosen == m_controller->selectedSide()) {
        bool same = true;
        for (std::size_t i = 0; i < sides.size(); ++i)
            same = same && sides[i] == m_controller->sideSettings(i);
        if (same)
            return;
    }
    m_controller->setSides(sides, chosen);
    m_compareButton->setText(sides.size() > 1 ? tr("Compare A and B with reference") : tr("Compare with reference"));
    const QString side = QString(QLatin1Char(char('A' + chosen)));
    m_tuneButton->setText(sides.size() > 1 ? tr("Tune bias of side %1").arg(side) : tr("Tune bias"));
    m_chart->sweepButton()->setText(sides.size() > 1 ? tr("Sweep around side %1").arg(side) : tr("Sweep around current settings"));
    m_metrics->showMeasurement(*m_controller);
    updateOverlay();
    m_chart->setCurrentSettings(m_controller->settings());
}

void AccuracyDock::sceneContentsChanged()
{
    m_controller->withdrawResults();
    m_metrics->showMeasurement(*m_controller);
    updateOverlay();
}

void AccuracyDock::setFrameTimes(const std::vector<FrameTimeHistory::Summary>& sides, bool cpuTime)
{
    m_metrics->showFrameTimes(sides, cpuTime);
}

void AccuracyDock::setViewSize(QSize size)
{
    m_controller->setViewSize(size);
    m_metrics->showMeasurement(*m_controller);
    updateOverlay();
}

QSize AccuracyDock::measureSize() const
{
    return m_controller->measureSize();
}

void AccuracyDock::setAreaSamplesPerAxis(int samples)
{
    m_controller->setAreaSamplesPerAxis(samples);
}

int AccuracyDock::areaSamplesPerAxis() const
{
    return m_controller->areaSamplesPerAxis();
}

bool AccuracyDock::isBusy() const
{
    return m_controller->isBusy();
}

void AccuracyDock::updateOverlay()
{
    for (std::size_t side = 0; side < m_overlays.size(); ++side) {
        const bool have = side < m_controller->sideCount() && m_controller->measurementIsCurrent(side);
        const QImage wanted = !have || !m_metrics->overlayWanted() ? QImage()
                              : m_metrics->heatWanted()          ? m_controller->measurement(side)->heat
                                                                 : m_controller->measurement(side)->errors;
        if (wanted.cacheKey() == m_overlays[side].cacheKey())
            continue;
        m_overlays[side] = wanted;
        emit errorOverlayChanged(int(side), wanted);
    }
}

Settings AccuracyDock::tunedSettings() const
{
    const auto& t = *m_controller->tuning();
    Settings tuned = m_controller->settings();
    tuned.bias.space = t.space;
    tuned.bias.slope = t.candidates[t.best].slope;
    tuned.bias.min = t.candidates[t.best].min;
    return tuned;
}

bool AccuracyDock::tunesOnOpen() const
{
    return m_tuneOnOpen->isChecked();
}

void AccuracyDock::tuneForOpenedModel()
{
    if (!tunesOnOpen() || m_controller->isBusy())
        return;
    m_tuningForOpen = true;
    m_controller->tuneBias();
    if (!m_controller->isBusy())
        m_tuningForOpen = false;    // it could not start
}

void AccuracyDock::showTuning()
{
    const auto& t = m_controller->tuning();
    const bool forOpen = std::exchange(m_tuningForOpen, false);
    m_tuningChart->setVisible(t.has_value());
    m_tuningResult->setVisible(t.has_value());
    // Nothing to apply when the bias as set is already as good as any on the curve.
    m_applyTuningButton->setEnabled(t && t->improves);
    if (!t)
        return;
    // The acne-against-leak trade-off: each point a bias no other beats on both.
    auto* curve = new QLineSeries;
    curve->setName(tr("trade-off"));
    curve->setPointsVisible(true);
    for (const std::size_t i : t->front)
        curve->append(100.0 * t->candidates[i].falseShadow, 100.0 * t->candidates[i].falseLight);
    auto* best = new QScatterSeries;
    best->setName(tr("best"));
    best->append(100.0 * t->candidates[t->best].falseShadow, 100.0 * t->candidates[t->best].falseLight);
    auto* current = new QScatterSeries;
    current->setName(tr("as set"));
    current->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    current->append(100.0 * t->current.falseShadow, 100.0 * t->current.falseLight);
    auto* chart = new QChart;
    for (QAbstractSeries* series : std::initializer_list<QAbstractSeries*>{curve, best, current})
        chart->addSeries(series);
    chart->createDefaultAxes();
    // Shares start at zero: the default axes pad a flat curve into negative percentages.
    double maxShadow = 100.0 * t->current.falseShadow, maxLight = 100.0 * t->current.falseLight;
    for (const std::size_t i : t->front) {
        maxShadow = std::max(maxShadow, 100.0 * t->candidates[i].falseShadow);
        maxLight = std::max(maxLight, 100.0 * t->candidates[i].falseLight);
    }
    chart->axes(Qt::Horizontal).front()->setRange(0.0, std::max(maxShadow * 1.15, 0.001));
    chart->axes(Qt::Vertical).front()->setRange(0.0, std::max(maxLight * 1.15, 0.001));
    // Few, short tick labels: a narrow dock otherwise elides every one to "…".
    for (QAbstractAxis* axis : chart->axes()) {
        if (auto* value = qobject_cast<QValueAxis*>(axis)) {
            value->setTickCount(4);
            value->setLabelFormat(QStringLiteral("%.2g"));
        }
    }
    chart->setMargins(QMargins(4, 4, 4, 4));
    chart->axes(Qt::Horizontal).front()->setTitleText(tr("false shadow % (acne)"));
    chart->axes(Qt::Vertical).front()->setTitleText(tr("false light % (leaks)"));
    chart->legend()->setAlignment(Qt::AlignBottom);
    QChart* old = m_tuningChart->chart();
    m_tuningChart->setChart(chart);
    delete old;
    m_tuningChart->setVisible(true);
    m_applyTuningButton->setEnabled(t->improves);
    // What the curve says, under it, where it stays while the status line moves on.
    const BiasCandidate& knee = t->candidates[t->best];
    const QString kneeText = tr("slope %1, min %2 (%3 units), %4 % misclassified against %5 %")
                             .arg(knee.slope)
                             .arg(knee.min)
                             .arg(toString(t->space))
                             .arg(100.0 * knee.misclassified(), 0, 'f', 3)
                             .arg(100.0 * t->current.misclassified(), 0, 'f', 3);
    m_tuningResult->setText(t->improves ? tr("Best on the curve: %1 as set. Apply tuned bias sets it.").arg(kneeText)
                                        : tr("The bias as set (%1 % misclassified) is already on the knee: no point of the curve is "
                                             "clearly better, so there is nothing to apply.")
                                              .arg(100.0 * t->current.misclassified(), 0, 'f', 3));
    m_tuningResult->setVisible(true);
    if (!forOpen)
        return;
    // Tuned as the model opened: set it (one undo step), and say what and why.
    if (t->improves) {
        m_applyTuningButton->setEnabled(false);
        m_tuningResult->setText(tr("Tuned as the model opened: %1 at the model's defaults, over this view and %2 light directions around "
                                   "it, against the ray-traced reference. Edit → Undo brings the defaults back.")
                                    .arg(kneeText)
                                    .arg(int(t->placements.size()) - 1));
        emit tunedBiasRequested(tunedSettings());
    } else {
        m_tuningResult->setText(tr("Tuned as the model opened: its defaults (%1 % misclassified) are already on the knee of the "
                                   "curve against the ray-traced reference, so they stay.")
                                    .arg(100.0 * t->current.misclassified(), 0, 'f', 3));
    }
}

void AccuracyDock::updateButtons()
{
    const bool busy = m_controller->isBusy();
    m_tuneButton->setEnabled(!busy);
    m_compareButton->setEnabled(!busy);
    m_chart->sweepButton()->setEnabled(!busy);
    m_cancelButton->setEnabled(busy);
    m_progress->setVisible(busy);
    m_cancelButton->setVisible(busy);
}

void AccuracyDock::setStatus(const QString& text, bool error)
{
    m_status->setText(text);
    m_status->setVisible(!text.isEmpty());
    QPalette palette = this->palette();
    if (error)
        palette.setColor(QPalette::WindowText, QColor(190, 30, 30));
    m_status->setPalette(palette);
}

} // namespace shadowlab
