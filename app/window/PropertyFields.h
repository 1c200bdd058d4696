#pragma once

#include "Settings.h"
#include "SliderSpinBox.h"

#include <QHash>
#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QGridLayout;
class QLabel;
class QWidget;

namespace shadowlab {

// The fields of the properties dock, built from the settings table: a spin box with its slider
// per number, three per vector, a combo box per choice, a check box per flag, and for a
// directional light its azimuth, elevation and distance. Each row has a note under it for the
// reason a value was refused or a warning. The fields show settings without emitting; a user's
// edit comes out as edited() with the key and the value as text, as `--set` takes it.
class PropertyFields : public QObject {
    Q_OBJECT

public:
    // How a key is shown, from its presentation in the settings table (SettingsKeys.h).
    struct Look {
        QString label;
        QString unit;
        int decimals;
        double sliderLow;
        double sliderHigh;
        SliderSpinBox::Scale scale = SliderSpinBox::Scale::Linear;
    };
    static Look look(const QString& key);
    static QString toolTip(const QString& key);

    // `pending`: the settings as typed, from which an edit of one component (a vector's, or a
    // direction's angle) writes the whole value.
    explicit PropertyFields(const Settings& pending, QObject* parent = nullptr);

    void addNumber(QGridLayout* grid, const QString& key);
    void addVector(QGridLayout* grid, const QString& key);
    // Azimuth, elevation and distance, the rows light.direction.*; all three edit light.position.
    void addDirection(QGridLayout* grid);
    void addChoice(QGridLayout* grid, const QString& key);
    void addBool(QGridLayout* grid, const QString& key, const QString& text);
    // A list of the scene's objects, each checked while it is not in the key's list of names
    // (objects.no_cast: it casts). setObjects() fills it.
    void addObjects(QGridLayout* grid, const QString& key);
    // The objects of the scene shown: their tokens (objectTokens()) and what each list shows.
    void setObjects(const QStringList& tokens, const QStringList& labels);

    void loadAll(const Settings& settings);
    // Shows `key`'s value from `settings`; false when there is no such field.
    bool load(const QString& key, const Settings& settings);
    // The label and editor of `key` (to hide or disable), empty when there is no such field.
    std::vector<QWidget*> row(const QString& key) const { return m_rows.value(key); }
    // The note under `key`'s row; nullptr when there is no such field.
    QLabel* note(const QString& key) const;
    // Says `text` in `key`'s note and marks its editors red; false when there is no such field.
    bool markRefused(const QString& key, const QString& text);
    // Every note hidden and every editor unmarked.
    void clearErrors();

signals:
    void edited(const QString& key, const QString& value);

private:
    struct Field {
        QString key;
        QLabel* error = nullptr;
        std::vector<QWidget*> markable;              // widgets that turn red when refused
        std::function<void(const Settings&)> load;   // shows a value without emitting
    };

    void addRow(QGridLayout* grid, const QString& label, const QString& rangeText, QWidget* editor, Field field);

    const Settings& m_pending;
    std::vector<QString> m_objectKeys;              // keys shown by addObjects()
    QHash<QString, Field> m_fields;
    QHash<QString, std::vector<QWidget*>> m_rows;   // label and editor of a key, to hide/disable
    double m_lastAzimuth = 0.0;     // kept while the light stands straight above its target
};

} // namespace shadowlab
