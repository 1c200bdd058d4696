#pragma once

#include <QDialog>

namespace shadowlab {

// Help → Shadow Artifacts: one link per artifact preset, what each artifact looks like, why it
// happens and which settings trade it against which; then every setting with its range and help, read from settingKeys()
// so the page cannot drift from the dock and the command line.
class ArtifactsHelp : public QDialog {
    Q_OBJECT

public:
    explicit ArtifactsHelp(QWidget* parent = nullptr);

    static QString html();

signals:
    // A preset link was clicked: show that artifact.
    void presetRequested(const QString& name);
};

} // namespace shadowlab
