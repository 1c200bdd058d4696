#include "WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QWidget>

namespace shadowlab {

WheelGuard* WheelGuard::instance()
{
    // One filter for every field, owned by the application so it outlives them all.
    static WheelGuard* guard = new WheelGuard(QCoreApplication::instance());
    return guard;
}

void WheelGuard::guard(QWidget* field)
{
    field->setFocusPolicy(Qt::StrongFocus);   // not Qt::WheelFocus: the wheel alone does not focus
    field->installEventFilter(instance());
}

void WheelGuard::guardFields(QWidget* root)
{
    for (QWidget* w : root->findChildren<QAbstractSpinBox*>())
        guard(w);
    for (QWidget* w : root->findChildren<QAbstractSlider*>()) {
        // A scroll bar is for scrolling.
        if (w->inherits("QScrollBar"))
            continue;
        guard(w);
    }
    for (QWidget* w : root->findChildren<QComboBox*>())
        guard(w);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Wheel) {
        const auto* field = static_cast<QWidget*>(watched);
        if (!field->hasFocus()) {
            // Ignored, the event goes on to the parents: the dock's scroll area scrolls.
            event->ignore();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace shadowlab
