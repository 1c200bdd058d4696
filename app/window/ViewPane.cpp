#include "ViewPane.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace shadowlab {

ViewPane::ViewPane(QWidget* view, QWidget* parent) : QFrame(parent), m_view(view), m_strip(new QWidget), m_caption(new QLabel)
{
    m_caption->setTextFormat(Qt::RichText);
    m_caption->setContentsMargins(8, 3, 8, 3);
    // Wrapped, not cut: at the default window size a caption is wider than its view.
    m_caption->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_caption->setWordWrap(true);
    m_strip->setObjectName(QStringLiteral("captionStrip"));
    m_stripLayout = new QHBoxLayout(m_strip);
    m_stripLayout->setContentsMargins(0, 0, 4, 0);
    m_stripLayout->setSpacing(2);
    m_stripLayout->addWidget(m_caption, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_strip);
    layout->addWidget(view, 1);
    setHighlighted(false);
    // A view squeezed to no pixels never draws (and a screenshot would wait for it forever).
    view->setMinimumSize(64, 48);
}

void ViewPane::setCaption(const QString& title, const QString& detail)
{
    m_caption->setText(QStringLiteral("<b>%1</b>&nbsp;&nbsp;<span style='color:%3'>%2</span>")
                           .arg(title.toHtmlEscaped(), detail.toHtmlEscaped(),
                                m_highlighted ? QStringLiteral("#e8eefc") : QStringLiteral("#a0a6b4")));
    m_caption->setToolTip(detail);
}

void ViewPane::addCaptionButton(QAction* action)
{
    auto* button = new QToolButton;
    button->setDefaultAction(action);
    button->setObjectName(action->objectName() + QStringLiteral("Button"));
    button->setAutoRaise(true);
    // An icon where the action has one: the caption keeps the strip's width.
    button->setToolButtonStyle(action->icon().isNull() ? Qt::ToolButtonTextOnly : Qt::ToolButtonIconOnly);
    button->setIconSize(QSize(16, 16));
    m_stripLayout->addWidget(button, 0, Qt::AlignTop);
}

void ViewPane::setHighlighted(bool highlighted)
{
    m_highlighted = highlighted;
    m_strip->setStyleSheet(highlighted ? QStringLiteral("#captionStrip, #captionStrip * { background: #2f6fdb; color: white; }")
                                       : QStringLiteral("#captionStrip, #captionStrip * { background: #2a2d35; color: #e6e8ee; }"));
}

} // namespace shadowlab
