#include "ArtifactsPage.h"

#include "ArtifactPresets.h"
#include "HeadlessRenderer.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

namespace shadowlab {

namespace {

const char* const kArtifacts = R"html(
<h2>Shadow artifacts and the settings that trade them</h2>
<p>A shadow map stores, per texel, the depth of the nearest caster seen from the light. A
pixel is in shadow when it is farther from the light than that depth. Every artifact below
comes from comparing two depths that were sampled at different places and precisions.</p>

<h3>Shadow acne</h3>
<p>Stripes or moiré of false shadow on lit surfaces. A texel covers an area of the surface;
across that area the surface's true depth rises above the stored one, so the surface shadows
itself. It is worst on slopes seen at a grazing angle from the light.
<b>Fixes:</b> <i>Bias → Slope</i> and <i>Minimum</i> (push the comparison away from the light),
<i>Cull front faces</i> (store back faces, which are farther), <i>Offset factor/units</i>
(the same in hardware), a larger <i>Shadow map → Size</i> or a smaller light <i>Extent</i>
(smaller texels).</p>

<h3>Peter panning</h3>
<p>Shadows detached from the objects that cast them, as if they floated. Too much bias moves
the comparison past the contact point. <b>Trade:</b> lower the bias until acne just
disappears; cull front faces instead of a large constant bias where casters are closed.</p>

<h3>Light leaks</h3>
<p>Light where two surfaces meet or through thin casters: with front faces culled, a thin
caster has no back face close enough; with a large minimum bias, contacts leak.
<b>Trade:</b> smaller minimum bias, thicker casters, or no front-face culling.</p>

<h3>Aliasing (blocky edges)</h3>
<p>Stair-stepped shadow edges: one texel covers many screen pixels. <b>Fixes:</b> more texels
(<i>Size</i>), a tighter light volume (<i>Extent</i>, <i>Field of view</i>, <i>Near/Far</i>),
or a filter (<i>Filtering → Filter</i>):</p>
%FILTERS%
<h3>Depth precision</h3>
<p>For a perspective light, depth resolution falls off with distance as far/near grows; a
24-bit map runs out far from the light and acne comes back there. <b>Fixes:</b> push
<i>Near</i> out, pull <i>Far</i> in, or use the <i>depth32f</i> format.</p>

<h3>Reading the depth map</h3>
<p>The pane beside the scene is the light's view. Its colours run from dark blue (nearest the
light) through green to pale yellow (farthest), stretched to the depths the map really holds;
the legend under it gives those depths and their distance from the light in world units. Hatched
grey is <i>empty (far plane)</i>: nothing was drawn there, so whatever lies there is lit. (With
front faces culled a single-sided ground is not drawn either: it cannot shadow anything.) A
perspective light's depth is shown linearised between near and far. The dashed frame is the
light's volume, drawn at its real aspect; with <i>Volume: scene</i> it is fitted to what the
camera sees, which is why the map moves as the camera does. The orange outline is the camera's
visible region seen from the light. Hover a texel to read its coordinates and depth in the
status bar; the status bar also shows how much world one texel covers, the number that decides
how blocky the shadow is. <i>View → Texel Density Overlay</i> colours the scene by how many
screen pixels one texel covers: blue under one, green one to two, yellow four, red eight and
more (blocky).</p>
)html";

} // namespace

const std::map<QString, QImage>& artifactPictures()
{
    static const std::map<QString, QImage> rendered = [] {
        std::map<QString, QImage> images;
        try {
            HeadlessRenderer headless;
            for (const ArtifactPreset& preset : artifactPresets()) {
                const QSize size(kArtifactPictureWidth, kArtifactPictureHeight);
                images[preset.name] = headless.renderScene(artifactPresetSettings(preset), size);
                images[preset.name + QStringLiteral("-fixed")] = headless.renderScene(artifactPresetFixed(preset), size);
            }
        } catch (const std::exception&) {
            images.clear();     // the page reads without them
        }
        return images;
    }();
    return rendered;
}

QString artifactsPageHtml(bool withPictures)
{
    QString table = QStringLiteral("<h3>Every setting</h3><table cellpadding='3'>"
                                   "<tr><th align='left'>Key</th><th align='left'>Range</th><th align='left'>What it trades</th></tr>");
    for (const SettingKey& key : settingKeys())
        table += QStringLiteral("<tr><td><tt>%1</tt></td><td>%2</td><td>%3</td></tr>")
                     .arg(key.key, key.range.toHtmlEscaped(), key.help.toHtmlEscaped());
    table += QStringLiteral("</table><p>The same keys work as <tt>shadowlab render --set key=value</tt> and in "
                            "exported JSON files. <i>wu</i> is a world unit.</p>");
    QString filters = QStringLiteral("<ul>");
    for (const ShadowTechnique& t : shadowTechniques())
        filters += QStringLiteral("<li><i>%1</i> — %2</li>").arg(t.label.toHtmlEscaped(), t.help.toHtmlEscaped());
    filters += QStringLiteral("</ul>");
    QString presets = QStringLiteral("<h3>See each artifact in one click</h3><p>Each link sets the selected side to an artifact "
                                     "preset (also in the Properties dock, and <tt>--preset NAME</tt> on the command line):</p><ul>");
    for (const ArtifactPreset& p : artifactPresets()) {
        presets += QStringLiteral("<li><a href='preset:%1'><b>%2</b></a> (<tt>%1</tt>) — %3 <i>Fix:</i> %4")
                       .arg(p.name, p.title.toHtmlEscaped(), p.lookFor.toHtmlEscaped(), p.fix.toHtmlEscaped());
        if (withPictures)
            presets += QStringLiteral("<table cellpadding='2'><tr><td><img src='artifact:%1' width='%2' height='%3'></td>"
                                      "<td><img src='artifact:%1-fixed' width='%2' height='%3'></td></tr>"
                                      "<tr><td align='center'><small>the artifact</small></td><td align='center'><small>with the fix</small></td></tr></table>")
                           .arg(p.name)
                           .arg(kArtifactPictureWidth)
                           .arg(kArtifactPictureHeight);
        presets += QStringLiteral("</li>");
    }
    presets += QStringLiteral("</ul>");
    QString text = QString::fromUtf8(kArtifacts).replace(QStringLiteral("%FILTERS%"), filters);
    // Right after the introduction, before the artifacts one by one.
    return text.replace(QStringLiteral("<h3>Shadow acne</h3>"), presets + QStringLiteral("<h3>Shadow acne</h3>")) + table;
}

} // namespace shadowlab
