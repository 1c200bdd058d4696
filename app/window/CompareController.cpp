#include "CompareController.h"

#include "LightMath.h"
#include "SceneLibrary.h"
#include "SettingsError.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

CompareController::CompareController()
{
    m_sides[0] = presetSettings(QStringLiteral("seed"));
    m_sides[1] = m_sides[0];
}

SettingsChange::Sides CompareController::set(std::size_t side, const Settings& settings)
{
    const std::size_t i = side, other = 1 - i;
    SettingsChange::Sides before;
    before[i] = m_sides[i];
    // One scene for both sides: the other follows onto a new one with its techniques kept,
    // in the same undo step; where they do not fit the scene's light it takes this side's.
    if (settings.scene != m_sides[i].scene && m_sides[other].scene != settings.scene) {
        before[other] = m_sides[other];
        try {
            // The light and camera as this side has them; world-unit lengths from the scene's
            // defaults where this side measures its bias in another unit.
            Settings scene = settings;
            if (scene.bias.space != BiasSpace::World)
                scene.bias = presetSettings(settings.scene).bias;
            m_sides[other] = movedToScene(m_sides[other], scene);
            ensureValid(m_sides[other]);
        } catch (const SettingsError&) {
            m_sides[other] = settings;
        }
    }
    m_sides[i] = settings;
    m_sides[other].camera = settings.camera;
    m_sides[other].animation = settings.animation;     // one clock for both sides
    return before;
}

SettingsChange::Sides CompareController::copyAToB()
{
    const SettingsChange::Sides before{std::nullopt, m_sides[1]};
    m_sides[1] = m_sides[0];
    return before;
}

SettingsChange::Sides CompareController::swap()
{
    const SettingsChange::Sides before{m_sides[0], m_sides[1]};
    std::swap(m_sides[0], m_sides[1]);
    return before;
}

void CompareController::setCamera(const CameraSettings& camera)
{
    for (Settings& s : m_sides)
        s.camera = camera;
}

void CompareController::show(const SettingsChange::Sides& target, const SettingsChange::Sides& from)
{
    std::array<Settings, 2> next = m_sides;
    for (std::size_t i = 0; i < 2; ++i) {
        if (!target[i])
            continue;
        Settings s = *target[i];
        // The view stays where the user looks from, unless the step changes the scene: the
        // camera then goes back with it.
        if (!from[i] || from[i]->scene == s.scene)
            s.camera = m_sides[i].camera;
        // A light the animation moved since keeps its place unless this step moved it; so does
        // the clock, which plays on.
        if (from[i] && from[i]->light.position == s.light.position)
            s.light.position = m_sides[i].light.position;
        if (from[i] && from[i]->animation.time == s.animation.time)
            s.animation.time = m_sides[i].animation.time;
        try {
            ensureValid(s);
        } catch (const SettingsError&) {
            s.light.position = target[i]->light.position;   // the animated position does not fit the restored volume
        }
        next[i] = s;
    }
    m_sides = next;
    m_sides[0].camera = m_sides[1].camera = next[m_selected].camera;  // one camera for both sides
    m_sides[0].animation = m_sides[1].animation = next[m_selected].animation;
}

void CompareController::setTime(double time)
{
    for (Settings& settings : m_sides)
        settings.animation.time = time;
}

void CompareController::advanceClock(double seconds, double clipLength)
{
    if (!(clipLength > 0.0))
        return;
    // Wrapped at scene.time's range, not the clip's: objects whose cycles are shorter than the
    // longest (a city's vehicles) would jump at every loop of it.
    const AnimationSettings& clock = m_sides[m_selected].animation;
    setTime(std::fmod(clock.time + seconds * clock.speed, kMaxSceneTime));
}

void CompareController::turnLights(double radians)
{
    const double c = std::cos(radians), s = std::sin(radians);
    for (Settings& settings : m_sides) {
        const glm::dvec3 offset = settings.light.position - settings.light.target;
        settings.light.position = settings.light.target + glm::dvec3(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
    }
}

Settings CompareController::lightTurned(double azimuthDegrees, double elevationDegrees)
{
    Settings turned = m_sides[m_selected];
    LightAngles angles = lightAngles(turned.light.position, turned.light.target, m_lightAzimuth);
    angles.azimuth = std::remainder(angles.azimuth + azimuthDegrees, 360.0);
    // Short of the pole, so the next drag still knows which way round it is.
    angles.elevation = std::clamp(angles.elevation + elevationDegrees, -89.5, 89.5);
    m_lightAzimuth = angles.azimuth;
    turned.light.position = lightPosition(turned.light.target, angles);
    return turned;
}

} // namespace shadowlab
