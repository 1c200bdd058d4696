#pragma once

#include "LightFitting.h"

#include <glm/vec3.hpp>

#include <optional>

#include "Settings.h"

#include <QDockWidget>

#include <vector>

class QCheckBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace shadowlab {

class PropertyFields;
class SliderSpinBox;

// The settings of one side (A or B): first one button per artifact preset (ArtifactPresets.h)
// with what to look for and the fix, then every key of settingKeys(), generated from the table
// and grouped as a shadow-mapping person thinks of them: Light, Shadow map, Bias, Filtering,
// Shading, Reference, Camera, Scene. The spin boxes take their ranges from the table (and the
// technique table for the filter's parameters) and the tooltips their help, so the dock and
// the CLI never disagree; a key added to the table gets a field without touching the dock.
// Each edit goes through applySetting() and validate(); an edit that makes the settings
// impossible (near >= far) is kept in its field, marked there with the reason, and not
// emitted, so the views keep the last valid image.
class PropertiesDock : public QDockWidget {
    Q_OBJECT

public:
    explicit PropertiesDock(QWidget* parent = nullptr);

    // Shows `settings` (valid ones) in every field and clears all error marks.
    void setSettings(const Settings& settings);
    // The settings as typed, valid or not.
    const Settings& pendingSettings() const { return m_pending; }
    // "A" or "B" in compare mode, empty otherwise.
    void setSideName(const QString& name);

    // Marks the field of `key` (from a failed render, say) with `message`.
    void showError(const QString& key, const QString& message);
    // The message shown at the field of `key`, empty when it holds an accepted value.
    QString errorText(const QString& key) const;
    // After a frame: with light.fit=scene the volume's fields show the fitted values, read-only;
    // the fit's warnings (a manual volume that cuts receivers) show at the fields they name.
    void showFit(const FittedLight& fit, const LightSettings& light);
    // The fit warning shown at `key`, empty when there is none.
    QString warningText(const QString& key) const;

    // The size of what casts shadows in the scene: sliders of world positions and lengths span
    // what fits it (a city's light sits hundreds of units out, a small model's a few), centred
    // on it; the spin boxes still take any allowed value.
    void setSceneSize(const glm::dvec3& centre, double radius);
    // The objects of the scene shown, for the lists that switch their casting and receiving.
    void setSceneObjects(const QStringList& tokens, const QStringList& labels);

    // Shows the light animation state without emitting animationChanged().
    void setAnimation(bool animate, double degreesPerSecond);
    // Takes `keys` (and the camera) from `applied` into the fields without touching the others,
    // so a moving light or camera does not undo an edit still being corrected.
    void updateFrom(const Settings& applied, const QStringList& keys);
    bool animateLight() const;
    // Applies the artifact preset `name` to this side (its scene, light and camera included)
    // and shows what to look for and a button that applies the fix.
    void applyPreset(const QString& name);
    // Shows preset `name`'s sentences and its fix button for settings that came from it some
    // other way (`shadowlab --preset`, `screenshot --preset`); changes no setting. Throws
    // SettingsError for an unknown name.
    void showPreset(const QString& name);
    void applyPresetFix();
    double animationSpeed() const;     // degrees per second around the target

signals:
    void settingsEdited(const shadowlab::Settings& settings);
    void warningsChanged(const QString& text);  // empty when there are none
    void animationChanged(bool animate, double degreesPerSecond);

private:
    QGridLayout* addGroup(const QString& title);
    void addPresetButtons();

    void edit(const QString& key, const QString& value);
    void editScene(const QString& name);
    void resetToDefaults();
    void accept(const Settings& candidate, const QString& editedKey);
    void clearErrors();
    void markError(const QString& key, const QString& message);
    void updateDependentRows();
    void hidePreset();
    // A note under `key` from the fit, unless the field shows a refusal.
    void showFitNote(const QString& key, const QString& text, const QString& style);

    QStringList m_warned;       // keys showing a fit warning
    std::optional<FittedLight> m_lastFit;   // of the newest frame

    Settings m_pending;
    PropertyFields* m_fields = nullptr;
    QLabel* m_sideLabel = nullptr;
    QCheckBox* m_animate = nullptr;
    SliderSpinBox* m_speed = nullptr;
    bool m_loading = false;
    QLabel* m_presetNote = nullptr;
    QPushButton* m_fixButton = nullptr;
    QString m_lastPreset;
    QString m_sideName;
};

} // namespace shadowlab
