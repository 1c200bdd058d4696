#include "PropertiesDock.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "ArtifactPresets.h"
#include "PropertyFields.h"
#include "SceneLibrary.h"
#include "SettingRelevance.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "SliderSpinBox.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {

namespace {

constexpr double kDefaultSpeed = 30.0;  // degrees per second

} // namespace

PropertiesDock::PropertiesDock(QWidget* parent) : QDockWidget(tr("Properties"), parent)
{
    setObjectName(QStringLiteral("PropertiesDock"));
    setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetFloatable);

    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->setContentsMargins(8, 6, 8, 8);
    column->setSpacing(8);
    m_sideLabel = new QLabel;
    m_sideLabel->setObjectName(QStringLiteral("sideLabel"));
    m_sideLabel->setVisible(false);
    m_sideLabel->setWordWrap(true);     // whole at the dock's narrowest
    column->addWidget(m_sideLabel);

    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    setWidget(scroll);

    addPresetButtons();

    m_fields = new PropertyFields(m_pending, this);
    connect(m_fields, &PropertyFields::edited, this, &PropertiesDock::edit);
    // Every key of the table gets a field, in the table's order, in its group.
    std::map<QString, QGridLayout*> groups;
    for (const QString& title : settingGroups())
        groups[title] = addGroup(tr(title.toUtf8().constData()));
    for (const SettingKey& info : settingKeys()) {
        const auto group = groups.find(info.presentation.group);
        QGridLayout* grid = group != groups.end() ? group->second : groups.at(settingGroups().back());
        if (info.key == u"light.position")
            m_fields->addDirection(grid);
        if (info.type == u"vec3")
            m_fields->addVector(grid, info.key);
        else if (info.type == u"choice")
            m_fields->addChoice(grid, info.key);
        else if (info.type == u"bool")
            m_fields->addBool(grid, info.key, PropertyFields::look(info.key).label);
        else if (info.type == u"objects")
            m_fields->addObjects(grid, info.key);
        else
            m_fields->addNumber(grid, info.key);
    }

    QGridLayout* light = groups.at(QStringLiteral("Light"));
    m_animate = new QCheckBox(tr("Animate around the target"));
    m_animate->setObjectName(QStringLiteral("animateLight"));
    m_animate->setToolTip(tr("Circles the light around its target: watch acne crawl and shadows swing as the angle changes"));
    m_speed = new SliderSpinBox(-360.0, 360.0, 0);
    m_speed->setObjectName(QStringLiteral("animationSpeed"));
    m_speed->setSuffix(QStringLiteral("°/s"));
    m_speed->setValue(kDefaultSpeed);
    m_speed->setToolTip(tr("Degrees per second around the vertical axis through the target; negative turns the other way"));
    const int animateRow = light->rowCount();
    light->addWidget(m_animate, animateRow, 0, 1, 2);
    light->addWidget(new QLabel(tr("Speed")), animateRow + 1, 0);
    light->addWidget(m_speed, animateRow + 1, 1);
    connect(m_animate, &QCheckBox::toggled, this, [this](bool on) { emit animationChanged(on, m_speed->value()); });
    connect(m_speed, &SliderSpinBox::valueEdited, this, [this](double v) { emit animationChanged(m_animate->isChecked(), v); });

    QGridLayout* scene = groups.at(QStringLiteral("Scene"));
    auto* reset = new QPushButton(tr("Reset to Defaults"));
    reset->setObjectName(QStringLiteral("resetToDefaults"));
    reset->setToolTip(tr("Every setting of this side back to the scene preset's; the camera stays"));
    scene->addWidget(reset, scene->rowCount(), 0, 1, 2, Qt::AlignRight);
    connect(reset, &QPushButton::clicked, this, &PropertiesDock::resetToDefaults);

    column->addStretch(1);
    content->setMinimumWidth(320);
    setSettings(m_pending);
}

void PropertiesDock::addPresetButtons()
{
    // One click per artifact: the preset's settings on this side, and what to look for.
    auto* box = new QGroupBox(tr("Show an artifact"));
    box->setObjectName(QStringLiteral("artifactPresets"));
    auto* grid = new QGridLayout(box);
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(4);
    int i = 0;
    for (const ArtifactPreset& preset : artifactPresets()) {
        auto* button = new QPushButton(preset.title);
        button->setObjectName(QStringLiteral("preset.") + preset.name);
        button->setToolTip(QStringLiteral("<p><b>%1</b> (--preset %2)</p><p>%3</p><p><i>Fix:</i> %4</p>")
                               .arg(preset.title.toHtmlEscaped(), preset.name, preset.lookFor.toHtmlEscaped(), preset.fix.toHtmlEscaped()));
        connect(button, &QPushButton::clicked, this, [this, name = preset.name] { applyPreset(name); });
        grid->addWidget(button, i / 2, i % 2);
        ++i;
    }
    m_presetNote = new QLabel;
    m_presetNote->setObjectName(QStringLiteral("presetNote"));
    m_presetNote->setWordWrap(true);
    m_presetNote->setVisible(false);
    grid->addWidget(m_presetNote, (i + 1) / 2, 0, 1, 2);
    m_fixButton = new QPushButton(tr("Apply the Fix"));
    m_fixButton->setObjectName(QStringLiteral("presetFix"));
    m_fixButton->setVisible(false);
    connect(m_fixButton, &QPushButton::clicked, this, &PropertiesDock::applyPresetFix);
    grid->addWidget(m_fixButton, (i + 1) / 2 + 1, 0, 1, 2, Qt::AlignRight);
    auto* column = static_cast<QVBoxLayout*>(static_cast<QScrollArea*>(widget())->widget()->layout());
    column->addWidget(box);
}

void PropertiesDock::showPreset(const QString& name)
{
    const ArtifactPreset& preset = artifactPreset(name);
    m_presetNote->setText(tr("<b>%1.</b> %2<br><i>Fix:</i> %3").arg(preset.title.toHtmlEscaped(), preset.lookFor.toHtmlEscaped(),
                                                                     preset.fix.toHtmlEscaped()));
    m_presetNote->setVisible(true);
    m_fixButton->setText(tr("Apply the Fix"));
    m_fixButton->setVisible(true);
    m_fixButton->setEnabled(true);
    m_lastPreset = preset.name;
}

void PropertiesDock::applyPreset(const QString& name)
{
    Settings candidate;
    try {
        candidate = applyArtifactPreset(artifactPreset(name), m_pending);
    } catch (const SettingsError& e) {
        markError(QStringLiteral("scene"), QString::fromStdString(e.what()));
        return;
    }
    setSettings(candidate);
    showPreset(name);   // after: a preset on another scene would otherwise withdraw its own note
    accept(candidate, QString());
}

void PropertiesDock::applyPresetFix()
{
    Settings candidate = m_pending;
    try {
        candidate = settingsFromJson(artifactPreset(m_lastPreset).fixSettings, m_pending);
    } catch (const SettingsError& e) {
        markError(e.key(), QString::fromStdString(e.what()));
        return;
    }
    // Disabled with the focus on it, the button would pass the focus on down the dock, and
    // the scroll area would follow it away from the explanation and the fields just changed.
    auto* scroll = static_cast<QScrollArea*>(widget());
    const int scrolled = scroll->verticalScrollBar()->value();
    m_fixButton->clearFocus();
    m_fixButton->setEnabled(false);
    m_fixButton->setText(tr("Fix Applied"));
    setSettings(candidate);
    accept(candidate, QString());
    scroll->verticalScrollBar()->setValue(scrolled);
}

QGridLayout* PropertiesDock::addGroup(const QString& title)
{
    auto* box = new QGroupBox(title);
    auto* grid = new QGridLayout(box);
    grid->setColumnStretch(1, 1);
    grid->setHorizontalSpacing(10);
    grid->setVerticalSpacing(4);
    auto* column = static_cast<QVBoxLayout*>(static_cast<QScrollArea*>(widget())->widget()->layout());
    column->addWidget(box);
    return grid;
}

void PropertiesDock::setSettings(const Settings& settings)
{
    // A preset's sentences are about its scene: on another one they no longer say what is shown.
    if (settings.scene != m_pending.scene)
        hidePreset();
    m_pending = settings;
    m_loading = true;
    m_fields->loadAll(settings);
    m_loading = false;
    clearErrors();
    updateDependentRows();
    // Settings that render the same frame again draw none: show the last fit at once.
    if (m_lastFit)
        showFit(*m_lastFit, settings.light);
}

void PropertiesDock::hidePreset()
{
    m_presetNote->setVisible(false);
    m_fixButton->setVisible(false);
    m_lastPreset.clear();
}

void PropertiesDock::setSideName(const QString& name)
{
    if (name != m_sideName)
        hidePreset();   // they were about the other side's settings
    m_sideName = name;
    m_sideLabel->setVisible(!name.isEmpty());
    m_sideLabel->setText(tr("<b>Editing side %1</b> — click a view to edit the other").arg(name));
}

void PropertiesDock::edit(const QString& key, const QString& value)
{
    if (m_loading)
        return;
    if (key == u"scene") {
        editScene(value);
        return;
    }
    Settings candidate = m_pending;
    try {
        applySetting(candidate, key, value);
    } catch (const SettingsError& e) {
        markError(key, QString::fromStdString(e.what()));
        return;
    }
    accept(candidate, key);
}

void PropertiesDock::editScene(const QString& name)
{
    // As the key's help says: a preset brings its own light and camera.
    Settings candidate;
    try {
        candidate = movedToScene(m_pending, presetSettings(name));
    } catch (const SettingsError& e) {
        markError(QStringLiteral("scene"), QString::fromStdString(e.what()));
        return;
    }
    setSettings(candidate);
    accept(candidate, QStringLiteral("scene"));
}

void PropertiesDock::resetToDefaults()
{
    Settings defaults;
    try {
        defaults = presetSettings(m_pending.scene);
    } catch (const SettingsError& e) {
        markError(QStringLiteral("scene"), QString::fromStdString(e.what()));   // its file changed or went away
        return;
    }
    defaults.camera = m_pending.camera;
    setSettings(defaults);
    accept(defaults, QString());
}

void PropertiesDock::accept(const Settings& candidate, const QString& editedKey)
{
    m_pending = candidate;
    // light.type and light.projection set each other, and the direction and the position are
    // two views of light.position (one of them hidden): every one shows the result.
    for (const QString linked : {"light.type", "light.projection", "light.position", "light.direction.azimuth"})
        m_fields->load(linked, m_pending);
    clearErrors();
    updateDependentRows();
    QStringList warnings;
    bool valid = true;
    for (const SettingsIssue& issue : validate(candidate)) {
        if (issue.severity == SettingsIssue::Severity::Error) {
            valid = false;
            markError(issue.key, issue.message);
        } else {
            warnings << issue.key + QStringLiteral(": ") + issue.message;
        }
    }
    if (!valid) {
        // A cross-field rule names one field (near >= far names far); the one just edited
        // says so too, so the reason is where the user is looking.
        if (!editedKey.isEmpty() && errorText(editedKey).isEmpty()) {
            for (const SettingsIssue& issue : validate(candidate)) {
                if (issue.severity == SettingsIssue::Severity::Error) {
                    markError(editedKey, issue.key + QStringLiteral(": ") + issue.message);
                    break;
                }
            }
        }
        return;
    }
    emit warningsChanged(warnings.join(QStringLiteral("; ")));
    emit settingsEdited(candidate);
}

void PropertiesDock::clearErrors()
{
    m_fields->clearErrors();
}

void PropertiesDock::markError(const QString& key, const QString& message)
{
    // A directional light's place is edited, and its refusals shown, at its direction's fields.
    if (key == u"light.position" && m_pending.light.type == LightType::Directional) {
        markError(QStringLiteral("light.direction.distance"), message.startsWith(key + QStringLiteral(": ")) ? message : key + QStringLiteral(": ") + message);
        return;
    }
    // The message without the "key: " prefix SettingsError puts in front: the field is the key.
    QString text = message;
    if (text.startsWith(key + QStringLiteral(": ")))
        text = text.mid(key.size() + 2);
    if (!m_fields->markRefused(key, text))
        return;
    m_warned.removeAll(key);
    if (const std::vector<QWidget*> row = m_fields->row(key); !row.empty())
        static_cast<QScrollArea*>(widget())->ensureWidgetVisible(row.back());
}

void PropertiesDock::showError(const QString& key, const QString& message)
{
    markError(key, message);
}

QString PropertiesDock::errorText(const QString& key) const
{
    const QLabel* note = m_fields->note(key);
    return note ? note->text() : QString();
}

namespace {

// The light-volume keys that light.fit=scene computes instead of reading.
const char* const kFittedKeys[] = {"light.extent", "light.fov", "light.near", "light.far"};

// The fitted volume in the units of the keys: half-size or full angle, and near and far as
// distances from the light's position along its direction.
Settings fittedVolume(const LightVolume& v, const LightSettings& light, Settings shown)
{
    const double along = glm::dot(v.origin - light.position, v.direction);
    if (v.perspective)
        shown.light.fov = glm::degrees(2.0 * std::atan(std::max({-v.left, v.right, -v.bottom, v.top})));
    else
        shown.light.extent = 0.5 * std::max(v.width(), v.height());
    shown.light.nearPlane = v.nearPlane + along;
    shown.light.farPlane = v.farPlane + along;
    return shown;
}

} // namespace

void PropertiesDock::showFit(const FittedLight& fit, const LightSettings& light)
{
    if (!m_lastFit || &fit != &*m_lastFit)
        m_lastFit = fit;
    // Last frame's warnings off first; the fields keep their refusals (red) if any.
    for (const QString& key : std::as_const(m_warned)) {
        if (QLabel* note = m_fields->note(key); note && !note->property("refusal").toBool()) {
            note->clear();
            note->setVisible(false);
        }
    }
    m_warned.clear();
    const bool fitted = light.fit == LightFit::Scene;
    // A spot light's field of view is its cone, which the fitted map lies inside: it stays
    // the user's to set, whatever the fit.
    const bool spot = light.type == LightType::Spot;
    const auto isFitted = [&](const char* key) { return fitted && !(spot && qstrcmp(key, "light.fov") == 0); };

    for (const char* key : kFittedKeys) {
        for (QWidget* w : m_fields->row(QString::fromLatin1(key))) {
            w->setEnabled(!isFitted(key));
            w->setToolTip(isFitted(key) ? tr("Fitted to the scene (read-only): set Volume to manual to set it by hand")
                                        : PropertyFields::toolTip(QString::fromLatin1(key)));
        }
    }
    if (fitted && fit.fitted) {
        const Settings shown = fittedVolume(fit.volume, light, m_pending);
        const bool loading = m_loading;
        m_loading = true;
        for (const char* key : kFittedKeys)
            m_fields->load(QString::fromLatin1(key), isFitted(key) ? shown : m_pending);
        m_loading = loading;
        // What the fit chose inside the cone, said under the cone's own field.
        if (spot && fit.volume.perspective)
            showFitNote(QStringLiteral("light.fov"), tr("The cone; the map fitted to what it lights spans %1°").arg(shown.light.fov, 0, 'f', 1),
                        QStringLiteral("color: palette(mid);"));
    } else if (!fitted) {
        const bool loading = m_loading;
        m_loading = true;
        for (const char* key : kFittedKeys)
            m_fields->load(QString::fromLatin1(key), m_pending);
        m_loading = loading;
    }
    for (const SettingsIssue& issue : fitWarnings(fit))
        showFitNote(issue.key, issue.message, QStringLiteral("color: #b8860b;"));
}

void PropertiesDock::showFitNote(const QString& key, const QString& text, const QString& style)
{
    QLabel* note = m_fields->note(key);
    if (!note || note->property("refusal").toBool())
        return;
    note->setText(text);
    note->setStyleSheet(style);
    note->setVisible(true);
    m_warned << key;
}

QString PropertiesDock::warningText(const QString& key) const
{
    return m_warned.contains(key) ? errorText(key) : QString();
}

void PropertiesDock::updateDependentRows()
{
    // Show only what the current technique uses: extent for an ortho light, field of view for
    // a perspective one; a filter's parameters only while a filter that reads them is selected.
    const bool ortho = m_pending.light.projection == LightProjection::Ortho;
    for (QWidget* w : m_fields->row(QStringLiteral("light.extent")))
        w->setVisible(ortho);
    for (QWidget* w : m_fields->row(QStringLiteral("light.fov")))
        w->setVisible(!ortho);
    // The cone's falloff for a spot light; cascades for a directional one, and their split
    // settings once there are several.
    for (QWidget* w : m_fields->row(QStringLiteral("light.falloff")))
        w->setVisible(m_pending.light.type == LightType::Spot);
    const bool directional = m_pending.light.type == LightType::Directional;
    // A direction for a directional light, a place for the others.
    for (QWidget* w : m_fields->row(QStringLiteral("light.position")))
        w->setVisible(!directional);
    for (const QString key : {"light.direction.azimuth", "light.direction.elevation", "light.direction.distance"}) {
        for (QWidget* w : m_fields->row(key))
            w->setVisible(directional);
    }
    // Every field the current settings leave unread is greyed, its tooltip saying why and what
    // would make it count (the fitted volume's fields say so in showFit()).
    for (const SettingKey& info : settingKeys()) {
        if (std::any_of(std::begin(kFittedKeys), std::end(kFittedKeys), [&](const char* k) { return info.key == QLatin1String(k); }))
            continue;
        const QString why = ignoredBecause(m_pending, info.key);
        for (QWidget* w : m_fields->row(info.key)) {
            // The reason goes after the field's own tooltip (which names its key first), and
            // comes off again. A field that rewrote its tooltip since (a filter's help on a load)
            // has lost the reason: what it holds now is its own.
            const QString shown = w->property("shownToolTip").toString();
            const QString own = !shown.isEmpty() && w->toolTip() == shown ? w->property("ownToolTip").toString() : w->toolTip();
            if (!why.isEmpty()) {
                const QString tip = QStringLiteral("%1<p><b>Not read now:</b> %2</p>").arg(own, why.toHtmlEscaped());
                w->setEnabled(false);
                w->setToolTip(tip);
                w->setProperty("ownToolTip", own);
                w->setProperty("shownToolTip", tip);
            } else if (!shown.isEmpty()) {
                w->setEnabled(true);
                w->setToolTip(own);
                w->setProperty("ownToolTip", QVariant());
                w->setProperty("shownToolTip", QVariant());
            }
        }
    }
}

void PropertiesDock::setSceneObjects(const QStringList& tokens, const QStringList& labels)
{
    m_fields->setObjects(tokens, labels);
}

void PropertiesDock::setSceneSize(const glm::dvec3& centre, double radius)
{
    // The presentation's spans are the seed's; other scenes scale them by their size.
    static const double seedRadius = [] {
        const Bounds b = buildScene(QStringLiteral("seed")).modelBounds();
        return glm::length(b.max - b.min) * 0.5;
    }();
    if (!(radius > 0.0) || !std::isfinite(radius))
        return;
    const double scale = radius / seedRadius;
    for (const SettingKey& info : settingKeys()) {
        const PropertyFields::Look look = PropertyFields::look(info.key);
        if (look.unit != u" wu")
            continue;
        if (info.type == u"vec3") {
            for (int i = 0; i < 3; ++i) {
                auto* box = findChild<SliderSpinBox*>(info.key + QLatin1Char('.') + QLatin1Char("xyz"[i]));
                if (!box)
                    continue;
                // Positions round the scene's centre; a light's or camera's target within it.
                box->setSliderSpan(centre[i] + look.sliderLow * scale, centre[i] + look.sliderHigh * scale);
                box->setSingleStep(std::max(1e-6, 0.1 * scale));
            }
        } else if (auto* box = findChild<SliderSpinBox*>(info.key)) {
            box->setSliderSpan(look.sliderLow * scale, look.sliderHigh * scale, look.scale);
            box->setSingleStep(std::max(1e-6, (look.sliderHigh - look.sliderLow) * scale / 200.0));
        }
    }
    if (auto* distance = findChild<SliderSpinBox*>(QStringLiteral("light.distance")))
        distance->setSliderSpan(0.5 * scale, 20.0 * scale, SliderSpinBox::Scale::Logarithmic);
}

void PropertiesDock::setAnimation(bool animate, double degreesPerSecond)
{
    const QSignalBlocker block(m_animate);
    m_animate->setChecked(animate);
    m_speed->setValue(degreesPerSecond);
}

void PropertiesDock::updateFrom(const Settings& applied, const QStringList& keys)
{
    m_pending.camera = applied.camera;
    m_loading = true;
    for (const QString& key : {QStringLiteral("camera.position"), QStringLiteral("camera.target"), QStringLiteral("camera.fov")})
        m_fields->load(key, m_pending);
    for (const QString& key : keys) {
        applySetting(m_pending, key, settingValue(applied, key));
        m_fields->load(key, m_pending);
        if (key.startsWith(u"light.position") || key.startsWith(u"light.target"))
            m_fields->load(QStringLiteral("light.direction.azimuth"), m_pending);
    }
    m_loading = false;
}

bool PropertiesDock::animateLight() const
{
    return m_animate->isChecked();
}

double PropertiesDock::animationSpeed() const
{
    return m_speed->value();
}

} // namespace shadowlab
