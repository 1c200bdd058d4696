#include "ScreenshotDialog.h"

#include "ImageFile.h"
#include "OutputFile.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

namespace shadowlab {

ScreenshotDialog::ScreenshotDialog(const QString& defaultPath, QWidget* parent)
    : QDialog(parent), m_target(new QComboBox), m_path(new QLineEdit(defaultPath))
{
    setWindowTitle(tr("Save Screenshot"));
    m_target->setObjectName(QStringLiteral("screenshotTarget"));
    m_target->addItem(tr("Scene view"), int(Target::SceneView));
    m_target->addItem(tr("Depth-map view"), int(Target::DepthMapView));
    m_target->addItem(tr("Whole window"), int(Target::Window));
    m_path->setObjectName(QStringLiteral("screenshotPath"));
    m_path->setMinimumWidth(420);

    auto* browse = new QPushButton(tr("Browse…"));
    connect(browse, &QPushButton::clicked, this, &ScreenshotDialog::browse);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_path, &QLineEdit::textChanged, this, [buttons](const QString& text) {
        buttons->button(QDialogButtonBox::Save)->setEnabled(!text.trimmed().isEmpty());
    });

    auto* form = new QFormLayout(this);
    form->addRow(tr("Capture:"), m_target);
    form->addRow(tr("File:"), pathRow);
    form->addRow(buttons);
}

ScreenshotDialog::Target ScreenshotDialog::target() const
{
    return Target(m_target->currentData().toInt());
}

void ScreenshotDialog::setTarget(Target target)
{
    m_target->setCurrentIndex(m_target->findData(int(target)));
}

QString ScreenshotDialog::path() const
{
    QString path = m_path->text().trimmed();
    if (!path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive))
        path += QStringLiteral(".png");
    return path;
}

void ScreenshotDialog::setPath(const QString& path)
{
    m_path->setText(path);
}

void ScreenshotDialog::browse()
{
    const QString chosen = QFileDialog::getSaveFileName(this, tr("Save Screenshot"), m_path->text(), tr("PNG images (*.png)"));
    if (!chosen.isEmpty())
        m_path->setText(chosen);
}

QString ScreenshotDialog::write(const QImage& image, const QString& path)
{
    if (image.isNull())
        return tr("There is nothing to capture: the view has no size.");
    try {
        checkOutputFile(path, tr("Screenshot"));
        writeOutputFile(path, encodePng(image.convertToFormat(QImage::Format_RGB32)));
    } catch (const OutputError& e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

} // namespace shadowlab
