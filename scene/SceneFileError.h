#pragma once

#include "SettingsError.h"

namespace shadowlab {

// A model or scene file that cannot be used: names the file, what is wrong with it and how to
// fix it. A bad file is a bad value of the `scene` key, so everything that reports a
// SettingsError (exit 2 on the command line, the window keeping its last good settings)
// reports this too.
class SceneFileError : public SettingsError {
public:
    SceneFileError(const QString& path, const QString& problem)
        : SettingsError(QStringLiteral("scene"), QStringLiteral("'%1': %2").arg(path, problem)), m_problem(problem) {}

    // What is wrong, without the file's name: what the import worker sends back.
    const QString& problem() const { return m_problem; }

private:
    QString m_problem;
};

} // namespace shadowlab
