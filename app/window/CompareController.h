#pragma once

#include "Settings.h"
#include "SettingsChange.h"

#include <array>
#include <cstddef>

namespace shadowlab {

// The two sides of compare mode without widgets: their settings (always valid ones), the side
// selected for editing and whether compare mode is on, and the changes between them that keep
// one scene and one camera for both sides. Side A is 0, side B is 1. The window shows what
// this holds; the undo history records what its changes return.
class CompareController {
public:
    CompareController();    // both sides on the seed preset

    const Settings& settings(std::size_t side) const { return m_sides[side]; }
    Settings& settings(std::size_t side) { return m_sides[side]; }
    const std::array<Settings, 2>& sides() const { return m_sides; }
    std::array<Settings, 2>& sides() { return m_sides; }
    const Settings& selectedSettings() const { return m_sides[m_selected]; }

    bool isOn() const { return m_on; }
    void setOn(bool on) { m_on = on; }
    std::size_t selected() const { return m_selected; }
    void select(std::size_t side) { m_selected = side; }

    // Sets one side (the other follows onto its scene), returning what both were for the undo step.
    SettingsChange::Sides set(std::size_t side, const Settings& settings);
    SettingsChange::Sides copyAToB();
    SettingsChange::Sides swap();
    void setCamera(const CameraSettings& camera);
    // An undo step's `target` on the sides it holds; `from` is what they held (SettingsChange::Apply).
    void show(const SettingsChange::Sides& target, const SettingsChange::Sides& from);
    // Both lights turned by `radians` around the vertical through their targets.
    void turnLights(double radians);
    // The shared clock: both sides at `time`, or `seconds` on by their speed where the scene has a
    // clip of `clipLength` seconds (0: a still scene, whose clock stands).
    void setTime(double time);
    void advanceClock(double seconds, double clipLength);
    // The selected side's settings with its light turned around its target by these angles
    // (a Ctrl+drag in a scene view), short of the pole; not applied.
    Settings lightTurned(double azimuthDegrees, double elevationDegrees);

private:
    std::array<Settings, 2> m_sides;
    std::size_t m_selected = 0;
    bool m_on = false;
    double m_lightAzimuth = 0.0;    // kept while a drag passes over the light's pole
};

} // namespace shadowlab
