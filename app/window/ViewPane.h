#pragma once

#include <QFrame>

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
    QWidget* view() const { return m_view; }

private:
    QWidget* m_view;
    QLabel* m_caption;
    bool m_highlighted = false;
};

} // namespace shadowlab
