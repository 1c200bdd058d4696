#pragma once

#include "GlObject.h"

#include <QString>
#include <QStringList>

#include <algorithm>
#include <map>
#include <memory>

namespace shadowlab {

// A pass's compiled shader variants by their defines: each built as Program(gl, defines) on
// first use and kept, so switching back to a variant costs nothing. Program is the pass's own
// program with its uniform locations looked up.
template <class Program>
class ProgramCache {
public:
    explicit ProgramCache(GlFunctions* gl) : m_gl(gl) {}

    // The variant of `defines`; one that fails to compile (RenderError) is not kept.
    Program& get(const QStringList& defines)
    {
        const QString key = defines.join(QLatin1Char(';'));
        auto it = m_programs.find(key);
        if (it == m_programs.end())
            it = m_programs.emplace(key, std::make_unique<Program>(m_gl, defines)).first;
        return *it->second;
    }

    int size() const { return int(m_programs.size()); }
    // How many of the variants were compiled with `define`.
    int countWith(const QString& define) const
    {
        return int(std::count_if(m_programs.begin(), m_programs.end(),
                                 [&](const auto& p) { return p.first.split(QLatin1Char(';')).contains(define); }));
    }

private:
    GlFunctions* m_gl;
    std::map<QString, std::unique_ptr<Program>> m_programs;
};

} // namespace shadowlab
