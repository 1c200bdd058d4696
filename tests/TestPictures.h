#pragma once

#include <QDir>
#include <QString>
#include <QWidget>

// With SHADOWLAB_TEST_PICTURES set to a folder, what the user sees at a step of a test is saved
// there as NAME.png, to be looked at.
inline void keepPicture(QWidget* widget, const QString& name)
{
    const QString folder = qEnvironmentVariable("SHADOWLAB_TEST_PICTURES");
    if (!folder.isEmpty() && widget)
        widget->grab().save(QDir(folder).filePath(name + QStringLiteral(".png")));
}
