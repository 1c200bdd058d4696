#include "PropertiesDock.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "ArtifactPresets.h"
#include "LightMath.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "SliderSpinBox.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {

namespace {

// How a key is shown, from its presentation in the settings table (SettingsKeys.h).
struct Look {
    QString label;
    QString unit;
    int decimals;
    double sliderLow;
    double sliderHigh;
    SliderSpinBox::Scale scale = SliderSpinBox::Scale::Linear;
};

Look presentation(const QString& key)
{
    const SettingKey* info = findSettingKey(key);
    if (info && !info->presentation.label.isEmpty()) {
        const SettingPresentation& p = info->presentation;
        return {p.label, p.unit, p.decimals, p.sliderLow, p.sliderHigh,
                p.logarithmic ? SliderSpinBox::Scale::Logarithmic : SliderSpinBox::Scale::Linear};
    }
    // A key added to the table without a presentation still gets a field: named by its key,
    // its whole range on the slider.
    return {key, QString(), 3, info ? std::max(info->minimum, -1e3) : 0.0, info ? std::min(info->maximum, 1e3) : 1.0};
}

const SettingKey& keyInfo(const QString& key)
{
    const SettingKey* info = findSettingKey(key);
    if (!info)
        throw SettingsError(key, QStringLiteral("unknown setting"));
    return *info;
}

const ShadowTechnique* techniqueNamed(const QString& key)
{
    const std::vector<ShadowTechnique>& all = shadowTechniques();
    const auto it = std::find_if(all.begin(), all.end(), [&](const ShadowTechnique& t) { return t.key == key; });
    return it == all.end() ? nullptr : &*it;
}

// One filter's tooltip: its name, and a sentence or two of what it does and what it costs.
QString choiceTooltip(const ShadowTechnique& technique)
{
    return QStringLiteral("<p><b>%1</b> (filter.mode=%2)</p><p>%3</p>").arg(technique.label.toHtmlEscaped(), technique.key, technique.help.toHtmlEscaped());
}

// Under the chosen filter's tooltip: where the others are explained, not all twelve at once.
QString filterTooltipTail(const SettingKey& info)
{
    return QStringLiteral("<p><i>%1</i></p><p>Allowed: %2</p>")
        .arg(QCoreApplication::translate("PropertiesDock", "Open the list and hover a filter for what it does and costs; Help → Shadow "
                                                           "Artifacts compares them."),
             info.range.toHtmlEscaped());
}

QString tooltipFor(const SettingKey& info)
{
    return QStringLiteral("<p><b>%1</b> — %2</p><p>Allowed: %3</p>").arg(info.key, info.help.toHtmlEscaped(), info.range.toHtmlEscaped());
}

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

    // Every key of the table gets a field, in the table's order, in its group.
    std::map<QString, QGridLayout*> groups;
    for (const QString& title : settingGroups())
        groups[title] = addGroup(tr(title.toUtf8().constData()));
    for (const SettingKey& info : settingKeys()) {
        const auto group = groups.find(info.presentation.group);
        QGridLayout* grid = group != groups.end() ? group->second : groups.at(settingGroups().back());
        if (info.key == u"light.position")
            addDirection(grid);
        if (info.type == u"vec3")
            addVector(grid, info.key);
        else if (info.type == u"choice")
            addChoice(grid, info.key);
        else if (info.type == u"bool")
            addBool(grid, info.key, presentation(info.key).label);
        else
            addNumber(grid, info.key);
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

void PropertiesDock::addRow(QGridLayout* grid, const QString& label, const QString& rangeText, QWidget* editor, Field field)
{
    const int row = grid->rowCount();
    auto* name = new QLabel(rangeText.trimmed().isEmpty() ? label
                                                : QStringLiteral("%1<br><span style='color:gray; font-size:small'>%2</span>")
                                                      .arg(label.toHtmlEscaped(), rangeText.trimmed().toHtmlEscaped()));
    name->setToolTip(editor->toolTip());
    grid->addWidget(name, row, 0);
    grid->addWidget(editor, row, 1);
    field.error = new QLabel;
    field.error->setObjectName(field.key + QStringLiteral(".error"));
    field.error->setWordWrap(true);
    field.error->setStyleSheet(QStringLiteral("color: #d9534f;"));
    field.error->setVisible(false);
    grid->addWidget(field.error, row + 1, 0, 1, 2);
    m_rows[field.key] = {name, editor};
    m_fields.insert(field.key, std::move(field));
}

void PropertiesDock::addNumber(QGridLayout* grid, const QString& key)
{
    const SettingKey& info = keyInfo(key);
    const Look look = presentation(key);
    // Open ends of a range ((0, 180)) become the nearest value the spin box can show.
    const double step = std::pow(10.0, -look.decimals);
    const bool loOpen = info.range.startsWith(QLatin1Char('('));
    const bool hiOpen = info.range.contains(QLatin1Char(')'));
    auto* editor = new SliderSpinBox(info.minimum + (loOpen ? step : 0.0), info.maximum - (hiOpen ? step : 0.0), look.decimals);
    editor->setObjectName(key);
    editor->setSuffix(look.unit);
    editor->setSliderSpan(look.sliderLow, look.sliderHigh, look.scale);
    if (info.range.contains(QStringLiteral("odd")))
        editor->setSingleStep(2.0);
    else if (look.decimals > 0)
        editor->setSingleStep(std::max(step, (look.sliderHigh - look.sliderLow) / 200.0));
    editor->setToolTip(tooltipFor(info));
    const bool integer = info.type == u"integer";
    connect(editor, &SliderSpinBox::valueEdited, this, [this, key, integer](double v) {
        edit(key, integer ? QString::number(qRound(v)) : QString::number(v, 'g', 12));
    });
    Field field{key, nullptr, {editor}, [editor, key](const Settings& s) { editor->setValue(settingValue(s, key).toDouble()); }};
    // Huge limits ([-1e7, 1e7]) only say "any sensible number": the tooltip still has them.
    const bool telling = std::max(std::abs(info.minimum), std::abs(info.maximum)) < 1e5;
    addRow(grid, look.label, (telling ? info.range : QString()) + look.unit, editor,
           std::move(field));
}

void PropertiesDock::addVector(QGridLayout* grid, const QString& key)
{
    const SettingKey& info = keyInfo(key);
    const Look look = presentation(key);
    auto* editor = new QWidget;
    auto* layout = new QVBoxLayout(editor);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    std::vector<QWidget*> parts;
    std::vector<SliderSpinBox*> boxes;
    for (int i = 0; i < 3; ++i) {
        const QString axis = QString(QLatin1Char("xyz"[i]));
        auto* box = new SliderSpinBox(info.minimum, info.maximum, look.decimals);
        box->setObjectName(key + QLatin1Char('.') + axis);
        box->setSuffix(look.unit);
        box->setSliderSpan(look.sliderLow, look.sliderHigh);
        box->setSingleStep(0.1);
        box->setToolTip(tooltipFor(info));
        box->spinBox()->setPrefix(axis + QStringLiteral("  "));
        layout->addWidget(box);
        parts.push_back(box);
        boxes.push_back(box);
        // A component edit is written as the whole vector, through the same parser as --set.
        connect(box, &SliderSpinBox::valueEdited, this, [this, key, i](double v) {
            QStringList xyz = settingValue(m_pending, key).split(QLatin1Char(','));
            xyz[i] = QString::number(v, 'g', 12);
            edit(key, xyz.join(QLatin1Char(',')));
        });
    }
    editor->setToolTip(tooltipFor(info));
    Field field{key, nullptr, parts, [boxes, key](const Settings& s) {
                    const QStringList xyz = settingValue(s, key).split(QLatin1Char(','));
                    for (int i = 0; i < 3; ++i)
                        boxes[std::size_t(i)]->setValue(xyz.value(i).toDouble());
                }};
    addRow(grid, look.label, QString(), editor, std::move(field));
}

void PropertiesDock::addDirection(QGridLayout* grid)
{
    // A directional light is a direction: azimuth and elevation around its target, and the
    // distance its manual volume's near and far count from. All three edit light.position.
    auto* azimuth = new SliderSpinBox(-180.0, 180.0, 1);
    auto* elevation = new SliderSpinBox(-90.0, 90.0, 1);
    auto* distance = new SliderSpinBox(1e-6, 1e7, 2);
    azimuth->setObjectName(QStringLiteral("light.azimuth"));
    elevation->setObjectName(QStringLiteral("light.elevation"));
    distance->setObjectName(QStringLiteral("light.distance"));
    azimuth->setSuffix(QStringLiteral("°"));
    elevation->setSuffix(QStringLiteral("°"));
    distance->setSuffix(QStringLiteral(" wu"));
    elevation->setSliderSpan(0.0, 90.0);
    distance->setSliderSpan(0.5, 20.0, SliderSpinBox::Scale::Logarithmic);
    azimuth->setToolTip(tr("<p><b>Azimuth</b> — the light's direction around the vertical through its target, in degrees: 0 from +z, "
                           "90 from +x. Sets light.position. Ctrl+drag in the scene view turns the light.</p>"));
    elevation->setToolTip(tr("<p><b>Elevation</b> — how high the light stands above the horizon, in degrees: 90 straight above. "
                             "Sets light.position. Ctrl+drag in the scene view turns the light.</p>"));
    distance->setToolTip(tr("<p><b>Distance</b> from light.target to light.position, in world units: where a manual volume's near and "
                            "far count from; the direction alone decides the shadows.</p>"));
    const auto apply = [this, azimuth, elevation, distance] {
        const LightAngles angles{azimuth->value(), elevation->value(), distance->value()};
        const glm::dvec3 p = lightPosition(m_pending.light.target, angles);
        m_lastAzimuth = angles.azimuth;
        edit(QStringLiteral("light.position"), QStringLiteral("%1,%2,%3").arg(p.x, 0, 'g', 12).arg(p.y, 0, 'g', 12).arg(p.z, 0, 'g', 12));
    };
    for (SliderSpinBox* box : {azimuth, elevation, distance})
        connect(box, &SliderSpinBox::valueEdited, this, apply);
    const auto load = [this, azimuth, elevation, distance](const Settings& s) {
        const LightAngles angles = lightAngles(s.light.position, s.light.target, m_lastAzimuth);
        m_lastAzimuth = angles.azimuth;
        azimuth->setValue(angles.azimuth);
        elevation->setValue(angles.elevation);
        distance->setValue(angles.distance);
    };
    const std::pair<QString, SliderSpinBox*> rows[] = {{tr("Azimuth"), azimuth}, {tr("Elevation"), elevation}, {tr("Distance"), distance}};
    for (const auto& [label, box] : rows) {
        // Each its own row (hidden together for spot and point lights); the first one loads all three.
        const QString key = QStringLiteral("light.direction.") + box->objectName().section(QLatin1Char('.'), 1);
        addRow(grid, label, QString(), box, Field{key, nullptr, {box}, box == azimuth ? std::function<void(const Settings&)>(load) : [](const Settings&) {}});
    }
}

void PropertiesDock::addChoice(QGridLayout* grid, const QString& key)
{
    const SettingKey& info = keyInfo(key);
    auto* combo = new QComboBox;
    combo->setObjectName(key);
    // Each choice's value is its key; filters read as people name them, the key beside it, and
    // each says in its own tooltip what it does and costs.
    for (const QString& choice : info.choices) {
        const ShadowTechnique* technique = key == u"filter.mode" ? techniqueNamed(choice) : nullptr;
        combo->addItem(technique ? QStringLiteral("%1 — %2").arg(technique->label, choice) : choice, choice);
        if (technique)
            combo->setItemData(combo->count() - 1, choiceTooltip(*technique), Qt::ToolTipRole);
    }
    const auto showTooltip = [combo, info = &info] {
        if (const ShadowTechnique* technique = info->key == u"filter.mode" ? techniqueNamed(combo->currentData().toString()) : nullptr)
            combo->setToolTip(choiceTooltip(*technique) + filterTooltipTail(*info));
        else
            combo->setToolTip(tooltipFor(*info));
    };
    showTooltip();
    connect(combo, &QComboBox::currentIndexChanged, this, [this, combo, key, showTooltip] {
        showTooltip();
        if (m_loading)
            return;
        const QString value = combo->currentData().toString();
        if (key == u"scene")
            editScene(value);
        else
            edit(key, value);
    });
    Field field{key, nullptr, {combo}, [combo, key, showTooltip](const Settings& s) {
                    const QSignalBlocker block(combo);
                    const QString value = settingValue(s, key);
                    // A loaded model or scene file joins the presets, so it can be chosen again.
                    if (combo->findData(value) < 0)
                        combo->addItem(key == u"scene" ? QFileInfo(value).fileName() : value, value);
                    combo->setCurrentIndex(combo->findData(value));
                    if (key == u"scene")
                        combo->setItemData(combo->currentIndex(), value, Qt::ToolTipRole);
                    showTooltip();
                }};
    addRow(grid, presentation(key).label, QString(), combo, std::move(field));
}

void PropertiesDock::addBool(QGridLayout* grid, const QString& key, const QString& text)
{
    const SettingKey& info = keyInfo(key);
    auto* check = new QCheckBox(text);
    check->setObjectName(key);
    check->setToolTip(tooltipFor(info));
    connect(check, &QCheckBox::toggled, this, [this, key](bool on) {
        if (!m_loading)
            edit(key, on ? QStringLiteral("true") : QStringLiteral("false"));
    });
    Field field{key, nullptr, {check}, [check, key](const Settings& s) {
                    const QSignalBlocker block(check);
                    check->setChecked(settingValue(s, key) == u"true");
                }};
    const int row = grid->rowCount();
    grid->addWidget(check, row, 0, 1, 2);
    field.error = new QLabel;
    field.error->setObjectName(key + QStringLiteral(".error"));
    field.error->setStyleSheet(QStringLiteral("color: #d9534f;"));
    field.error->setWordWrap(true);
    field.error->setVisible(false);
    grid->addWidget(field.error, row + 1, 0, 1, 2);
    m_rows[key] = {check};
    m_fields.insert(key, std::move(field));
}

void PropertiesDock::setSettings(const Settings& settings)
{
    // A preset's sentences are about its scene: on another one they no longer say what is shown.
    if (settings.scene != m_pending.scene)
        hidePreset();
    m_pending = settings;
    m_loading = true;
    for (const Field& field : std::as_const(m_fields))
        field.load(settings);
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
    for (const QString linked : {"light.type", "light.projection", "light.position", "light.direction.azimuth"}) {
        if (const auto it = m_fields.find(linked); it != m_fields.end())
            it->load(m_pending);
    }
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
    for (const Field& field : std::as_const(m_fields)) {
        field.error->setVisible(false);
        field.error->clear();
        field.error->setProperty("refusal", false);
        for (QWidget* w : field.markable) {
            if (auto* box = qobject_cast<SliderSpinBox*>(w))
                box->setInvalid(false);
            else
                w->setStyleSheet(QString());
        }
    }
}

void PropertiesDock::markError(const QString& key, const QString& message)
{
    // A directional light's place is edited, and its refusals shown, at its direction's fields.
    if (key == u"light.position" && m_pending.light.type == LightType::Directional) {
        markError(QStringLiteral("light.direction.distance"), message.startsWith(key + QStringLiteral(": ")) ? message : key + QStringLiteral(": ") + message);
        return;
    }
    auto it = m_fields.find(key);
    if (it == m_fields.end())
        return;
    // The message without the "key: " prefix SettingsError puts in front: the field is the key.
    QString text = message;
    if (text.startsWith(key + QStringLiteral(": ")))
        text = text.mid(key.size() + 2);
    it->error->setText(text);
    it->error->setStyleSheet(QString());
    it->error->setProperty("refusal", true);
    it->error->setVisible(true);
    m_warned.removeAll(key);
    for (QWidget* w : it->markable) {
        if (auto* box = qobject_cast<SliderSpinBox*>(w))
            box->setInvalid(true);
        else
            w->setStyleSheet(QStringLiteral("border: 2px solid #d9534f; border-radius: 3px;"));
    }
    if (QWidget* row = m_rows.value(key).empty() ? nullptr : m_rows.value(key).back())
        static_cast<QScrollArea*>(widget())->ensureWidgetVisible(row);
}

void PropertiesDock::showError(const QString& key, const QString& message)
{
    markError(key, message);
}

QString PropertiesDock::errorText(const QString& key) const
{
    const auto it = m_fields.find(key);
    return it == m_fields.end() ? QString() : it->error->text();
}

namespace {

// The light-volume keys that light.fit=scene computes instead of reading.
const char* const kFittedKeys[] = {"light.extent", "light.fov", "light.near", "light.far"};

} // namespace

void PropertiesDock::showFit(const FittedLight& fit, const LightSettings& light)
{
    if (!m_lastFit || &fit != &*m_lastFit)
        m_lastFit = fit;
    // Last frame's warnings off first; the fields keep their refusals (red) if any.
    for (const QString& key : std::as_const(m_warned)) {
        if (auto it = m_fields.find(key); it != m_fields.end() && !it->error->property("refusal").toBool()) {
            it->error->clear();
            it->error->setVisible(false);
        }
    }
    m_warned.clear();
    const bool fitted = light.fit == LightFit::Scene;
    // A spot light's field of view is its cone, which the fitted map lies inside: it stays
    // the user's to set, whatever the fit.
    const bool spot = light.type == LightType::Spot;
    const auto isFitted = [&](const char* key) { return fitted && !(spot && qstrcmp(key, "light.fov") == 0); };

    for (const char* key : kFittedKeys) {
        for (QWidget* w : m_rows.value(QString::fromLatin1(key))) {
            w->setEnabled(!isFitted(key));
            w->setToolTip(isFitted(key) ? tr("Fitted to the scene (read-only): set Volume to manual to set it by hand")
                                        : tooltipFor(keyInfo(QString::fromLatin1(key))));
        }
    }
    if (fitted && fit.fitted) {
        // The fitted volume in the units of the keys: half-size or full angle, and near and
        // far as distances from the light's position along its direction.
        Settings shown = m_pending;
        const LightVolume& v = fit.volume;
        const double along = glm::dot(v.origin - light.position, v.direction);
        if (v.perspective)
            shown.light.fov = glm::degrees(2.0 * std::atan(std::max({-v.left, v.right, -v.bottom, v.top})));
        else
            shown.light.extent = 0.5 * std::max(v.width(), v.height());
        shown.light.nearPlane = v.nearPlane + along;
        shown.light.farPlane = v.farPlane + along;
        const bool loading = m_loading;
        m_loading = true;
        for (const char* key : kFittedKeys) {
            if (const auto it = m_fields.find(QString::fromLatin1(key)); it != m_fields.end())
                it->load(isFitted(key) ? shown : m_pending);
        }
        m_loading = loading;
        if (spot && v.perspective) {
            // What the fit chose inside the cone, said under the cone's own field.
            const QString key = QStringLiteral("light.fov");
            if (auto it = m_fields.find(key); it != m_fields.end() && !it->error->property("refusal").toBool()) {
                it->error->setText(tr("The cone; the map fitted to what it lights spans %1°").arg(shown.light.fov, 0, 'f', 1));
                it->error->setStyleSheet(QStringLiteral("color: palette(mid);"));
                it->error->setVisible(true);
                m_warned << key;
            }
        }
    } else if (!fitted) {
        const bool loading = m_loading;
        m_loading = true;
        for (const char* key : kFittedKeys) {
            if (const auto it = m_fields.find(QString::fromLatin1(key)); it != m_fields.end())
                it->load(m_pending);
        }
        m_loading = loading;
    }
    for (const SettingsIssue& issue : fitWarnings(fit)) {
        auto it = m_fields.find(issue.key);
        if (it == m_fields.end() || it->error->property("refusal").toBool())
            continue;
        it->error->setText(issue.message);
        it->error->setStyleSheet(QStringLiteral("color: #b8860b;"));
        it->error->setVisible(true);
        m_warned << issue.key;
    }
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
    for (QWidget* w : m_rows.value(QStringLiteral("light.extent")))
        w->setVisible(ortho);
    for (QWidget* w : m_rows.value(QStringLiteral("light.fov")))
        w->setVisible(!ortho);
    for (const TechniqueParameter& parameter : techniqueParameters()) {
        for (QWidget* w : m_rows.value(parameter.key))
            w->setEnabled(usesParameter(m_pending.filter, parameter.key));
    }
    // The cone's falloff for a spot light; cascades for a directional one, and their split
    // settings once there are several.
    for (QWidget* w : m_rows.value(QStringLiteral("light.falloff")))
        w->setVisible(m_pending.light.type == LightType::Spot);
    const bool directional = m_pending.light.type == LightType::Directional;
    // A direction for a directional light, a place for the others.
    for (QWidget* w : m_rows.value(QStringLiteral("light.position")))
        w->setVisible(!directional);
    for (const QString key : {"light.direction.azimuth", "light.direction.elevation", "light.direction.distance"}) {
        for (QWidget* w : m_rows.value(key))
            w->setVisible(directional);
    }
    for (QWidget* w : m_rows.value(QStringLiteral("shadow.cascades")))
        w->setEnabled(directional);
    for (const QString key : {"shadow.split", "shadow.split_lambda", "shadow.distance", "shadow.blend"}) {
        for (QWidget* w : m_rows.value(key))
            w->setEnabled(directional && m_pending.shadow.cascades > 1);
    }
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
        const Look look = presentation(info.key);
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
    for (const QString& key : {QStringLiteral("camera.position"), QStringLiteral("camera.target"), QStringLiteral("camera.fov")}) {
        if (const auto it = m_fields.find(key); it != m_fields.end())
            it->load(m_pending);
    }
    for (const QString& key : keys) {
        applySetting(m_pending, key, settingValue(applied, key));
        if (const auto it = m_fields.find(key); it != m_fields.end())
            it->load(m_pending);
        if (key.startsWith(u"light.position") || key.startsWith(u"light.target"))
            m_fields[QStringLiteral("light.direction.azimuth")].load(m_pending);
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
