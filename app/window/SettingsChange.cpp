#include "SettingsChange.h"

namespace shadowlab {

SettingsChange::SettingsChange(const QString& text, Sides before, Sides after, int mergeKey, quint64 gesture, Apply apply)
    : QUndoCommand(text), m_before(std::move(before)), m_after(std::move(after)), m_mergeKey(mergeKey), m_gesture(gesture),
      m_apply(std::move(apply))
{
}

void SettingsChange::undo()
{
    m_apply(m_before, m_after);
}

void SettingsChange::redo()
{
    if (m_shown) {
        m_shown = false;
        return;
    }
    m_apply(m_after, m_before);
}

bool SettingsChange::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SettingsChange*>(other);  // same id(): a SettingsChange
    if (next->m_gesture != m_gesture)
        return false;
    for (std::size_t i = 0; i < 2; ++i) {
        if (m_after[i].has_value() != next->m_after[i].has_value())
            return false;
    }
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

} // namespace shadowlab
