#pragma once

#include <QFrame>

class QAction;
class QHBoxLayout;
class QLabel;

namespace shadowlab {

// A view with a caption strip above it: which side it is and what technique it shows. In
// compare mode the selected pane's caption is highlighted, since that is the side the dock edits.
class ViewPane : public QFrame {
    Q_OBJECT

public:
    ViewPane(QWidget* view, QWidget* parent = nullptr);

    void setCaption(const QString& title, const QString& detail);
    void setHighlighted(bool highlighted);
    // A small button for `action` at the caption strip's right end.
    void addCaptionButton(QAction* action);
    QWidget* view() const { return m_view; }

private:
    QWidget* m_view;
    QWidget* m_strip;           // the caption and its buttons
    QHBoxLayout* m_stripLayout;
    QLabel* m_caption;
    bool m_highlighted = false;
};

} // namespace shadowlab
