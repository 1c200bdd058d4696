#include "AccuracyMetricsPanel.h"

#include "AccuracyController.h"
#include "ErrorNoise.h"
#include "FrameStatsText.h"
#include "NoteLabel.h"
#include "ReportAnalysis.h"
#include "ShadowMetrics.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QStringList>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

const char* const kColumnNames[3] = {"A", "B", "B − A"};
const char* const kColumnSuffix[3] = {"Value", "ValueB", "Delta"};

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

// A grid of metrics under a header row naming the sides (hidden with one side).
QGridLayout* metricGrid(QWidget* box, std::vector<QLabel*>& headers)
{
    auto* grid = new QGridLayout(box);
    grid->setColumnStretch(0, 1);
    for (int c = 0; c < 3; ++c) {
        auto* header = new QLabel(QStringLiteral("<b>%1</b>").arg(QString::fromUtf8(kColumnNames[c])));
        header->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        header->setVisible(false);
        grid->addWidget(header, 0, c + 1);
        headers.push_back(header);
    }
    return grid;
}

} // namespace

AccuracyMetricsPanel::AccuracyMetricsPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(createHardGroup());
    layout->addWidget(createAreaGroup());

    m_referenceInfo = noteLabel(QStringLiteral("referenceInfo"));
    m_referenceInfo->setToolTip(tr("Speed of the Embree ray tracer here. The reference depends on scene, camera, view "
                                   "size and light placement only, so map, bias and filter changes reuse it."));
    layout->addWidget(m_referenceInfo);
    layout->addWidget(createCostGroup());

    auto* overlayRow = new QHBoxLayout;
    m_overlayCheck = new QCheckBox(tr("Show errors on the scene view"));
    m_overlayCheck->setObjectName(QStringLiteral("overlayCheck"));
    m_overlayCheck->setChecked(true);
    m_overlayCheck->setToolTip(tr("Grey the scene view and paint false shadow magenta and false light cyan "
                                  "(against the hard-shadow reference)"));
    overlayRow->addWidget(m_overlayCheck);
    overlayRow->addStretch(1);
    layout->addLayout(overlayRow);
    // What the overlay shows, on a line of its own under the check box: the dock is narrow.
    auto* kindRow = new QHBoxLayout;
    kindRow->setContentsMargins(m_overlayCheck->style()->pixelMetric(QStyle::PM_IndicatorWidth) + 6, 0, 0, 0);
    m_overlayKind = new QComboBox;
    m_overlayKind->setObjectName(QStringLiteral("overlayKind"));
    m_overlayKind->addItem(tr("wrong pixels"));
    m_overlayKind->addItem(tr("|V − V_ref| heat"));
    m_overlayKind->setToolTip(tr("Wrong pixels: those wrong by more than half, as false shadow or false light. Heat: every pixel's "
                                 "difference from the reference, so partial shadow that is wrong by less (a filter's moiré over a lit "
                                 "floor, a soft edge too wide) shows too."));
    kindRow->addWidget(m_overlayKind);
    kindRow->addStretch(1);
    layout->addLayout(kindRow);
    // The colours of errorImage(), or errorHeatImage()'s ramp.
    auto* legend = noteLabel(QStringLiteral("overlayLegend"));
    legend->setContentsMargins(m_overlayCheck->style()->pixelMetric(QStyle::PM_IndicatorWidth) + 6, 0, 0, 0);
    layout->addWidget(legend);
    const auto showLegend = [this, legend] {
        if (m_overlayKind->currentIndex() == 0) {
            legend->setText(tr("<span style='color:%1'>■</span> false shadow &nbsp; <span style='color:%2'>■</span> false light")
                                .arg(QColor(235, 40, 200).name(), QColor(40, 220, 235).name()));
            return;
        }
        QString ramp;
        for (double e : {0.02, 0.05, 0.1, 0.25, 0.5, 1.0})
            ramp += QStringLiteral("<span style='color:%1'>■</span>%2 ").arg(errorHeatColour(e).name()).arg(e);
        legend->setText(tr("|V − V_ref|: %1").arg(ramp));
    };
    showLegend();
    connect(m_overlayCheck, &QCheckBox::toggled, this, &AccuracyMetricsPanel::overlayToggled);
    connect(m_overlayKind, &QComboBox::currentIndexChanged, this, [this, showLegend] {
        showLegend();
        emit overlayToggled(m_overlayCheck->isChecked());
    });
    setColumns(1);
}

QGroupBox* AccuracyMetricsPanel::createHardGroup()
{
    auto* hard = new QGroupBox(tr("Hard-shadow reference"));
    hard->setObjectName(QStringLiteral("hardGroup"));
    QGridLayout* hardGrid = metricGrid(hard, m_headers);
    m_misclassified = addRow(hardGrid, QStringLiteral("misclassified"), tr("Misclassified"),
                             tr("Share of lit-facing pixels on the wrong side of half visibility compared with one shadow ray per "
                                "pixel: false shadow plus false light."),
                             Kind::Share);
    m_dssim = addRow(hardGrid, QStringLiteral("dssim"), tr("DSSIM (picture)"),
                     tr("How unlike the frame looks from the same frame shaded with the reference: 1 − its mean SSIM, 0 when a "
                        "reader sees the same picture. It sees what a misclassified count misses, such as a moiré of partial "
                        "shadow over a lit floor; over %1 the picture is visibly wrong.")
                         .arg(kVisibleDssim),
                     Kind::Error);
    m_falseShadow = addRow(hardGrid, QStringLiteral("falseShadow"), tr("False shadow (acne)"),
                           tr("Dark where the reference is lit: shadow acne from too little bias, over-darkened edges. "
                              "Magenta on the scene view."),
                           Kind::Share);
    m_falseLight = addRow(hardGrid, QStringLiteral("falseLight"), tr("False light (leaks)"),
                          tr("Lit where the reference is dark: peter panning from too much bias, light leaking through thin "
                             "casters. Cyan on the scene view."),
                          Kind::Share);
    m_hardMae = addRow(hardGrid, QStringLiteral("hardMae"), tr("MAE"),
                       tr("Mean absolute difference of visibility (0 shadowed … 1 lit); soft edges count in part."), Kind::Share);
    m_hardRmse = addRow(hardGrid, QStringLiteral("hardRmse"), tr("RMSE"),
                        tr("Root mean square difference of visibility; weighs whole wrong pixels more than MAE does."), Kind::Share);
    m_flicker = addRow(hardGrid, QStringLiteral("flicker"), tr("Flicker"),
                       tr("Shimmer: the light's maps follow a camera walking in steps of a third of a texel while the same "
                          "pixels are measured; the share of them whose shadow flips from one step to the next. Stabilised "
                          "maps should barely flicker."),
                       Kind::Share);
    return hard;
}

QGroupBox* AccuracyMetricsPanel::createAreaGroup()
{
    auto* area = new QGroupBox(tr("Area-light reference"));
    area->setObjectName(QStringLiteral("areaGroup"));
    area->setToolTip(tr("A disk light of radius light.radius, sampled with stratified rays: how close a "
                        "filtered edge comes to a real penumbra."));
    QGridLayout* areaGrid = metricGrid(area, m_headers);
    m_areaMae = addRow(areaGrid, QStringLiteral("areaMae"), tr("MAE"), tr("Mean absolute difference from the area light's visibility."),
                       Kind::Share);
    m_areaRmse = addRow(areaGrid, QStringLiteral("areaRmse"), tr("RMSE"),
                        tr("Root mean square difference from the area light's visibility."), Kind::Share);
    m_noiseFloor = addRow(areaGrid, QStringLiteral("noiseFloor"), tr("Noise floor"),
                          tr("Mean standard error of the area reference itself: differences this small are sampling noise, "
                             "not error. More samples per pixel lower it."),
                          Kind::Share);
    return area;
}

QGroupBox* AccuracyMetricsPanel::createCostGroup()
{
    auto* cost = new QGroupBox(tr("Cost"));
    cost->setObjectName(QStringLiteral("costGroup"));
    cost->setToolTip(tr("What the scene view's frames took: medians over its last frames (View > Measure 100 Frames for "
                        "more). The shadow pass only counts frames that drew the map; a cached map costs nothing."));
    QGridLayout* costGrid = metricGrid(cost, m_headers);
    m_frame = addRow(costGrid, QStringLiteral("frameTime"), tr("Frame"), tr("Median wall time of a whole frame."), Kind::Milliseconds);
    m_shadowPass = addRow(costGrid, QStringLiteral("shadowPassTime"), tr("Shadow pass"),
                          tr("Median wall time of the frames' shadow pass, over the frames that ran it."), Kind::Milliseconds);
    // Counts of the measured frame: what a GPU is asked for, unlike the times a software
    // rasteriser's CPU takes.
    m_taps = addRow(costGrid, QStringLiteral("shadowTaps"), tr("Shadow taps"),
                    tr("Texture reads of the shadow lookups in one frame at the measured size: the technique's taps per lookup "
                       "times the fragments that looked up. The same on any GPU."),
                    Kind::Count);
    m_shadowSamples = addRow(costGrid, QStringLiteral("shadowSamples"), tr("Shadow-pass samples"),
                             tr("Fragments the shadow pass wrote (GL_SAMPLES_PASSED): the casters, and for a moments map its far-plane "
                                "fill and blur. The same on any GPU."),
                             Kind::Count);
    m_cleared = addRow(costGrid, QStringLiteral("texelsCleared"), tr("Texels cleared"),
                       tr("Shadow-map texels one shadow pass cleared: a view without casters is not cleared, a tile of several only "
                          "where it was or will be drawn."),
                       Kind::Count);
    m_mapMemory = addRow(costGrid, QStringLiteral("mapMemory"), tr("Map memory"), tr("Memory of the shadow map and its storage."), Kind::Bytes);
    m_costInfo = noteLabel(QStringLiteral("costInfo"));
    costGrid->addWidget(m_costInfo, costGrid->rowCount(), 0, 1, 4);
    return cost;
}

AccuracyMetricsPanel::Row* AccuracyMetricsPanel::addRow(QGridLayout* grid, const QString& objectName, const QString& name,
                                                        const QString& toolTip, Kind kind)
{
    auto row = std::make_unique<Row>();
    row->kind = kind;
    row->toolTip = toolTip;
    auto* nameLabel = new QLabel(name);
    nameLabel->setToolTip(toolTip);
    nameLabel->setWordWrap(true);   // three columns of numbers in compare mode leave a narrow dock little room
    const int r = grid->rowCount();
    grid->addWidget(nameLabel, r, 0);
    for (int c = 0; c < 3; ++c) {
        row->values[c] = valueLabel(objectName + QLatin1String(kColumnSuffix[c]));
        // Room for the widest number from the start: a dock that widens when numbers arrive
        // would shrink the scene views and make the measurement it shows stale at once.
        const QFontMetrics metrics = row->values[c]->fontMetrics();
        row->values[c]->setMinimumWidth(metrics.horizontalAdvance(c < 2 ? QStringLiteral("88.88 %") : QStringLiteral("+88.88 pp")));
        row->values[c]->setToolTip(c < 2 ? toolTip
                                         : tr("B − A: negative (green) where B is better, positive (red) where it is worse; "
                                              "\"same\" within the measurement's noise. Shares differ in percentage points (pp)."));
        grid->addWidget(row->values[c], r, c + 1);
    }
    Row* raw = row.get();
    m_rows.push_back(std::move(row));
    return raw;
}

void AccuracyMetricsPanel::setColumns(int sides)
{
    m_sides = sides;
    const bool both = sides > 1;
    for (QLabel* header : m_headers)
        header->setVisible(both);
    for (const auto& row : m_rows) {
        row->values[1]->setVisible(both);
        row->values[2]->setVisible(both);
    }
}

void AccuracyMetricsPanel::put(Row& row, const std::array<std::optional<double>, 2>& values, const std::array<bool, 2>& stale, double noise)
{
    const auto text = [&row](double v) {
        switch (row.kind) {
        case Kind::Share: return percentText(v);
        case Kind::Error: return errorText(v);
        case Kind::Milliseconds: return QStringLiteral("%1 ms").arg(v, 0, 'f', 1);
        case Kind::Count: return countText(std::int64_t(v));
        case Kind::Bytes: return bytesText(std::int64_t(v));
        }
        return QString();
    };
    for (int c = 0; c < 2; ++c) {
        row.values[c]->setText(values[c] ? text(*values[c]) : QStringLiteral("—"));
        row.values[c]->setEnabled(!stale[c]);
    }
    QLabel* delta = row.values[2];
    delta->setEnabled(!stale[0] && !stale[1]);
    if (m_sides < 2 || !values[0] || !values[1]) {
        delta->setText(QStringLiteral("—"));
        delta->setStyleSheet(QString());
        return;
    }
    const double d = *values[1] - *values[0];
    if (std::isnan(noise)) {
        delta->setText(QStringLiteral("…"));    // too few samples to tell a difference from noise
        delta->setStyleSheet(QString());
        return;
    }
    if (std::abs(d) <= noise || (row.kind == Kind::Share && std::abs(d) < 5e-7)) {
        delta->setText(tr("same"));
        delta->setStyleSheet(QString());
        return;
    }
    // U+2212 for minus, as the captions write it.
    const QString sign = d > 0.0 ? QStringLiteral("+") : QStringLiteral("\u2212");
    const double a = std::abs(d);
    switch (row.kind) {
    case Kind::Share: {
        const double points = a * 100.0;
        delta->setText(QStringLiteral("%1%2 pp").arg(sign).arg(points, 0, 'f', points < 0.1 ? 3 : 2));
        break;
    }
    case Kind::Error: delta->setText(sign + errorText(a)); break;
    case Kind::Milliseconds: delta->setText(QStringLiteral("%1%2 ms").arg(sign).arg(a, 0, 'f', 1)); break;
    case Kind::Count: delta->setText(sign + countText(std::int64_t(a))); break;
    case Kind::Bytes: delta->setText(sign + bytesText(std::int64_t(a))); break;
    }
    // Every number here is an error or a cost: less is better.
    delta->setStyleSheet(d < 0.0 ? QStringLiteral("color: #2e8b3e;") : QStringLiteral("color: #c0392b;"));
}

bool AccuracyMetricsPanel::overlayWanted() const
{
    return m_overlayCheck->isChecked();
}

bool AccuracyMetricsPanel::heatWanted() const
{
    return m_overlayKind->currentIndex() == 1;
}

namespace {

// The line under the table: the image, the reference's samples and whether it was traced, and
// whether a side changed since.
QString referenceInfo(const AccuracyController& controller, const std::array<const AccuracyController::Measurement*, 2>& m, const std::array<bool, 2>& stale)
{
    const AccuracyController::Measurement* shown = m[controller.selectedSide() < 2 ? controller.selectedSide() : 0];
    if (!m[0] && !m[1])
        return AccuracyMetricsPanel::tr("Not measured yet.");
    if (!shown)
        shown = m[0] ? m[0] : m[1];
    const QSize size = shown->errors.size();
    const int traced = controller.lastReferencesTraced();
    const QString reference = traced == 0 ? AccuracyMetricsPanel::tr("reference reused")
                              : traced == 1 ? AccuracyMetricsPanel::tr("reference traced at %1").arg(raysText(controller.lastRaysPerSecond()))
                                            : AccuracyMetricsPanel::tr("%1 references traced (the sides' lights differ), at %2").arg(traced).arg(raysText(controller.lastRaysPerSecond()));
    QString info = AccuracyMetricsPanel::tr("%1×%2 px, %3 rays/px for the area light; %4.")
                       .arg(size.width())
                       .arg(size.height())
                       .arg(shown->referenceSamplesPerPixel)
                       .arg(reference);
    const int sides = int(std::min<std::size_t>(controller.sideCount(), 2));
    if (sides > 1)
        info += QLatin1Char(' ') + AccuracyMetricsPanel::tr("Both sides over the same pixels.");
    if (stale[0] || stale[1])
        info += QLatin1Char(' ') + (sides > 1 && stale[0] != stale[1] ? AccuracyMetricsPanel::tr("Side %1 changed since: compare again.").arg(QLatin1Char(stale[0] ? 'A' : 'B'))
                                                                       : AccuracyMetricsPanel::tr("The view changed since: compare again."));
    return info;
}

} // namespace

void AccuracyMetricsPanel::markStillFlicker(const AccuracyController& controller)
{
    // A zero that measured nothing: the maps stood still through the walk.
    for (std::size_t s = 0; s < std::min<std::size_t>(controller.sideCount(), 2); ++s) {
        const auto& m = controller.measurement(s);
        m_flicker->values[s]->setToolTip(m_flicker->toolTip);
        if (m && m->flicker.frames > 1 && m->flicker.mapMoves == 0) {
            m_flicker->values[s]->setText(tr("still"));   // short: the tooltip says why
            m_flicker->values[s]->setToolTip(tr("The light's maps did not move while the camera walked: the casters, not the view, bound "
                                                "the fitted volume, so this view cannot show shimmer. Move the camera so its view cuts "
                                                "the shadows, or try the city."));
        }
    }
}

void AccuracyMetricsPanel::showMeasurement(const AccuracyController& controller)
{
    const int sides = int(std::min<std::size_t>(controller.sideCount(), 2));
    setColumns(sides);
    std::array<const AccuracyController::Measurement*, 2> m{};
    std::array<bool, 2> stale{};
    for (int s = 0; s < sides; ++s) {
        const auto& measurement = controller.measurement(std::size_t(s));
        m[s] = measurement ? &*measurement : nullptr;
        stale[s] = m[s] && !controller.measurementIsCurrent(std::size_t(s));
    }
    const auto values = [&](auto get) {
        std::array<std::optional<double>, 2> out;
        for (int s = 0; s < 2; ++s)
            out[s] = m[s] ? get(*m[s]) : std::optional<double>();
        return out;
    };
    using M = AccuracyController::Measurement;
    // The report's noise rule (ErrorNoise.h): a share of pixels is a count, known to
    // n ± max(3, 2√n); two sides are the same while their bands overlap.
    const auto countNoise = [&](auto share, auto pixels) {
        double noise = 0.0;
        for (int s = 0; s < 2; ++s) {
            if (m[s] && pixels(*m[s]) > 0)
                noise += errorNoisePixels(share(*m[s]) * pixels(*m[s])) / pixels(*m[s]);
        }
        return noise;
    };
    const auto hardPixels = [](const M& x) { return double(x.hard.pixels); };
    const auto hard = [&](double ErrorMetrics::*share) {
        return std::pair{values([share](const M& x) { return std::optional(x.hard.*share); }),
                         countNoise([share](const M& x) { return x.hard.*share; }, hardPixels)};
    };
    for (auto [row, share] : {std::pair{m_misclassified, &ErrorMetrics::misclassified}, std::pair{m_falseShadow, &ErrorMetrics::falseShadow},
                              std::pair{m_falseLight, &ErrorMetrics::falseLight}, std::pair{m_hardMae, &ErrorMetrics::mae}}) {
        const auto [shown, noise] = hard(share);
        put(*row, shown, stale, noise);
    }
    put(*m_dssim, values([](const M& x) { return std::optional(x.dssim); }), stale, 5e-5);
    // Counts are exact: any difference is one. Not taken (-1): no value.
    const auto counted = [](std::int64_t n) { return n >= 0 ? std::optional(double(n)) : std::nullopt; };
    put(*m_taps, values([&](const M& x) { return counted(x.counts.taps()); }), stale, 0.0);
    put(*m_shadowSamples, values([&](const M& x) { return counted(x.counts.shadow.samples); }), stale, 0.0);
    put(*m_cleared, values([&](const M& x) { return counted(x.counts.clearedTexels); }), stale, 0.0);
    put(*m_mapMemory, values([&](const M& x) { return counted(x.counts.mapBytes); }), stale, 0.0);
    put(*m_hardRmse, values([](const M& x) { return std::optional(x.hard.rmse); }), stale, 5e-5);
    put(*m_flicker, values([](const M& x) { return x.flicker.frames > 1 ? std::optional(x.flicker.flicker) : std::nullopt; }), stale,
        countNoise([](const M& x) { return x.flicker.flicker; }, [](const M& x) { return double(x.flicker.frames > 1 ? x.flicker.pixels : 0); }));
    markStillFlicker(controller);
    // The area reference is a Monte Carlo estimate: a difference within its noise floor is noise.
    double floor = 5e-5;
    for (int s = 0; s < 2; ++s)
        floor = m[s] ? std::max(floor, m[s]->areaNoiseFloor) : floor;
    const auto area = [](auto get) {
        return [get](const M& x) { return x.area.pixels > 0 ? std::optional(get(x)) : std::nullopt; };
    };
    put(*m_areaMae, values(area([](const M& x) { return x.area.mae; })), stale,
        std::max(floor, countNoise([](const M& x) { return x.area.mae; }, [](const M& x) { return double(x.area.pixels); })));
    put(*m_areaRmse, values(area([](const M& x) { return x.area.rmse; })), stale, floor);
    put(*m_noiseFloor, values(area([](const M& x) { return x.areaNoiseFloor; })), stale, floor);

    m_referenceInfo->setText(referenceInfo(controller, m, stale));
}

void AccuracyMetricsPanel::showFrameTimes(const std::vector<FrameTimeHistory::Summary>& sides, bool cpuTime)
{
    setColumns(int(std::min<std::size_t>(sides.size(), 2)));
    std::array<std::optional<double>, 2> frame, shadow;
    double frameNoise = 0.0, shadowNoise = 0.0;
    int frames = 0;
    for (std::size_t s = 0; s < std::min<std::size_t>(sides.size(), 2); ++s) {
        const FrameTimeHistory::Summary& x = sides[s];
        if (x.frame.count > 0) {
            frame[s] = x.frame.median;
            frameNoise = std::max(frameNoise, 0.5 * (x.frame.p90 - x.frame.p10));
            frames = frames == 0 ? x.frame.count : std::min(frames, x.frame.count);
        }
        if (x.shadow.count > 0) {
            shadow[s] = x.shadow.median;
            shadowNoise = std::max(shadowNoise, 0.5 * (x.shadow.p90 - x.shadow.p10));
        }
    }
    // Timing noise: half the wider p10–p90 spread, once each side has frames enough for one
    // (the windows restart when a side's settings change). Times are never stale, only more or
    // less settled.
    const auto settled = [&](auto count) {
        for (std::size_t s = 0; s < std::min<std::size_t>(sides.size(), 2); ++s) {
            if (count(sides[s]) > 0 && count(sides[s]) < kFramesToCompare)
                return false;
        }
        return true;
    };
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    put(*m_frame, frame, {}, settled([](const FrameTimeHistory::Summary& x) { return x.frame.count; }) ? frameNoise : unknown);
    put(*m_shadowPass, shadow, {}, settled([](const FrameTimeHistory::Summary& x) { return x.shadow.count; }) ? shadowNoise : unknown);
    for (std::size_t s = 0; s < std::min<std::size_t>(sides.size(), 2); ++s) {
        if (frame[s] && !shadow[s])
            m_shadowPass->values[s]->setText(tr("cached"));
    }
    const QString cpu = cpuTime ? tr(", CPU time (software renderer)") : QString();
    if (frames == 0)
        m_costInfo->setText(tr("No frames yet."));
    else if (sides.size() > 1)
        m_costInfo->setText(tr("Medians of the last %1 frames since the settings changed%2; \"same\" within half the p10–p90 spread, "
                               "\"…\" until each side has %3 frames.")
                                .arg(frames)
                                .arg(cpu)
                                .arg(kFramesToCompare));
    else
        m_costInfo->setText(tr("Medians of the last %1 frames since the settings changed%2.").arg(frames).arg(cpu));
    // A pass median over fewer frames than the frame's: say so, or it reads larger than the frame.
    QStringList partial;
    for (std::size_t s = 0; s < std::min<std::size_t>(sides.size(), 2); ++s) {
        const FrameTimeHistory::Summary& x = sides[s];
        if (x.shadow.count > 0 && x.shadow.count < x.frame.count)
            partial << (sides.size() > 1 ? tr("Side %1: ").arg(QLatin1Char(char('A' + s))) : QString()) + FrameTimeHistory::explanation(x);
    }
    if (!partial.isEmpty())
        m_costInfo->setText(m_costInfo->text() + QLatin1Char(' ') + partial.join(QLatin1Char(' ')));
}

} // namespace shadowlab
