#include "AccuracyDock.h"

#include "HeadlessRenderer.h"
#include "RayTracer.h"
#include "SampleStats.h"
#include "SettingsKeys.h"
#include "SettingsSummary.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QCursor>
#include <QGraphicsLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QScrollArea>
#include <QStyle>
#include <QTimer>
#include <QToolTip>
#include <QValueAxis>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

constexpr int kProgressSteps = 1000;
constexpr int kTimedFrames = 5;

const QColor kVariationColor(52, 120, 190);
const QColor kCurrentColor(235, 120, 30);

// One configuration of a sweep before it is measured.
struct Variation {
    QString label;
    Settings settings;
};

QString filterLabel(const FilterSettings& filter)
{
    if (filter.mode == FilterMode::Pcf)
        return QStringLiteral("pcf %1×%1").arg(filter.kernel);
    return toString(filter.mode);
}

// The current settings first, then one change at a time: each filter, PCF 3 and 5, half and
// double the map, bias halved, doubled and off, front-face culling toggled. Changes that make
// the settings invalid or repeat an earlier configuration are left out.
std::vector<Variation> sweepAround(const Settings& base, int maxTextureSize)
{
    std::vector<Variation> out{{QStringLiteral("current settings"), base}};
    auto add = [&](const QString& label, Settings s) {
        const std::vector<SettingsIssue> issues = validate(s);  // errors come first
        if (s.map.size > maxTextureSize || (!issues.empty() && issues.front().severity == SettingsIssue::Severity::Error))
            return;
        if (std::any_of(out.begin(), out.end(), [&](const Variation& v) { return v.settings == s; }))
            return;
        out.push_back({label, s});
    };
    for (FilterMode mode : {FilterMode::Hard, FilterMode::Pcf, FilterMode::PcfDither4, FilterMode::Pcf64, FilterMode::HwBilinear}) {
        Settings s = base;
        s.filter.mode = mode;
        add(filterLabel(s.filter), s);
    }
    for (int kernel : {3, 5}) {
        Settings s = base;
        s.filter = {FilterMode::Pcf, kernel};
        add(filterLabel(s.filter), s);
    }
    for (int size : {base.map.size / 2, base.map.size * 2}) {
        Settings s = base;
        s.map.size = size;
        add(QStringLiteral("map %1").arg(squareSize(size)), s);
    }
    for (double factor : {0.5, 2.0, 0.0}) {
        Settings s = base;
        s.bias.slope *= factor;
        s.bias.min *= factor;
        add(factor == 0.0 ? QStringLiteral("no bias") : QStringLiteral("bias ×%1").arg(factor), s);
    }
    Settings culled = base;
    culled.bias.cullFront = !base.bias.cullFront;
    add(culled.bias.cullFront ? QStringLiteral("front-face culling") : QStringLiteral("no front-face culling"), culled);
    return out;
}

// Which pixels count (receivers facing the light) and the shadow term the rasteriser gave them.
void measuredVisibility(const VisibilityBuffer& buffer, std::vector<float>& measured, std::vector<bool>& counts)
{
    counts.assign(std::size_t(buffer.pixelCount()), false);
    measured.assign(counts.size(), 0.0f);
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        counts[std::size_t(i)] = buffer.mask(i) == VisibilityBuffer::FacingLight;
        measured[std::size_t(i)] = buffer.visibility(i);
    }
}

QString percentText(double share)
{
    const double percent = share * 100.0;
    return QStringLiteral("%1 %").arg(percent, 0, 'f', percent != 0.0 && percent < 0.1 ? 3 : 2);
}

QString errorText(double value)
{
    return QString::number(value, 'f', 4);
}

QString raysText(double raysPerSecond)
{
    return raysPerSecond >= 1e6 ? QStringLiteral("%1 M rays/s").arg(raysPerSecond * 1e-6, 0, 'f', 1)
                                : QStringLiteral("%1 k rays/s").arg(raysPerSecond * 1e-3, 0, 'f', 0);
}

QLabel* valueLabel(const QString& objectName)
{
    auto* label = new QLabel(QStringLiteral("—"));
    label->setObjectName(objectName);
    label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

// A name and its value on one grid row; both carry the tooltip so either can be hovered.
void addMetricRow(QGridLayout* grid, const QString& name, QLabel* value, const QString& toolTip)
{
    auto* nameLabel = new QLabel(name);
    nameLabel->setToolTip(toolTip);
    value->setToolTip(toolTip);
    const int row = grid->rowCount();
    grid->addWidget(nameLabel, row, 0);
    grid->addWidget(value, row, 1);
}

QLabel* noteLabel(const QString& objectName)
{
    auto* label = new QLabel;
    label->setObjectName(objectName);
    label->setWordWrap(true);
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    label->setFont(font);
    label->setForegroundRole(QPalette::PlaceholderText);
    return label;
}

} // namespace

AccuracyDock::AccuracyDock(QWidget* parent) : QDockWidget(tr("Accuracy"), parent)
{
    setObjectName(QStringLiteral("accuracyDock"));
    // One trace at a time, on a thread of its own: traceReference() fans its rows out over the
    // global pool and only polls from here, so it must not occupy one of that pool's threads.
    m_tracePool.setMaxThreadCount(1);

    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);

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

    layout->addWidget(buildMetricsPanel());
    layout->addWidget(buildChartPanel(), 1);

    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    setWidget(scroll);

    connect(m_compareButton, &QPushButton::clicked, this, &AccuracyDock::compare);
    connect(m_sweepButton, &QPushButton::clicked, this, &AccuracyDock::sweep);
    connect(m_cancelButton, &QPushButton::clicked, this, &AccuracyDock::cancel);
    connect(m_overlayCheck, &QCheckBox::toggled, this, &AccuracyDock::updateOverlay);
    connect(&m_traceWatcher, &QFutureWatcherBase::progressValueChanged, m_progress, &QProgressBar::setValue);
    connect(&m_traceWatcher, &QFutureWatcherBase::finished, this, &AccuracyDock::traceFinished);
    connect(m_variations, &QScatterSeries::clicked, this, &AccuracyDock::pointClicked);
    connect(m_current, &QScatterSeries::clicked, this, &AccuracyDock::pointClicked);
    connect(m_variations, &QScatterSeries::hovered, this, &AccuracyDock::pointHovered);
    connect(m_current, &QScatterSeries::hovered, this, &AccuracyDock::pointHovered);

    showMetrics();
    updateButtons();
}

AccuracyDock::~AccuracyDock()
{
    if (m_pending)
        m_pending->cancel->store(true);
    m_traceWatcher.waitForFinished();
}

QWidget* AccuracyDock::buildMetricsPanel()
{
    auto* panel = new QWidget;
    auto* layout = new QVBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);

    auto* hard = new QGroupBox(tr("Hard-shadow reference"));
    hard->setObjectName(QStringLiteral("hardGroup"));
    auto* hardGrid = new QGridLayout(hard);
    hardGrid->setColumnStretch(0, 1);
    m_misclassified = valueLabel(QStringLiteral("misclassifiedValue"));
    m_falseShadow = valueLabel(QStringLiteral("falseShadowValue"));
    m_falseLight = valueLabel(QStringLiteral("falseLightValue"));
    m_hardMae = valueLabel(QStringLiteral("hardMaeValue"));
    m_hardRmse = valueLabel(QStringLiteral("hardRmseValue"));
    addMetricRow(hardGrid, tr("Misclassified"), m_misclassified,
                 tr("Share of lit-facing pixels on the wrong side of half visibility compared with one shadow ray per "
                    "pixel: false shadow plus false light."));
    addMetricRow(hardGrid, tr("False shadow (acne)"), m_falseShadow,
                 tr("Dark where the reference is lit: shadow acne from too little bias, over-darkened edges. "
                    "Magenta on the scene view."));
    addMetricRow(hardGrid, tr("False light (leaks)"), m_falseLight,
                 tr("Lit where the reference is dark: peter panning from too much bias, light leaking through thin "
                    "casters. Cyan on the scene view."));
    addMetricRow(hardGrid, tr("MAE"), m_hardMae,
                 tr("Mean absolute difference of visibility (0 shadowed … 1 lit); soft edges count in part."));
    addMetricRow(hardGrid, tr("RMSE"), m_hardRmse,
                 tr("Root mean square difference of visibility; weighs whole wrong pixels more than MAE does."));
    layout->addWidget(hard);

    auto* area = new QGroupBox(tr("Area-light reference"));
    area->setObjectName(QStringLiteral("areaGroup"));
    area->setToolTip(tr("A disk light of radius reference.light_radius, sampled with stratified rays: how close a "
                        "filtered edge comes to a real penumbra."));
    auto* areaGrid = new QGridLayout(area);
    areaGrid->setColumnStretch(0, 1);
    m_areaMae = valueLabel(QStringLiteral("areaMaeValue"));
    m_areaRmse = valueLabel(QStringLiteral("areaRmseValue"));
    m_noiseFloor = valueLabel(QStringLiteral("noiseFloorValue"));
    addMetricRow(areaGrid, tr("MAE"), m_areaMae, tr("Mean absolute difference from the area light's visibility."));
    addMetricRow(areaGrid, tr("RMSE"), m_areaRmse, tr("Root mean square difference from the area light's visibility."));
    addMetricRow(areaGrid, tr("Noise floor"), m_noiseFloor,
                 tr("Mean standard error of the area reference itself: differences this small are sampling noise, "
                    "not error. More samples per pixel lower it."));
    layout->addWidget(area);

    m_referenceInfo = noteLabel(QStringLiteral("referenceInfo"));
    m_referenceInfo->setToolTip(tr("Speed of the Embree ray tracer here. The reference depends on scene, camera, view "
                                   "size and light placement only, so map, bias and filter changes reuse it."));
    layout->addWidget(m_referenceInfo);

    auto* overlayRow = new QHBoxLayout;
    m_overlayCheck = new QCheckBox(tr("Show errors on the scene view"));
    m_overlayCheck->setObjectName(QStringLiteral("overlayCheck"));
    m_overlayCheck->setChecked(true);
    m_overlayCheck->setToolTip(tr("Grey the scene view and paint false shadow magenta and false light cyan "
                                  "(against the hard-shadow reference)"));
    overlayRow->addWidget(m_overlayCheck);
    overlayRow->addStretch(1);
    layout->addLayout(overlayRow);
    // The colours of errorImage().
    auto* legend = noteLabel(QStringLiteral("overlayLegend"));
    legend->setText(tr("<span style='color:%1'>■</span> false shadow &nbsp; <span style='color:%2'>■</span> false light")
                        .arg(QColor(235, 40, 200).name(), QColor(40, 220, 235).name()));
    legend->setContentsMargins(m_overlayCheck->style()->pixelMetric(QStyle::PM_IndicatorWidth) + 6, 0, 0, 0);
    layout->addWidget(legend);
    return panel;
}

QWidget* AccuracyDock::buildChartPanel()
{
    auto* group = new QGroupBox(tr("Error against frame time"));
    group->setObjectName(QStringLiteral("sweepGroup"));
    auto* layout = new QVBoxLayout(group);

    m_sweepButton = new QPushButton(tr("Sweep around current settings"));
    m_sweepButton->setObjectName(QStringLiteral("sweepButton"));
    m_sweepButton->setToolTip(tr("Measure error and frame time for each filter, PCF 3 and 5, half and double the map, "
                                 "bias halved, doubled and off, and front-face culling toggled"));
    layout->addWidget(m_sweepButton);

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
    m_current = new QScatterSeries;
    m_current->setName(tr("Current settings"));
    m_current->setMarkerShape(QScatterSeries::MarkerShapeRotatedRectangle);
    m_current->setMarkerSize(15.0);
    m_current->setColor(kCurrentColor);
    m_current->setBorderColor(kCurrentColor.darker(140));
    m_chart->addSeries(m_variations);
    m_chart->addSeries(m_current);

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
    for (QScatterSeries* series : {m_variations, m_current}) {
        series->attachAxis(m_timeAxis);
        series->attachAxis(m_errorAxis);
    }

    auto* view = new QChartView(m_chart);
    view->setObjectName(QStringLiteral("sweepChart"));
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(240);
    view->setToolTip(tr("Misclassified pixels against the hard-shadow reference, and the median wall time of %1 "
                        "frames with the shadow map redrawn in each, at the measured size")
                         .arg(kTimedFrames));
    view->setFrameShape(QFrame::NoFrame);
    view->setBackgroundBrush(Qt::NoBrush);
    view->setStyleSheet(QStringLiteral("background: transparent"));
    layout->addWidget(view, 1);

    m_pointInfo = noteLabel(QStringLiteral("pointInfo"));
    m_pointInfo->setText(tr("Each point is one change to the current settings. Hover for what changed; click to apply it."));
    layout->addWidget(m_pointInfo);
    return group;
}

void AccuracyDock::setSettings(const Settings& settings)
{
    if (settings == m_settings)
        return;
    m_settings = settings;
    showMetrics();
    updateOverlay();
    updateCurrentMarker();
}

void AccuracyDock::setViewSize(QSize size)
{
    if (size == m_viewSize)
        return;
    m_viewSize = size;
    showMetrics();
    updateOverlay();
}

QSize AccuracyDock::measureSize() const
{
    if (m_viewSize.isEmpty())
        return {};
    const double scale = std::min(1.0, double(kMaxMeasureSide) / std::max(m_viewSize.width(), m_viewSize.height()));
    return {std::max(1, int(std::lround(m_viewSize.width() * scale))), std::max(1, int(std::lround(m_viewSize.height() * scale)))};
}

void AccuracyDock::setAreaSamplesPerAxis(int samples)
{
    m_areaSamplesPerAxis = std::clamp(samples, 1, 64);
}

bool AccuracyDock::isBusy() const
{
    return m_pending.has_value() || m_sweeping;
}

HeadlessRenderer& AccuracyDock::headless()
{
    if (!m_headless)
        m_headless = std::make_unique<HeadlessRenderer>();
    m_headless->makeCurrent();
    return *m_headless;
}

void AccuracyDock::compare()
{
    startMeasurement(false);
}

void AccuracyDock::sweep()
{
    startMeasurement(true);
}

void AccuracyDock::cancel()
{
    if (m_pending)
        m_pending->cancel->store(true);
    m_sweepCancelled = m_sweeping;
    setStatus(tr("Cancelling…"));
}

void AccuracyDock::startMeasurement(bool thenSweep)
{
    if (isBusy())
        return;
    const QSize size = measureSize();
    if (size.isEmpty()) {
        setStatus(tr("Nothing to measure: the scene view has no size yet."), true);
        return;
    }
    try {
        ensureValid(m_settings);
        Renderer& renderer = headless().renderer();
        auto buffer = std::make_shared<const VisibilityBuffer>(renderer.renderVisibility(m_settings, size));
        const ReferenceKey key = referenceKeyFor(m_settings, measureSize(), m_areaSamplesPerAxis);
        if (m_referenceKey == key) {
            m_lastReferenceReused = true;
            measure(m_settings, *buffer);
            if (thenSweep)
                startSweep();
            return;
        }

        // The worker gets copies: the renderer may load another scene while it traces.
        auto scene = std::make_shared<const Scene>(*renderer.scene());
        const LightFrame light = renderer.lightFrame();
        const ReferenceOptions options{true, m_settings.reference.lightRadius, m_areaSamplesPerAxis};
        auto cancelFlag = std::make_shared<std::atomic<bool>>(false);
        m_pending = PendingTrace{key, m_settings, buffer, cancelFlag, thenSweep};
        m_progress->setRange(0, kProgressSteps);
        m_progress->setValue(0);
        setStatus(tr("Tracing the reference at %1×%2…").arg(size.width()).arg(size.height()));
        m_traceWatcher.setFuture(QtConcurrent::run(&m_tracePool, [scene, buffer, light, options, cancelFlag](QPromise<TraceOutcome>& promise) {
            promise.setProgressRange(0, kProgressSteps);
            TraceOutcome outcome;
            try {
                const RayTracer tracer(*scene, buffer->cameraPosition);
                outcome.reference = traceReference(tracer, *buffer, light, options,
                                                   [&promise](double f) { promise.setProgressValue(int(f * kProgressSteps)); },
                                                   cancelFlag.get());
            } catch (const std::exception& e) {
                outcome.error = QString::fromUtf8(e.what());
            }
            promise.addResult(std::move(outcome));
        }));
    } catch (const std::exception& e) {
        setStatus(QString::fromUtf8(e.what()), true);
    }
    updateButtons();
}

void AccuracyDock::traceFinished()
{
    const PendingTrace pending = std::move(*m_pending);
    m_pending.reset();
    TraceOutcome outcome = m_traceWatcher.result();
    updateButtons();
    if (!outcome.error.isEmpty()) {
        setStatus(tr("The reference could not be traced: %1").arg(outcome.error), true);
        return;
    }
    if (outcome.reference.cancelled || pending.cancel->load()) {
        setStatus(tr("Cancelled; the partial reference was discarded."));
        return;
    }
    m_reference = std::move(outcome.reference);
    m_referenceKey = pending.key;
    m_lastRaysPerSecond = m_reference.raysPerSecond();
    m_lastReferenceReused = false;
    try {
        measure(pending.settings, *pending.buffer);
        if (pending.thenSweep)
            startSweep();
    } catch (const std::exception& e) {
        setStatus(QString::fromUtf8(e.what()), true);
    }
}

void AccuracyDock::measure(const Settings& settings, const VisibilityBuffer& buffer)
{
    std::vector<float> measured;
    std::vector<bool> counts;
    measuredVisibility(buffer, measured, counts);
    Measurement m;
    m.settings = settings;
    m.hard = compareVisibility(measured, m_reference.hard, counts);
    if (!m_reference.area.empty())
        m.area = compareVisibility(measured, m_reference.area, counts);
    m.areaNoiseFloor = m_reference.areaNoiseFloor;
    m.errors = errorImage(buffer.image, measured, m_reference.hard, counts);
    m_measurement = std::move(m);
    setStatus(m_measurement->hard.pixels == 0 ? tr("No surface in view faces the light; nothing to compare.") : QString());
    showMetrics();
    updateOverlay();
}

void AccuracyDock::startSweep()
{
    const int maxTextureSize = headless().renderer().maxTextureSize();
    m_sweepPlan.clear();
    for (Variation& v : sweepAround(m_settings, maxTextureSize))
        m_sweepPlan.push_back({v.label, std::move(v.settings), 0.0, 0.0});
    m_sweepPoints.clear();
    m_sweepSkipped.clear();
    m_variations->clear();
    m_current->clear();
    m_sweepNext = 0;
    m_sweepSize = measureSize();
    m_sweeping = true;
    m_sweepCancelled = false;
    m_timeAxis->setTitleText(tr("Frame time at %1×%2 (ms)").arg(m_sweepSize.width()).arg(m_sweepSize.height()));
    m_progress->setRange(0, int(m_sweepPlan.size()));
    m_progress->setValue(0);
    updateButtons();
    QTimer::singleShot(0, this, &AccuracyDock::sweepStep);
}

void AccuracyDock::sweepStep()
{
    if (m_sweepCancelled) {
        finishSweep(tr("Sweep cancelled after %1 of %2 configurations.").arg(m_sweepPoints.size()).arg(m_sweepPlan.size()));
        return;
    }
    if (m_sweepNext >= m_sweepPlan.size()) {
        finishSweep(m_sweepSkipped.isEmpty() ? QString() : tr("Left out: %1").arg(m_sweepSkipped.join(QStringLiteral("; "))));
        return;
    }
    SweepPoint point = m_sweepPlan[m_sweepNext++];
    setStatus(tr("Sweep %1/%2: %3").arg(m_sweepNext).arg(m_sweepPlan.size()).arg(point.label));
    try {
        HeadlessRenderer& h = headless();
        const VisibilityBuffer buffer = h.renderer().renderVisibility(point.settings, m_sweepSize);
        std::vector<float> measured;
        std::vector<bool> counts;
        measuredVisibility(buffer, measured, counts);
        point.misclassifiedPercent = 100.0 * compareVisibility(measured, m_reference.hard, counts).misclassified;

        // One untimed frame compiles the lit variant; then every frame redraws the shadow map,
        // so the time is what a moving light costs, not the cached-map best case.
        h.renderFrame(point.settings, m_sweepSize, TimingMode::Finish);
        std::vector<double> times;
        for (int i = 0; i < kTimedFrames; ++i) {
            h.renderer().invalidateShadowMap();
            h.renderFrame(point.settings, m_sweepSize, TimingMode::Finish);
            times.push_back(h.renderer().lastFrame().frameWallMs);
        }
        point.frameMs = summarize(times).median;
        m_sweepPoints.push_back(point);
        refreshChart();
    } catch (const std::exception& e) {
        m_sweepSkipped << QStringLiteral("%1 (%2)").arg(point.label, QString::fromUtf8(e.what()));
    }
    m_progress->setValue(int(m_sweepNext));
    QTimer::singleShot(0, this, &AccuracyDock::sweepStep);
}

void AccuracyDock::finishSweep(const QString& message)
{
    m_sweeping = false;
    m_sweepCancelled = false;
    updateButtons();
    setStatus(message, !m_sweepSkipped.isEmpty());
}

void AccuracyDock::refreshChart()
{
    double maxTime = 0.0, minError = std::numeric_limits<double>::infinity(), maxError = 0.0;
    for (const SweepPoint& p : m_sweepPoints) {
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

    QList<QPointF> points;
    for (const SweepPoint& p : m_sweepPoints)
        points << plotted(p);
    m_variations->replace(points);
    updateCurrentMarker();
}

QPointF AccuracyDock::plotted(const SweepPoint& point) const
{
    return {point.frameMs, std::max(point.misclassifiedPercent, m_errorAxis->min())};
}

int AccuracyDock::sweepPointAt(const QPointF& point) const
{
    const QPointF target = m_chart->mapToPosition(point, m_variations);
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_sweepPoints.size(); ++i) {
        const double d = QLineF(m_chart->mapToPosition(plotted(m_sweepPoints[i]), m_variations), target).length();
        if (d < bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

void AccuracyDock::pointClicked(const QPointF& point)
{
    const int index = sweepPointAt(point);
    if (index < 0 || m_sweepPoints[std::size_t(index)].settings == m_settings)
        return;
    emit applySettingsRequested(m_sweepPoints[std::size_t(index)].settings);
}

void AccuracyDock::pointHovered(const QPointF& point, bool state)
{
    const int index = state ? sweepPointAt(point) : -1;
    if (index < 0) {
        QToolTip::hideText();
        return;
    }
    const SweepPoint& p = m_sweepPoints[std::size_t(index)];
    const QString text = tr("<b>%1</b><br>%2 ms · %3 % misclassified<br><small>%4</small>")
                             .arg(p.label.toHtmlEscaped())
                             .arg(p.frameMs, 0, 'f', 1)
                             .arg(p.misclassifiedPercent, 0, 'f', 2)
                             .arg(settingsSummary(p.settings).toHtmlEscaped());
    QToolTip::showText(QCursor::pos(), text, this);
    m_pointInfo->setText(tr("%1: %2 ms, %3 % misclassified. Click to apply.")
                             .arg(p.label)
                             .arg(p.frameMs, 0, 'f', 1)
                             .arg(p.misclassifiedPercent, 0, 'f', 2));
}

void AccuracyDock::updateCurrentMarker()
{
    m_current->clear();
    for (const SweepPoint& p : m_sweepPoints) {
        if (p.settings == m_settings) {
            m_current->append(plotted(p));
            return;
        }
    }
}

void AccuracyDock::showMetrics()
{
    const bool have = m_measurement.has_value();
    const bool stale = have && (m_measurement->settings != m_settings || m_measurement->errors.size() != measureSize());
    auto put = [&](QLabel* label, const QString& text) {
        label->setText(have ? text : QStringLiteral("—"));
        label->setEnabled(!stale);
    };
    const ErrorMetrics hard = have ? m_measurement->hard : ErrorMetrics{};
    const ErrorMetrics area = have ? m_measurement->area : ErrorMetrics{};
    put(m_misclassified, percentText(hard.misclassified));
    put(m_falseShadow, percentText(hard.falseShadow));
    put(m_falseLight, percentText(hard.falseLight));
    put(m_hardMae, errorText(hard.mae));
    put(m_hardRmse, errorText(hard.rmse));
    const bool haveArea = have && area.pixels > 0;
    put(m_areaMae, haveArea ? errorText(area.mae) : QStringLiteral("—"));
    put(m_areaRmse, haveArea ? errorText(area.rmse) : QStringLiteral("—"));
    put(m_noiseFloor, haveArea ? errorText(m_measurement->areaNoiseFloor) : QStringLiteral("—"));

    if (!have) {
        m_referenceInfo->setText(tr("Not measured yet."));
        return;
    }
    const QSize size = m_measurement->errors.size();
    const QString reference = m_lastReferenceReused ? tr("reference reused") : tr("reference traced at %1").arg(raysText(m_lastRaysPerSecond));
    QString info = tr("%1×%2 px, %3 rays/px for the area light; %4.")
                       .arg(size.width())
                       .arg(size.height())
                       .arg(m_reference.samplesPerPixel)
                       .arg(reference);
    if (stale)
        info += QLatin1Char(' ') + tr("The view changed since: compare again.");
    m_referenceInfo->setText(info);
}

void AccuracyDock::updateOverlay()
{
    const bool fresh = m_measurement && m_measurement->settings == m_settings && m_measurement->errors.size() == measureSize();
    const QImage wanted = fresh && m_overlayCheck->isChecked() ? m_measurement->errors : QImage();
    if (wanted.cacheKey() == m_overlay.cacheKey())
        return;
    m_overlay = wanted;
    emit errorOverlayChanged(m_overlay);
}

void AccuracyDock::updateButtons()
{
    const bool busy = isBusy();
    m_compareButton->setEnabled(!busy);
    m_sweepButton->setEnabled(!busy);
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
