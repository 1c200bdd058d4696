#pragma once

#include <QWidget>

class QCheckBox;
class QLabel;

namespace shadowlab {

class AccuracyController;

// The accuracy dock's numbers: error against the hard and the area reference, what the
// reference cost, and the switch for the error overlay on the scene view.
class AccuracyMetricsPanel : public QWidget {
    Q_OBJECT

public:
    explicit AccuracyMetricsPanel(QWidget* parent = nullptr);

    // Shows what `controller` measured, greyed with a note when the view changed since.
    void showMeasurement(const AccuracyController& controller);
    bool overlayWanted() const;

signals:
    void overlayToggled(bool on);

private:
    QCheckBox* m_overlayCheck = nullptr;
    QLabel* m_misclassified = nullptr;
    QLabel* m_falseShadow = nullptr;
    QLabel* m_falseLight = nullptr;
    QLabel* m_hardMae = nullptr;
    QLabel* m_hardRmse = nullptr;
    QLabel* m_areaMae = nullptr;
    QLabel* m_areaRmse = nullptr;
    QLabel* m_noiseFloor = nullptr;
    QLabel* m_flicker = nullptr;
    QLabel* m_referenceInfo = nullptr;
};

} // namespace shadowlab
