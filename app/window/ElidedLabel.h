#pragma once

#include <QLabel>

namespace shadowlab {

// One line of text that never shows a cut word: where it does not fit it ends in "…", and the
// tooltip holds it whole. For the status bar's messages and the panes' captions, whose room
// depends on the window's size.
class ElidedLabel : public QLabel {
    Q_OBJECT

public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    void setFullText(const QString& text);
    const QString& fullText() const { return m_text; }
    // Whether the whole text is on screen.
    bool isElided() const { return text() != m_text; }

    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void elide();

    QString m_text;
};

} // namespace shadowlab
