#include "SliderSpinBox.h"

#include "WheelGuard.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace shadowlab {

SliderSpinBox::SliderSpinBox(double minimum, double maximum, int decimals, QWidget* parent)
    : QWidget(parent), m_slider(new QSlider(Qt::Horizontal, this)), m_spinBox(new QDoubleSpinBox(this)),
      m_spanLow(minimum), m_spanHigh(maximum), m_integer(decimals == 0)
{
    m_spinBox->setRange(minimum, maximum);
    m_spinBox->setDecimals(decimals);
    m_spinBox->setKeyboardTracking(false);   // apply a typed number on Enter, not per keystroke
    m_spinBox->setAccelerated(true);
    m_spinBox->setFixedWidth(112);
    m_spinBox->setAlignment(Qt::AlignRight);

    // The wheel scrolls the dock until the field is clicked or tabbed to.
    WheelGuard::guard(m_slider);
    WheelGuard::guard(m_spinBox);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spinBox);
    updateSliderRange();

    // valueChanged covers drags, clicks and keys on the slider; setValue() blocks it.
    connect(m_slider, &QSlider::valueChanged, this, &SliderSpinBox::onSliderMoved);
    connect(m_spinBox, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (m_settingValue)
            return;
        const QSignalBlocker block(m_slider);
        m_slider->setValue(sliderPosition(v));
        emit valueEdited(v);
    });
}

void SliderSpinBox::setSliderSpan(double low, double high, Scale scale)
{
    m_spanLow = low;
    m_spanHigh = high;
    m_scale = scale;
    updateSliderRange();
}

void SliderSpinBox::setSingleStep(double step)
{
    m_spinBox->setSingleStep(step);
    updateSliderRange();
}

void SliderSpinBox::updateSliderRange()
{
    // A short integer span gets one slider position per value, so every key press moves it.
    const double values = (m_spanHigh - m_spanLow) / m_spinBox->singleStep();
    m_steps = m_integer && m_scale == Scale::Linear && values <= 200.0 ? std::max(1, int(std::lround(values))) : 1000;
    const QSignalBlocker block(m_slider);
    m_slider->setRange(0, m_steps);
    m_slider->setSingleStep(1);
    m_slider->setPageStep(std::max(1, m_steps / 20));
    m_slider->setValue(sliderPosition(value()));
}

void SliderSpinBox::setSuffix(const QString& suffix)
{
    m_spinBox->setSuffix(suffix);
}

double SliderSpinBox::value() const
{
    return m_spinBox->value();
}

void SliderSpinBox::setValue(double value)
{
    m_settingValue = true;
    m_spinBox->setValue(value);
    m_settingValue = false;
    const QSignalBlocker block(m_slider);
    m_slider->setValue(sliderPosition(value));
}

void SliderSpinBox::setInvalid(bool invalid)
{
    if (invalid == m_invalid)
        return;
    m_invalid = invalid;
    m_spinBox->setStyleSheet(invalid ? QStringLiteral("QDoubleSpinBox { border: 2px solid #d9534f; border-radius: 3px; }") : QString());
}

int SliderSpinBox::sliderPosition(double value) const
{
    double t = 0.0;
    if (m_scale == Scale::Logarithmic)
        t = std::log(std::max(value, m_spanLow) / m_spanLow) / std::log(m_spanHigh / m_spanLow);
    else
        t = (value - m_spanLow) / (m_spanHigh - m_spanLow);
    return int(std::lround(std::clamp(t, 0.0, 1.0) * m_steps));
}

double SliderSpinBox::sliderValue(int position) const
{
    const double t = double(position) / m_steps;
    double v = m_scale == Scale::Logarithmic ? m_spanLow * std::pow(m_spanHigh / m_spanLow, t)
                                             : m_spanLow + t * (m_spanHigh - m_spanLow);
    if (m_integer && m_scale == Scale::Logarithmic)
        v = std::exp2(std::round(std::log2(v)));   // sizes that double snap to powers of two
    // Round to what the spin box shows, so the value emitted is the value displayed.
    const double unit = std::pow(10.0, m_spinBox->decimals());
    return std::round(v * unit) / unit;
}

void SliderSpinBox::onSliderMoved(int position)
{
    double v = sliderValue(position);
    if (m_integer && m_spinBox->singleStep() > 1.0) {
        // Integers with a step (odd kernel widths) snap to the spin box's grid.
        const double step = m_spinBox->singleStep();
        v = m_spinBox->minimum() + std::round((v - m_spinBox->minimum()) / step) * step;
    }
    if (v == m_spinBox->value())
        return;
    m_settingValue = true;
    m_spinBox->setValue(v);
    m_settingValue = false;
    emit valueEdited(m_spinBox->value());
}

} // namespace shadowlab
