#pragma once

#include <QImage>
#include <QString>

#include <map>

namespace shadowlab {

// The Shadow Artifacts page (Help → Shadow Artifacts, and the docs): one link per artifact
// preset, what each artifact looks like, why it happens and which settings trade it against
// which; then every setting with its range and help, read from settingKeys() so the page cannot
// drift from the dock and the command line.
// `withPictures`: each preset shows what it looks like and what its fix looks like, from
// artifact:NAME and artifact:NAME-fixed images (artifactPictures()).
QString artifactsPageHtml(bool withPictures = false);

// The presets rendered as the page shows them, NAME and NAME-fixed, drawn once per run on an
// offscreen renderer; empty where no GL context can be had.
const std::map<QString, QImage>& artifactPictures();
constexpr int kArtifactPictureWidth = 288, kArtifactPictureHeight = 162;

} // namespace shadowlab
