#include "UndoController.h"

#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QFileInfo>
#include <QKeyEvent>
#include <QUndoGroup>
#include <QUndoStack>
#include <QWidget>

#include <algorithm>

namespace shadowlab {

namespace {

const char* const kSideNames[] = {"A", "B"};

// The keys whose values differ between `a` and `b`, the camera's left out: it is the view's.
QStringList changedKeys(const Settings& a, const Settings& b)
{
    QStringList keys;
    for (const SettingKey& key : settingKeys()) {
        if (!key.key.startsWith(u"camera.") && settingValue(a, key.key) != settingValue(b, key.key))
            keys << key.key;
    }
    return keys;
}

} // namespace

UndoController::UndoController(SettingsChange::Apply show, QObject* parent) : QObject(parent), m_show(std::move(show))
{
    // One undo history per side; the selected side's is the one Edit > Undo works on.
    m_group = new QUndoGroup(this);
    for (std::size_t i = 0; i < 2; ++i) {
        m_stacks[i] = new QUndoStack(m_group);
        m_stacks[i]->setObjectName(QStringLiteral("undoStack%1").arg(QLatin1String(kSideNames[i])));
    }
    m_group->setActiveStack(m_stacks[0]);
    qApp->installEventFilter(this);    // counts presses, so one drag is one undo step
}

void UndoController::setActiveSide(std::size_t side)
{
    m_group->setActiveStack(m_stacks[side]);
}

QAction* UndoController::createUndoAction(QObject* owner)
{
    QAction* undo = m_undoAction = m_group->createUndoAction(owner, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setToolTip(tr("Take back the last settings change of this side (Ctrl+Z)"));
    return undo;
}

QAction* UndoController::createRedoAction(QObject* owner)
{
    QAction* redo = m_redoAction = m_group->createRedoAction(owner, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redo->setToolTip(tr("Make the change taken back again (Ctrl+Shift+Z)"));
    return redo;
}

void UndoController::record(const SettingsChange::Sides& before, const std::array<Settings, 2>& now, std::size_t side, QString text,
                            bool mayMerge)
{
    SettingsChange::Sides after;
    QStringList keys;
    for (std::size_t i = 0; i < 2; ++i) {
        if (!before[i])
            continue;
        after[i] = now[i];
        for (const QString& key : changedKeys(*before[i], now[i])) {
            if (!keys.contains(key))
                keys << key;
        }
    }
    if (keys.isEmpty())
        return;     // the camera alone, or nothing at all
    int mergeKey = -1;
    if (keys.size() == 1) {
        if (text.isEmpty())
            text = tr("Set %1").arg(keys.first());
        if (mayMerge) {
            const std::vector<SettingKey>& table = settingKeys();
            mergeKey = int(std::find_if(table.begin(), table.end(), [&](const SettingKey& k) { return k.key == keys.first(); }) - table.begin());
        }
    } else if (text.isEmpty()) {
        text = tr("Change %1 settings").arg(keys.size());
    }
    m_stacks[side]->push(new SettingsChange(text, before, after, mergeKey, m_gesture, m_show));
}

QString UndoController::editText(const SettingsChange::Sides& before, const Settings& after, std::size_t side)
{
    // Name the dock's two whole-side edits in the Edit menu; one key names itself ("Set bias.slope").
    const bool wholeSide = changedKeys(*before[side], after).size() > 1 || before[1 - side];
    if (wholeSide && after.scene != before[side]->scene)
        return tr("Choose scene %1").arg(QFileInfo(after.scene).fileName());
    if (wholeSide) {
        try {
            Settings defaults = presetSettings(after.scene);
            defaults.camera = after.camera;
            if (after == defaults)
                return tr("Reset to defaults");
        } catch (const SettingsError&) {
            // a scene file that went away: the generic name will do
        }
    }
    return QString();
}

bool UndoController::eventFilter(QObject* watched, QEvent* event)
{
    // A number field of a dock would take Ctrl+Z for its own text; its value is applied on
    // Enter, so what the user means is the window's undo. Left unaccepted, the override lets
    // the Edit menu's shortcut run.
    if (event->type() == QEvent::ShortcutOverride && m_undoAction) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const QKeySequence pressed(key->keyCombination());
        const bool undoKey = m_undoAction->shortcuts().contains(pressed) || m_redoAction->shortcuts().contains(pressed);
        auto* widget = qobject_cast<QWidget*>(watched);
        // The line edit first, then (the override travels up) its spin box, which would hand
        // it to the line edit again.
        const bool numberField = widget && (qobject_cast<QAbstractSpinBox*>(widget) || qobject_cast<QAbstractSpinBox*>(widget->parentWidget()));
        const bool inArea = std::any_of(m_areas.begin(), m_areas.end(), [&](const QWidget* area) { return area->isAncestorOf(widget); });
        if (undoKey && numberField && inArea)
            return true;
    }
    // A new press starts a new gesture; a key's auto-repeat continues the one it began.
    if (event->type() == QEvent::MouseButtonPress
        || (event->type() == QEvent::KeyPress && !static_cast<QKeyEvent*>(event)->isAutoRepeat()))
        ++m_gesture;
    return QObject::eventFilter(watched, event);
}

} // namespace shadowlab
