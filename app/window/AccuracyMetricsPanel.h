#pragma once

#include "FrameTimeHistory.h"

#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QGridLayout;
class QLabel;

namespace shadowlab {

class AccuracyController;

// The accuracy dock's numbers: error against the hard and the area reference, what the
// reference cost, what the frames cost, and the switch for the error overlay on the scene
// view. In compare mode each number shows for side A, side B and B − A, the difference
// coloured by which side is better and called "same" where it is within the measurement's
// noise.
class AccuracyMetricsPanel : public QWidget {
    Q_OBJECT

public:
    explicit AccuracyMetricsPanel(QWidget* parent = nullptr);

    // Shows what `controller` measured, each side greyed with a note when its view changed since.
    void showMeasurement(const AccuracyController& controller);
    // The frame times of each side (one, or A and B), medians over the window's last frames.
    void showFrameTimes(const std::vector<FrameTimeHistory::Summary>& sides, bool cpuTime);
    bool overlayWanted() const;
    // The overlay as a heat map of |V - V_ref| rather than the wrong pixels.
    bool heatWanted() const;

    // Frames each side needs before a difference in cost is told from noise (or called "same").
    static constexpr int kFramesToCompare = 5;

signals:
    void overlayToggled(bool on);

private:
    // The flicker row's zeros that measured nothing, the maps standing still through the walk.
    void markStillFlicker(const AccuracyController& controller);
    // The groups of rows: against the hard-shadow reference (with flicker), against the area
    // reference, and the frames' cost.
    QGroupBox* createHardGroup();
    QGroupBox* createAreaGroup();
    QGroupBox* createCostGroup();
    enum class Kind { Share, Error, Milliseconds, Count, Bytes };
    // A metric's name and its three values: A (or the only side), B, B − A.
    struct Row {
        Kind kind;
        std::array<QLabel*, 3> values{};
        QString toolTip;
    };
    Row* addRow(QGridLayout* grid, const QString& objectName, const QString& name, const QString& toolTip, Kind kind);
    // Fills `row` from both sides' values (nullopt: not measured); `noise` is the size of a
    // difference that says nothing.
    void put(Row& row, const std::array<std::optional<double>, 2>& values, const std::array<bool, 2>& stale, double noise);
    void setColumns(int sides);

    std::vector<QGridLayout*> m_grids;
    std::vector<QLabel*> m_headers;     // "A", "B", "B − A" over each grid
    int m_sides = 1;
    QCheckBox* m_overlayCheck = nullptr;
    QComboBox* m_overlayKind = nullptr;
    Row* m_misclassified = nullptr;
    Row* m_dssim = nullptr;
    Row* m_falseShadow = nullptr;
    Row* m_falseLight = nullptr;
    Row* m_hardMae = nullptr;
    Row* m_hardRmse = nullptr;
    Row* m_flicker = nullptr;
    Row* m_areaMae = nullptr;
    Row* m_areaRmse = nullptr;
    Row* m_noiseFloor = nullptr;
    Row* m_frame = nullptr;
    Row* m_shadowPass = nullptr;
    Row* m_taps = nullptr;              // counts of the measured frame, the same on any GPU
    Row* m_shadowSamples = nullptr;
    Row* m_cleared = nullptr;
    Row* m_mapMemory = nullptr;
    std::vector<std::unique_ptr<Row>> m_rows;
    QLabel* m_referenceInfo = nullptr;
    QLabel* m_costInfo = nullptr;
};

} // namespace shadowlab
