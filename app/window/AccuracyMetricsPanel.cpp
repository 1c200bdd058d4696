#include "AccuracyMetricsPanel.h"

#include "NoteLabel.h"
#include "AccuracyController.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QVBoxLayout>

namespace shadowlab {

namespace {

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

} // namespace

AccuracyMetricsPanel::AccuracyMetricsPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
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
    m_flicker = valueLabel(QStringLiteral("flickerValue"));
    addMetricRow(hardGrid, tr("Flicker"), m_flicker,
                 tr("Shimmer: the light's maps follow a camera walking in steps of a third of a texel while the same "
                    "pixels are measured; the share of them whose shadow flips from one step to the next. Stabilised "
                    "maps should barely flicker."));
    layout->addWidget(hard);

    auto* area = new QGroupBox(tr("Area-light reference"));
    area->setObjectName(QStringLiteral("areaGroup"));
    area->setToolTip(tr("A disk light of radius light.radius, sampled with stratified rays: how close a "
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
    connect(m_overlayCheck, &QCheckBox::toggled, this, &AccuracyMetricsPanel::overlayToggled);
}

bool AccuracyMetricsPanel::overlayWanted() const
{
    return m_overlayCheck->isChecked();
}

void AccuracyMetricsPanel::showMeasurement(const AccuracyController& controller)
{
    const auto& measurement = controller.measurement();
    const bool have = measurement.has_value();
    const bool stale = have && !controller.measurementIsCurrent();
    auto put = [&](QLabel* label, const QString& text) {
        label->setText(have ? text : QStringLiteral("—"));
        label->setEnabled(!stale);
    };
    const ErrorMetrics hard = have ? measurement->hard : ErrorMetrics{};
    const ErrorMetrics area = have ? measurement->area : ErrorMetrics{};
    put(m_misclassified, percentText(hard.misclassified));
    put(m_falseShadow, percentText(hard.falseShadow));
    put(m_falseLight, percentText(hard.falseLight));
    put(m_hardMae, errorText(hard.mae));
    put(m_hardRmse, errorText(hard.rmse));
    put(m_flicker, have && measurement->flicker.frames > 1 ? percentText(measurement->flicker.flicker) : QStringLiteral("—"));
    const bool haveArea = have && area.pixels > 0;
    put(m_areaMae, haveArea ? errorText(area.mae) : QStringLiteral("—"));
    put(m_areaRmse, haveArea ? errorText(area.rmse) : QStringLiteral("—"));
    put(m_noiseFloor, haveArea ? errorText(measurement->areaNoiseFloor) : QStringLiteral("—"));

    if (!have) {
        m_referenceInfo->setText(tr("Not measured yet."));
        return;
    }
    const QSize size = measurement->errors.size();
    const QString reference = controller.lastReferenceReused() ? tr("reference reused") : tr("reference traced at %1").arg(raysText(controller.lastRaysPerSecond()));
    QString info = tr("%1×%2 px, %3 rays/px for the area light; %4.")
                       .arg(size.width())
                       .arg(size.height())
                       .arg(controller.referenceSamplesPerPixel())
                       .arg(reference);
    if (stale)
        info += QLatin1Char(' ') + tr("The view changed since: compare again.");
    m_referenceInfo->setText(info);
}

} // namespace shadowlab
