#include "PropertyFields.h"

#include "LightMath.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// How a key is shown, from its presentation in the settings table (SettingsKeys.h).
PropertyFields::Look presentation(const QString& key)
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

} // namespace

PropertyFields::PropertyFields(const Settings& pending, QObject* parent) : QObject(parent), m_pending(pending)
{
}

PropertyFields::Look PropertyFields::look(const QString& key)
{
    return presentation(key);
}

QString PropertyFields::toolTip(const QString& key)
{
    return tooltipFor(keyInfo(key));
}

void PropertyFields::loadAll(const Settings& settings)
{
    for (const Field& field : std::as_const(m_fields))
        field.load(settings);
}

bool PropertyFields::load(const QString& key, const Settings& settings)
{
    const auto it = m_fields.find(key);
    if (it == m_fields.end())
        return false;
    it->load(settings);
    return true;
}

QLabel* PropertyFields::note(const QString& key) const
{
    const auto it = m_fields.find(key);
    return it == m_fields.end() ? nullptr : it->error;
}

bool PropertyFields::markRefused(const QString& key, const QString& text)
{
    auto it = m_fields.find(key);
    if (it == m_fields.end())
        return false;
    it->error->setText(text);
    it->error->setStyleSheet(QString());
    it->error->setProperty("refusal", true);
    it->error->setVisible(true);
    for (QWidget* w : it->markable) {
        if (auto* box = qobject_cast<SliderSpinBox*>(w))
            box->setInvalid(true);
        else
            w->setStyleSheet(QStringLiteral("border: 2px solid #d9534f; border-radius: 3px;"));
    }
    return true;
}

void PropertyFields::addRow(QGridLayout* grid, const QString& label, const QString& rangeText, QWidget* editor, Field field)
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

void PropertyFields::addNumber(QGridLayout* grid, const QString& key)
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
        emit edited(key, integer ? QString::number(qRound(v)) : QString::number(v, 'g', 12));
    });
    Field field{key, nullptr, {editor}, [editor, key](const Settings& s) { editor->setValue(settingValue(s, key).toDouble()); }};
    // Huge limits ([-1e7, 1e7]) only say "any sensible number": the tooltip still has them.
    const bool telling = std::max(std::abs(info.minimum), std::abs(info.maximum)) < 1e5;
    addRow(grid, look.label, (telling ? info.range : QString()) + look.unit, editor,
           std::move(field));
}

void PropertyFields::addVector(QGridLayout* grid, const QString& key)
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
            emit edited(key, xyz.join(QLatin1Char(',')));
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

void PropertyFields::addDirection(QGridLayout* grid)
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
        emit edited(QStringLiteral("light.position"), QStringLiteral("%1,%2,%3").arg(p.x, 0, 'g', 12).arg(p.y, 0, 'g', 12).arg(p.z, 0, 'g', 12));
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

void PropertyFields::addChoice(QGridLayout* grid, const QString& key)
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
        emit edited(key, combo->currentData().toString());
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

void PropertyFields::addBool(QGridLayout* grid, const QString& key, const QString& text)
{
    const SettingKey& info = keyInfo(key);
    auto* check = new QCheckBox(text);
    check->setObjectName(key);
    check->setToolTip(tooltipFor(info));
    connect(check, &QCheckBox::toggled, this, [this, key](bool on) { emit edited(key, on ? QStringLiteral("true") : QStringLiteral("false")); });
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

void PropertyFields::addObjects(QGridLayout* grid, const QString& key)
{
    const SettingKey& info = keyInfo(key);
    auto* list = new QListWidget;
    list->setObjectName(key);
    list->setToolTip(tooltipFor(info));
    list->setSelectionMode(QAbstractItemView::NoSelection);
    list->setUniformItemSizes(true);        // a city's thousands of objects stay quick
    list->setMaximumHeight(list->fontMetrics().height() * 7);
    connect(list, &QListWidget::itemChanged, this, [this, list, key] {
        QStringList off;
        for (int i = 0; i < list->count(); ++i) {
            if (list->item(i)->checkState() != Qt::Checked)
                off << list->item(i)->data(Qt::UserRole).toString();
        }
        emit edited(key, off.join(QLatin1Char(',')));
    });
    Field field{key, nullptr, {list}, [list, key](const Settings& s) {
                    const QSignalBlocker block(list);
                    const QStringList off = settingValue(s, key).split(QLatin1Char(','), Qt::SkipEmptyParts);
                    for (int i = 0; i < list->count(); ++i)
                        list->item(i)->setCheckState(off.contains(list->item(i)->data(Qt::UserRole).toString()) ? Qt::Unchecked : Qt::Checked);
                }};
    addRow(grid, presentation(key).label, QString(), list, std::move(field));
    m_objectKeys.push_back(key);
}

void PropertyFields::setObjects(const QStringList& tokens, const QStringList& labels)
{
    for (const QString& key : m_objectKeys) {
        auto* list = qobject_cast<QListWidget*>(m_fields.value(key).markable.front());
        const QSignalBlocker block(list);
        list->clear();
        for (qsizetype i = 0; i < tokens.size(); ++i) {
            auto* item = new QListWidgetItem(labels.value(i, tokens[i]), list);
            item->setData(Qt::UserRole, tokens[i]);
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        }
        m_fields.value(key).load(m_pending);
    }
}

void PropertyFields::clearErrors()
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

} // namespace shadowlab
