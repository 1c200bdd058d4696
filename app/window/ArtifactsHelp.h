#pragma once

#include <QDialog>
#include <QImage>
#include <QString>

#include <map>

namespace shadowlab {

// Help → Shadow Artifacts: one link per artifact preset, what each artifact looks like, why it
// happens and which settings trade it against which; then every setting with its range and help, read from settingKeys()
// so the page cannot drift from the dock and the command line.
class ArtifactsHelp : public QDialog {
    Q_OBJECT

public:
    explicit ArtifactsHelp(QWidget* parent = nullptr);

    // `withPictures`: each preset shows what it looks like and what its fix looks like, from
    // artifact:NAME and artifact:NAME-fixed images (pictures()).
    static QString html(bool withPictures = false);
    // The presets rendered as the dialog shows them, NAME and NAME-fixed, drawn once per run on
    // an offscreen renderer; empty where no GL context can be had.
    static const std::map<QString, QImage>& pictures();
    static constexpr int kPictureWidth = 288, kPictureHeight = 162;

signals:
    // A preset link was clicked: show that artifact.
    void presetRequested(const QString& name);
};

} // namespace shadowlab
