#include "AccuracyController.h"

#include "ReportSweep.h"

#include "AccuracyMeter.h"
#include "HeadlessRenderer.h"
#include "Measurement.h"
#include "ReportAnalysis.h"
#include "RayTracer.h"
#include "RenderError.h"
#include "SampleStats.h"
#include "SceneSupply.h"
#include "SettingsKeys.h"
#include "SettingsSummary.h"
#include "ShadowTechnique.h"

#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr int kProgressSteps = 1000;

} // namespace

AccuracyController::AccuracyController(QObject* parent) : QObject(parent)
{
    // One trace at a time, on a thread of its own: traceReference() fans its rows out over the
    // global pool and only polls from here, so it must not occupy one of that pool's threads.
    m_tracePool.setMaxThreadCount(1);
    connect(&m_traceWatcher, &QFutureWatcherBase::progressValueChanged, this,
            [this](int value) { emit progressChanged(value, kProgressSteps); });
    connect(&m_traceWatcher, &QFutureWatcherBase::finished, this, &AccuracyController::traceFinished);
}

AccuracyController::~AccuracyController()
{
    if (m_cancelTrace)
        m_cancelTrace->store(true);
    m_traceWatcher.waitForFinished();
}

void AccuracyController::setSettings(const Settings& settings)
{
    setSides({settings}, 0);
}

void AccuracyController::setSides(const std::vector<Settings>& sides, std::size_t selected)
{
    if (sides.empty())
        return;
    const bool sceneChanged = sides.front().scene != m_sides.front().scene;
    const bool sideChanged = std::min(selected, sides.size() - 1) != m_selected;
    m_sides = sides;
    m_selected = std::min(selected, sides.size() - 1);
    // A side that went (compare mode off) takes its measurement with it.
    m_measurements.resize(sides.size());
    if (sceneChanged)
        withdrawResults();
    else if (sideChanged && m_tuning)
        withdrawTuning();   // it was of the other side's settings
}

void AccuracyController::withdrawResults()
{
    // Measured on another scene: nothing of it says anything about this one, and work still
    // under way for it is stopped.
    if (isBusy())
        cancel();
    for (auto& measurement : m_measurements)
        measurement.reset();
    m_sweepPoints.clear();
    m_tuning.reset();
    setStatus({});
    emit measurementChanged();
    emit sweepPointsChanged();
    emit tuningFinished();
}

void AccuracyController::withdrawTuning()
{
    m_tuning.reset();
    emit tuningFinished();
}

void AccuracyController::setViewSize(QSize size)
{
    m_viewSize = size;
}

QSize AccuracyController::measureSize() const
{
    if (m_viewSize.isEmpty())
        return {};
    const double scale = std::min(1.0, double(kMaxMeasureSide) / std::max(m_viewSize.width(), m_viewSize.height()));
    return {std::max(1, int(std::lround(m_viewSize.width() * scale))), std::max(1, int(std::lround(m_viewSize.height() * scale)))};
}

void AccuracyController::setAreaSamplesPerAxis(int samples)
{
    m_areaSamplesPerAxis = std::clamp(samples, 1, 64);
}

bool AccuracyController::isBusy() const
{
    return m_tracing || !m_captures.empty() || m_sweeping || m_tuner != nullptr;
}

bool AccuracyController::measurementIsCurrent(std::size_t side) const
{
    if (side >= m_sides.size())
        return false;
    const std::optional<Measurement>& m = m_measurements[side];
    return m && m->settings == m_sides[side] && m->errors.size() == measureSize();
}

const ReferenceVisibility* AccuracyController::cachedReference(const ReferenceKey& key) const
{
    const auto it = std::find_if(m_references.begin(), m_references.end(), [&](const auto& cached) { return cached.first == key; });
    return it == m_references.end() ? nullptr : &it->second;
}

HeadlessRenderer& AccuracyController::headless()
{
    if (!m_headless)
        m_headless = std::make_unique<HeadlessRenderer>();
    m_headless->makeCurrent();
    return *m_headless;
}

void AccuracyController::compare()
{
    startMeasurement(false);
}

void AccuracyController::sweep()
{
    startMeasurement(true);
}

void AccuracyController::cancel()
{
    if (m_cancelTrace)
        m_cancelTrace->store(true);
    m_sweepCancelled = m_sweeping;
    m_tuneCancelled = m_tuner != nullptr;
    setStatus(tr("Cancelling…"));
}

void AccuracyController::tuneBias()
{
    if (isBusy())
        return;
    // A small image: the tuner renders every candidate at every light direction.
    const QSize size = measureSize().scaled(QSize(320, 320), Qt::KeepAspectRatio).expandedTo(QSize(16, 16));
    m_tuner = std::make_unique<BiasTuner>(settings(), size);
    m_tunedSize = size;
    m_tuneCancelled = false;
    emit busyChanged(true);
    emit progressChanged(0, m_tuner->steps());
    setStatus(tr("Tuning the bias over %1 light directions…").arg(m_tuner->placementCount()));
    QTimer::singleShot(0, this, &AccuracyController::tuneStep);
}

void AccuracyController::tuneStep()
{
    const auto finish = [this](const QString& message, bool error) {
        m_tuner.reset();
        emit busyChanged(false);
        setStatus(message, error);
    };
    if (m_tuneCancelled) {
        finish(tr("Bias tuning cancelled."), false);
        return;
    }
    try {
        HeadlessRenderer& h = headless();
        // A few measurements per event: the window stays responsive, the overhead small.
        for (int i = 0; i < 4 && !m_tuner->done(); ++i)
            m_tuner->step(h.renderer());
    } catch (const std::exception& e) {
        finish(tr("Bias tuning failed: %1").arg(QString::fromUtf8(e.what())), true);
        return;
    }
    emit progressChanged(m_tuner->stepsDone(), m_tuner->steps());
    if (!m_tuner->done()) {
        QTimer::singleShot(0, this, &AccuracyController::tuneStep);
        return;
    }
    m_tuning = m_tuner->result();
    const BiasCandidate& best = m_tuning->candidates[m_tuning->best];
    // Both figures are the tuner's own: the mean over its light directions at its size, not
    // the accuracy table's one view at the window's.
    const QString over = tr("mean over %1 light directions at %2×%3").arg(m_tuning->placements.size()).arg(m_tunedSize.width()).arg(m_tunedSize.height());
    if (!m_tuning->improves) {
        finish(tr("The bias as set is already on the knee: no bias on the curve misclassifies clearly fewer pixels (%1 % as set, %2).")
                   .arg(100.0 * m_tuning->current.misclassified(), 0, 'f', 3)
                   .arg(over),
               false);
    } else {
        finish(tr("Best bias (%1 units): slope %2, min %3 — misclassified %4 %, against %5 % as set (%6).")
                   .arg(toString(m_tuning->space))
                   .arg(best.slope)
                   .arg(best.min)
                   .arg(100.0 * best.misclassified(), 0, 'f', 3)
                   .arg(100.0 * m_tuning->current.misclassified(), 0, 'f', 3)
                   .arg(over),
               false);
    }
    emit tuningFinished();
}

void AccuracyController::startMeasurement(bool thenSweep)
{
    if (isBusy())
        return;
    const QSize size = measureSize();
    if (size.isEmpty()) {
        setStatus(tr("Nothing to measure: the scene view has no size yet."), true);
        return;
    }
    try {
        // Every side's capture first, at the same size: the sides differ in their settings
        // only, so the same pixels are compared.
        // The selected side last: its reference is then the newest, which the sweep reads.
        std::vector<std::size_t> order;
        for (std::size_t side = 0; side < m_sides.size(); ++side) {
            if (side != m_selected)
                order.push_back(side);
        }
        order.push_back(m_selected);
        std::vector<Capture> captures;
        for (const std::size_t side : order) {
            const Settings& s = m_sides[side];
            ensureValid(s);
            Renderer& renderer = headless().renderer();
            Capture capture{side, s, referenceKeyFor(s, size, m_areaSamplesPerAxis), nullptr, {}, {}, nullptr, {}};
            capture.flicker = measureFlicker(renderer, s, subTexelPath(renderer, s, size, kFlickerFrames, kFlickerStepTexels), size);
            capture.counts = countFrames(headless(), s, size);
            supplyScene(renderer, s);
            capture.buffer = std::make_shared<const VisibilityBuffer>(renderer.renderVisibility(s, size));
            // A trace needs the scene and light as they were: copied, unless an earlier capture
            // traces the same reference or the cache holds it.
            const bool traced = cachedReference(capture.key)
                || std::any_of(captures.begin(), captures.end(), [&](const Capture& c) { return c.key == capture.key; });
            if (!traced) {
                capture.scene = std::make_shared<const Scene>(*renderer.scene());
                capture.light = renderer.lightFrame();
            }
            captures.push_back(std::move(capture));
        }
        m_captures = std::move(captures);
        m_thenSweep = thenSweep;
        m_lastReferencesTraced = 0;
        measureCaptures();
    } catch (const std::exception& e) {
        m_captures.clear();
        setStatus(QString::fromUtf8(e.what()), true);
    }
    emit busyChanged(isBusy());
}

void AccuracyController::measureCaptures()
{
    std::optional<Settings> measured;     // the selected side, as it was captured
    while (!m_captures.empty()) {
        const Capture& capture = m_captures.front();
        const ReferenceVisibility* reference = cachedReference(capture.key);
        if (!reference)
            break;
        measure(capture, *reference);
        if (capture.side == m_selected)
            measured = capture.settings;
        m_captures.erase(m_captures.begin());
    }
    if (m_captures.empty()) {
        if (m_thenSweep) {
            m_thenSweep = false;
            // Around the settings measured, not the side's now: a playing scene's clock has moved on.
            startSweep(measured.value_or(settings()));
        }
        return;
    }

    const Capture& capture = m_captures.front();
    if (!capture.scene)
        throw RenderError(tr("no scene was captured for the reference of side %1").arg(QLatin1Char(char('A' + capture.side))));
    auto scene = capture.scene;
    const LightFrame light = capture.light;
    const ReferenceOptions options{true, capture.settings.reference.lightRadius, m_areaSamplesPerAxis};
    auto buffer = capture.buffer;
    m_cancelTrace = std::make_shared<std::atomic<bool>>(false);
    m_tracing = true;
    emit progressChanged(0, kProgressSteps);
    const QSize size = capture.buffer->size;
    setStatus(m_sides.size() > 1 ? tr("Tracing the reference of side %1 at %2×%3…").arg(QLatin1Char(char('A' + capture.side))).arg(size.width()).arg(size.height())
                                 : tr("Tracing the reference at %1×%2…").arg(size.width()).arg(size.height()));
    m_traceWatcher.setFuture(QtConcurrent::run(&m_tracePool, [scene, buffer, light, options, cancelFlag = m_cancelTrace](QPromise<TraceOutcome>& promise) {
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
}

void AccuracyController::traceFinished()
{
    m_tracing = false;
    const bool cancelled = m_cancelTrace && m_cancelTrace->load();
    m_cancelTrace.reset();
    TraceOutcome outcome = m_traceWatcher.result();
    const auto stop = [this](const QString& message, bool error) {
        m_captures.clear();
        m_thenSweep = false;
        emit busyChanged(isBusy());
        setStatus(message, error);
    };
    if (!outcome.error.isEmpty()) {
        stop(tr("The reference could not be traced: %1").arg(outcome.error), true);
        return;
    }
    if (outcome.reference.cancelled || cancelled) {
        stop(tr("Cancelled; the partial reference was discarded."), false);
        return;
    }
    m_lastRaysPerSecond = outcome.reference.raysPerSecond();
    ++m_lastReferencesTraced;
    m_references.insert(m_references.begin(), {m_captures.front().key, std::move(outcome.reference)});
    if (m_references.size() > kCachedReferences)
        m_references.pop_back();
    try {
        measureCaptures();
    } catch (const std::exception& e) {
        stop(QString::fromUtf8(e.what()), true);
        return;
    }
    emit busyChanged(isBusy());
}

void AccuracyController::measure(const Capture& capture, const ReferenceVisibility& reference)
{
    const AccuracyResult result = compareWithReference(*capture.buffer, reference);
    Measurement m;
    m.settings = capture.settings;
    m.hard = result.hard;
    m.dssim = 1.0 - result.ssim;
    m.area = result.area;
    m.areaNoiseFloor = result.areaNoiseFloor;
    m.referenceSamplesPerPixel = reference.samplesPerPixel;
    m.errors = result.hardErrors;
    m.heat = result.hardHeat;
    m.flicker = capture.flicker;
    m.counts = capture.counts;
    if (capture.side < m_measurements.size())
        m_measurements[capture.side] = std::move(m);
    const bool nothing = result.hard.pixels == 0;
    setStatus(nothing ? tr("No surface in view faces the light; nothing to compare.") : QString());
    emit measurementChanged();
}

void AccuracyController::startSweep(const Settings& around)
{
    const int maxTextureSize = headless().renderer().maxTextureSize();
    m_sweepPlan.clear();
    m_sweepKey = referenceKeyFor(around, measureSize(), m_areaSamplesPerAxis);
    for (const SweepEntry& entry : sweepAround(around)) {
        Settings s = applySweepEntry(around, entry);    // valid: sweepAround() keeps only what is
        if (s.map.size <= maxTextureSize)
            m_sweepPlan.push_back({entry.label, std::move(s), 0.0, 0.0, QString()});
    }
    m_sweepPoints.clear();
    m_sweepSkipped.clear();
    m_sweepNext = 0;
    m_sweepSize = measureSize();
    m_sweeping = true;
    m_sweepCancelled = false;
    emit sweepStarted(m_sweepSize);
    emit sweepPointsChanged();
    emit progressChanged(0, int(m_sweepPlan.size()));
    emit busyChanged(true);
    QTimer::singleShot(0, this, &AccuracyController::sweepStep);
}

void AccuracyController::sweepStep()
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
        const ReferenceVisibility* reference = cachedReference(m_sweepKey);
        if (!reference)
            throw RenderError(tr("the reference is gone; compare again"));
        supplyScene(h.renderer(), point.settings);
        const VisibilityBuffer buffer = h.renderer().renderVisibility(point.settings, m_sweepSize);
        const AccuracyResult result = compareWithReference(buffer, *reference);
        point.misclassifiedPercent = 100.0 * result.hard.misclassified;
        point.visiblyWrong = visiblyWrong(result);

        // One untimed frame compiles the lit variant; every frame redraws the shadow map, so
        // the time is what a moving light costs, not the cached-map best case.
        std::vector<TimedRun> runs{{&h, point.settings, true, false, {}, {}}};
        timeInterleaved(runs, m_sweepSize, 1, kTimedFrames);
        point.frameMs = summarize(runs.front().samples.wall).median;
        m_sweepPoints.push_back(point);
        emit sweepPointsChanged();
    } catch (const std::exception& e) {
        m_sweepSkipped << QStringLiteral("%1 (%2)").arg(point.label, QString::fromUtf8(e.what()));
    }
    emit progressChanged(int(m_sweepNext), int(m_sweepPlan.size()));
    QTimer::singleShot(0, this, &AccuracyController::sweepStep);
}

void AccuracyController::finishSweep(const QString& message)
{
    m_sweeping = false;
    m_sweepCancelled = false;
    emit busyChanged(false);
    setStatus(message, !m_sweepSkipped.isEmpty());
}

void AccuracyController::setStatus(const QString& text, bool error)
{
    emit statusChanged(text, error);
}

} // namespace shadowlab
