#include "AccuracyDock.h"

#include "AccuracyController.h"
#include "AccuracyMetricsPanel.h"
#include "SweepChartPanel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace shadowlab {

AccuracyDock::AccuracyDock(QWidget* parent) : QDockWidget(tr("Accuracy"), parent), m_controller(new AccuracyController(this))
{
    setObjectName(QStringLiteral("accuracyDock"));

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

    m_metrics = new AccuracyMetricsPanel;
    layout->addWidget(m_metrics);
    m_chart = new SweepChartPanel;
    layout->addWidget(m_chart, 1);

    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    setWidget(scroll);

    connect(m_compareButton, &QPushButton::clicked, m_controller, &AccuracyController::compare);
    connect(m_chart->sweepButton(), &QPushButton::clicked, m_controller, &AccuracyController::sweep);
    connect(m_cancelButton, &QPushButton::clicked, m_controller, &AccuracyController::cancel);
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

    m_metrics->showMeasurement(*m_controller);
    updateButtons();
}

AccuracyDock::~AccuracyDock() = default;

void AccuracyDock::setSettings(const Settings& settings)
{
    if (settings == m_controller->settings())
        return;
    m_controller->setSettings(settings);
    m_metrics->showMeasurement(*m_controller);
    updateOverlay();
    m_chart->setCurrentSettings(settings);
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
    const auto& measurement = m_controller->measurement();
    const QImage wanted = m_controller->measurementIsCurrent() && m_metrics->overlayWanted() ? measurement->errors : QImage();
    if (wanted.cacheKey() == m_overlay.cacheKey())
        return;
    m_overlay = wanted;
    emit errorOverlayChanged(m_overlay);
}

void AccuracyDock::updateButtons()
{
    const bool busy = m_controller->isBusy();
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
