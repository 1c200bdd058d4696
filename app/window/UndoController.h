#pragma once

#include "Settings.h"
#include "SettingsChange.h"

#include <QObject>
#include <QString>

#include <array>
#include <vector>

class QAction;
class QUndoGroup;
class QUndoStack;
class QWidget;

namespace shadowlab {

// The undo history of each side (0 is A, 1 is B): every settings change is a SettingsChange
// step of one side's stack, and Edit > Undo works on the active one. Counts the presses on the
// whole application, so that the edits of one drag or one held key merge into one step, and
// keeps Ctrl+Z in the docks' number fields for the window's undo.
class UndoController : public QObject {
    Q_OBJECT

public:
    // `show` puts a step's settings on the sides it holds, when it is undone or redone.
    explicit UndoController(SettingsChange::Apply show, QObject* parent = nullptr);

    QUndoStack* stack(std::size_t side) const { return m_stacks[side]; }
    void setActiveSide(std::size_t side);
    // Edit > Undo and Edit > Redo with their shortcuts, owned by `owner`.
    QAction* createUndoAction(QObject* owner);
    QAction* createRedoAction(QObject* owner);
    // Number fields inside `areas` hand Ctrl+Z and Ctrl+Shift+Z to the undo actions.
    void guardFields(std::vector<QWidget*> areas) { m_areas = std::move(areas); }

    // Makes the change from `before` (the sides it holds) to `now` a step of `side`'s history,
    // named `text` ("Set bias.slope", "Change 5 settings" when empty). Changes of one key in
    // one gesture merge when `mayMerge`; a change of the camera alone is no step.
    void record(const SettingsChange::Sides& before, const std::array<Settings, 2>& now, std::size_t side, QString text = {},
                bool mayMerge = false);
    // The Edit menu's name for a dock edit of `side` to `after`: "Choose scene …" or "Reset to
    // defaults" for the dock's whole-side edits, else empty (the key names itself).
    static QString editText(const SettingsChange::Sides& before, const Settings& after, std::size_t side);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    SettingsChange::Apply m_show;
    QUndoGroup* m_group = nullptr;
    std::array<QUndoStack*, 2> m_stacks{};
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    std::vector<QWidget*> m_areas;
    quint64 m_gesture = 0;      // mouse and key presses so far: edits between two presses merge
};

} // namespace shadowlab
