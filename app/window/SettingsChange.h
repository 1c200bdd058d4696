#pragma once

#include "Settings.h"

#include <QUndoCommand>

#include <array>
#include <functional>
#include <optional>

namespace shadowlab {

// One undoable change of the settings of side A, side B or both: what they were and what they
// became. Consecutive changes of the same key made in one gesture (a slider drag, a held arrow
// button, turns of the wheel) merge into one step; a change back to where the step began
// leaves no step at all.
class SettingsChange : public QUndoCommand {
public:
    using Sides = std::array<std::optional<Settings>, 2>;
    // Shows `target` on the sides it holds; `from` is what those sides held, so fields the
    // change did not touch can keep their present values.
    using Apply = std::function<void(const Sides& target, const Sides& from)>;

    // `mergeKey` is -1 for a change that never merges; `gesture` counts the presses that
    // started edits. The change is already shown when it is pushed: the first redo() is empty.
    SettingsChange(const QString& text, Sides before, Sides after, int mergeKey, quint64 gesture, Apply apply);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeKey; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Sides m_before;
    Sides m_after;
    int m_mergeKey;
    quint64 m_gesture;
    Apply m_apply;
    bool m_shown = true;
};

} // namespace shadowlab
