#pragma once

#include <QDialog>

namespace shadowlab {

// Help → Shadow Artifacts: the artifacts page (ArtifactsPage.h) with its pictures, whose preset
// links show the artifact in the explorer.
class ArtifactsHelp : public QDialog {
    Q_OBJECT

public:
    explicit ArtifactsHelp(QWidget* parent = nullptr);

signals:
    // A preset link was clicked: show that artifact.
    void presetRequested(const QString& name);
};

} // namespace shadowlab
