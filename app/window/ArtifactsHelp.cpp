#include "ArtifactsHelp.h"

#include "ArtifactsPage.h"

#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

namespace shadowlab {

ArtifactsHelp::ArtifactsHelp(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Shadow Artifacts — ShadowLab"));
    auto* browser = new QTextBrowser;
    const std::map<QString, QImage>& images = artifactPictures();
    for (const auto& [name, image] : images)
        browser->document()->addResource(QTextDocument::ImageResource, QUrl(QStringLiteral("artifact:") + name), image);
    browser->setHtml(artifactsPageHtml(!images.empty()));
    browser->setOpenExternalLinks(false);
    browser->setOpenLinks(false);
    // "preset:NAME" links show the artifact in the explorer.
    connect(browser, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
        if (url.scheme() == u"preset")
            emit presetRequested(url.path());
    });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser);
    layout->addWidget(buttons);
    resize(780, 680);     // two pictures side by side in a list item, with no sideways scrolling
}

} // namespace shadowlab
