#pragma once

#include <QObject>

class QWidget;

namespace shadowlab {

// Keeps the mouse wheel for scrolling: a field (spin box, slider, combo box) takes the wheel
// only once it has the focus (clicked or tabbed to), so turning the wheel over a dock scrolls
// the dock instead of changing whatever value passes under the pointer.
class WheelGuard : public QObject {
    Q_OBJECT

public:
    // Guards `field`: focus by click or tab only, and the wheel only while focused.
    static void guard(QWidget* field);
    // Guards every spin box, slider and combo box under `root`.
    static void guardFields(QWidget* root);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
    static WheelGuard* instance();
};

} // namespace shadowlab
