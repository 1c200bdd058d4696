#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QLocale;
class QSlider;

namespace shadowlab {

// A slider paired with a spin box for one number. The spin box holds the exact value and the
// whole allowed range; the slider spans the part of it worth dragging through (linear, or
// logarithmic for sizes that double). Only user edits emit valueEdited(); setValue() is silent.
class SliderSpinBox : public QWidget {
    Q_OBJECT

public:
    enum class Scale { Linear, Logarithmic };

    SliderSpinBox(double minimum, double maximum, int decimals, QWidget* parent = nullptr);

    // The part of the range the slider covers; values outside it still fit in the spin box. A
    // value set past one of its ends (setValue()) widens it so the value has room both ways; it
    // narrows back to this span when a value set returns inside.
    void setSliderSpan(double low, double high, Scale scale = Scale::Linear);
    // The span the slider covers now.
    double sliderLow() const { return m_spanLow; }
    double sliderHigh() const { return m_spanHigh; }
    void setSingleStep(double step);
    void setSuffix(const QString& suffix);

    double value() const;
    void setValue(double value);

    // Marks the field as holding a value that was refused (red frame) or clears it.
    void setInvalid(bool invalid);
    bool isInvalid() const { return m_invalid; }

    // `value` as a field with `decimals` shows it: at least two significant digits, so a
    // small value never reads as 0.00.
    static QString formatValue(double value, int decimals, const QLocale& locale);

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* spinBox() const { return m_spinBox; }

signals:
    void valueEdited(double value);

private:
    void updateSliderRange();
    void fitSpanTo(double value);
    int sliderPosition(double value) const;
    double sliderValue(int position) const;
    void onSliderMoved(int position);

    QSlider* m_slider;
    QDoubleSpinBox* m_spinBox;
    double m_spanLow;
    double m_spanHigh;
    double m_baseLow;               // the span as set (setSliderSpan())
    double m_baseHigh;
    Scale m_scale = Scale::Linear;
    bool m_integer;
    int m_decimals;                 // shown; the spin box holds the value exactly
    int m_steps = 1000;             // slider positions; one per value for short integer spans
    bool m_invalid = false;
    bool m_settingValue = false;
};

} // namespace shadowlab
