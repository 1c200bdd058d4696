#include "SliderSpinBox.h"

#include "WheelGuard.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Holds a value exactly (a spin box rounds what it is given to its decimals, so 0.00001 would
// become 0.00) and shows it with the field's decimals, or with two significant digits where
// those would read as zero.
class PreciseSpinBox : public QDoubleSpinBox {
public:
    PreciseSpinBox(int shownDecimals, QWidget* parent) : QDoubleSpinBox(parent), m_shown(shownDecimals)
    {
        setDecimals(m_shown == 0 ? 0 : kStoredDecimals);
    }

    QString textFromValue(double value) const override
    {
        // No group separators: "1275.36 wu" fits the field where "1,275.36 wu" is cut.
        QLocale plain = locale();
        plain.setNumberOptions(plain.numberOptions() | QLocale::OmitGroupSeparator);
        return SliderSpinBox::formatValue(value, m_shown, plain);
    }

    double valueFromText(const QString& text) const override
    {
        QString number = text;
        number.remove(suffix()).remove(prefix());
        bool ok = false;
        const double v = locale().toDouble(number.trimmed(), &ok);
        return ok ? v : value();
    }

    QValidator::State validate(QString& text, int& pos) const override
    {
        const QValidator::State state = QDoubleSpinBox::validate(text, pos);
        if (state != QValidator::Invalid || m_shown == 0)
            return state;
        // Typed in the form shown (1e-05): acceptable when it reads as a number in range.
        QString number = text;
        number.remove(suffix()).remove(prefix());
        bool ok = false;
        const double v = locale().toDouble(number.trimmed(), &ok);
        return ok && v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    }

private:
    static constexpr int kStoredDecimals = 12;
    int m_shown;
};

} // namespace

QString SliderSpinBox::formatValue(double value, int decimals, const QLocale& locale)
{
    if (decimals == 0 || value == 0.0)
        return locale.toString(value, 'f', decimals);
    const double magnitude = std::abs(value);
    // One significant digit or none at the field's decimals (0.00 for 0.00001): show two.
    if (magnitude < 10.0 * std::pow(10.0, -decimals)) {
        const int needed = int(std::ceil(-std::log10(magnitude))) + 1;
        if (needed > 6)
            return locale.toString(value, 'g', 2);
        return locale.toString(value, 'f', std::max(decimals, needed));
    }
    return locale.toString(value, 'f', decimals);
}

SliderSpinBox::SliderSpinBox(double minimum, double maximum, int decimals, QWidget* parent)
    : QWidget(parent), m_slider(new QSlider(Qt::Horizontal, this)), m_spinBox(new PreciseSpinBox(decimals, this)),
      m_spanLow(minimum), m_spanHigh(maximum), m_baseLow(minimum), m_baseHigh(maximum), m_integer(decimals == 0), m_decimals(decimals)
{
    m_spinBox->setRange(minimum, maximum);
    m_spinBox->setKeyboardTracking(false);   // apply a typed number on Enter, not per keystroke
    m_spinBox->setAccelerated(true);
    m_spinBox->setFixedWidth(118);
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
    m_baseLow = m_spanLow = low;
    m_baseHigh = m_spanHigh = high;
    m_scale = scale;
    fitSpanTo(value());
    updateSliderRange();
}

void SliderSpinBox::fitSpanTo(double value)
{
    // The span as set, or, for a value past one of its ends (a model's bias, a scene's light),
    // one widened round it so that the value sits in the middle with room both ways, the spin
    // box's range permitting.
    double low = m_baseLow, high = m_baseHigh;
    if (m_scale == Scale::Logarithmic && value > 0.0 && low > 0.0) {
        if (value > high)
            high = value * value / low;
        else if (value < low)
            low = value * value / high;
    } else if (m_scale == Scale::Linear) {
        if (value > high)
            high = value + (value - low);
        else if (value < low)
            low = value - (high - value);
    }
    m_spanLow = std::max(low, m_spinBox->minimum());
    m_spanHigh = std::min(high, m_spinBox->maximum());
    if (!(m_spanHigh > m_spanLow) || (m_scale == Scale::Logarithmic && !(m_spanLow > 0.0))) {
        m_spanLow = m_baseLow;
        m_spanHigh = m_baseHigh;
    }
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
    // The span follows a value that left it, and returns to the span as set once the value is
    // back inside that; a value that only moved within it leaves it be, so the user's own keys
    // and clicks never make the thumb jump. Never under a dragging hand.
    const double v = m_spinBox->value();
    const bool left = v < m_spanLow || v > m_spanHigh;
    const bool back = (m_spanLow != m_baseLow || m_spanHigh != m_baseHigh) && v >= m_baseLow && v <= m_baseHigh;
    if (!m_slider->isSliderDown() && (left || back)) {
        fitSpanTo(v);
        updateSliderRange();
        return;
    }
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
    // Round to the field's decimals (finer where the span is small), so a drag emits values
    // as they are shown.
    const double span = std::abs(m_spanHigh - m_spanLow);
    const int decimals = std::max(m_decimals, span > 0.0 ? int(std::ceil(-std::log10(span))) + 3 : m_decimals);
    const double unit = std::pow(10.0, std::min(decimals, 12));
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
