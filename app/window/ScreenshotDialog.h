#pragma once

#include <QDialog>

class QComboBox;
class QImage;
class QLineEdit;

namespace shadowlab {

// File → Save Screenshot…: what to capture and where. The path starts as a default name in
// the last folder used; Browse… opens a file dialog for it.
class ScreenshotDialog : public QDialog {
    Q_OBJECT

public:
    enum class Target { SceneView, DepthMapView, Window };

    ScreenshotDialog(const QString& defaultPath, QWidget* parent = nullptr);

    Target target() const;
    void setTarget(Target target);
    QString path() const;
    void setPath(const QString& path);
    // Writes `image` to `path` as PNG; returns an empty string or what went wrong ("nothing to
    // capture" for a null image).
    static QString write(const QImage& image, const QString& path);

private:
    void browse();

    QComboBox* m_target;
    QLineEdit* m_path;
};

} // namespace shadowlab
