#pragma once

#include "SettingsError.h"

namespace shadowlab {

// A model or scene file that cannot be used: names the file, what is wrong with it and how to
// fix it. A bad file is a bad value of the `scene` key, so everything that reports a
// SettingsError (exit 2 on the command line, the window keeping its last good settings)
// reports this too.
class SceneFileError : public SettingsError {
public:
    // Which import limit (ImportLimits.h) stopped the file, where one did: a file that is only
    // large opens with a higher one, which each front end offers in its own words (an option
    // on the command line, a button in the window).
    enum class Limit { None, Time, Memory };

    SceneFileError(const QString& path, const QString& problem, Limit limit = Limit::None)
        : SettingsError(QStringLiteral("scene"), QStringLiteral("'%1': %2").arg(path, problem)), m_problem(problem), m_path(path), m_limit(limit) {}

    // What is wrong, without the file's name: what the import worker sends back.
    const QString& problem() const { return m_problem; }
    const QString& path() const { return m_path; }
    Limit limit() const { return m_limit; }

private:
    QString m_problem;
    QString m_path;
    Limit m_limit = Limit::None;
};

} // namespace shadowlab
