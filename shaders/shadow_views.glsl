// Several views in one shadow map, side by side: the cascades of a directional light
// (CASCADES) or the six cube faces of a point light (LIGHT_POINT). Each pixel picks its view
// (by view depth, or by the major axis of its direction from the light), transforms itself with
// that view's matrix and runs the technique's own filterShadow inside that view's tile.
#ifdef SHADOW_VIEWS
uniform int uShadowViewCount;
uniform mat4 uShadowViews[6];       // camera-relative world -> map uv (of the whole map) and the view's depth
uniform vec4 uShadowTiles[6];       // each view's tile in map uv: min xy, max xy
uniform vec2 uShadowViewUvWorld[6]; // world size of the whole map's uv square at the view's scale (perspective: at unit distance)
uniform vec2 uShadowViewDepth[6];   // near and far of each view's volume
uniform float uShadowViewTexel[6];  // world size of one of its texels (perspective: at unit distance)
uniform float uNormalOffsetTexels;  // bias.normal
#ifdef CASCADES
uniform vec4 uCascadeFar;           // view depth where each cascade ends (the last: shadow.distance)
uniform vec4 uCascadeBlendStart;    // view depth where each cascade starts fading into the next
uniform vec3 uViewForward;          // unit view direction of the camera the cascades were fitted to
uniform vec3 uViewOrigin;           // ... and its position, camera-relative
#endif

int gViewIndex = -1;                // the view the pixel read (the nearer one of a blend), -1 none

// A view's visibility, as shadowVisibility() computes it for the single map.
float viewVisibility(int i, vec3 normal, vec3 toLight, vec3 dx, vec3 dy)
{
    vec4 plain = uShadowViews[i] * vec4(vPosition, 1.0);
    float offset = uNormalOffsetTexels * uShadowViewTexel[i];
#ifdef LIGHT_PERSPECTIVE
    offset *= plain.w;
#endif
    vec4 shadowCoord = plain + uShadowViews[i] * vec4(normal * offset, 0.0);
    if (shadowCoord.w <= 0.0)
        return 1.0;
    vec3 coord = shadowCoord.xyz / shadowCoord.w;
    vec4 tile = uShadowTiles[i];
    if (any(lessThan(coord.xy, tile.xy)) || any(greaterThan(coord.xy, tile.zw)))
        return 1.0;             // outside the view's fitted volume: lit without a test
#ifdef REVERSED_Z
    if (coord.z < 0.0)
        return 1.0;
#else
    if (coord.z > 1.0)
        return 1.0;
#endif
    if (dot(normal, toLight) <= 0.0)
        return 0.0;
    // Taps stay inside the tile (half a texel in), so a wide filter never reads a neighbour.
    gShadowTile = vec4(tile.xy + 0.5 * uShadowTexel, tile.zw - 0.5 * uShadowTexel);
    gShadowUvWorld = uShadowViewUvWorld[i];
    gShadowDepthRange = uShadowViewDepth[i];
#ifdef RECEIVER_PLANE
    // The receiver's plane from the screen-space change of its position, through this view's
    // matrix (derivatives of coord itself are undefined where neighbours pick other views).
    vec4 cx = uShadowViews[i] * vec4(vPosition + dx, 1.0), cy = uShadowViews[i] * vec4(vPosition + dy, 1.0);
    vec3 ddx = cx.xyz / cx.w - coord, ddy = cy.xyz / cy.w - coord;
    float det = ddx.x * ddy.y - ddx.y * ddy.x;
    gReceiverSlope = abs(det) > 1e-20 ? vec2(ddx.z * ddy.y - ddx.y * ddy.z, ddx.x * ddy.z - ddx.z * ddy.x) / det : vec2(0.0);
#endif
    float bias = max(uBiasSlope * (1.0 - dot(normal, toLight)), uBiasMin);
    float cosTheta = clamp(dot(normal, toLight), 0.1, 1.0);
    vec4 alongRay = uShadowViews[i] * vec4(toLight, 0.0);
    float depthPerWorld = (alongRay.z * shadowCoord.w - shadowCoord.z * alongRay.w) / (shadowCoord.w * shadowCoord.w);
    gGrowth = depthPerWorld * sqrt(max(1.0 - cosTheta * cosTheta, 0.0)) / cosTheta;
    gShadowW = shadowCoord.w;
#ifdef BIAS_DEPTH
#ifdef REVERSED_Z
    return filterShadow(coord.xy, coord.z + bias);
#else
    return filterShadow(coord.xy, coord.z - bias);
#endif
#else
#if defined(BIAS_TEXEL)
    bias *= uShadowViewTexel[i];
#if defined(LIGHT_PERSPECTIVE)
    bias *= shadowCoord.w;
#endif
#endif
    vec4 moved = shadowCoord + uShadowViews[i] * vec4(toLight * bias, 0.0);
    return filterShadow(coord.xy, moved.z / moved.w);
#endif
}

float shadowViewsVisibility(vec3 normal, vec3 toLight)
{
    // Screen-space steps of the position, taken here where every pixel of a quad still runs.
    vec3 dx = dFdx(vPosition), dy = dFdy(vPosition);
#ifdef LIGHT_POINT
    vec3 d = vPosition - uLightPosition;
    vec3 a = abs(d);
    int face = a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5));
    gViewIndex = face;
    return viewVisibility(face, normal, toLight, dx, dy);
#else
    float depth = dot(vPosition - uViewOrigin, uViewForward);
    for (int i = 0; i < uShadowViewCount; ++i) {
        if (depth <= uCascadeFar[i]) {
            gViewIndex = i;
            float v = viewVisibility(i, normal, toLight, dx, dy);
            if (i + 1 < uShadowViewCount && depth > uCascadeBlendStart[i]) {
                float t = (depth - uCascadeBlendStart[i]) / max(uCascadeFar[i] - uCascadeBlendStart[i], 1e-30);
                v = mix(v, viewVisibility(i + 1, normal, toLight, dx, dy), t);
            }
            return v;
        }
    }
    return 1.0;                 // beyond shadow.distance
#endif
}

// The overlay colour of a view: cascades red, green, blue, yellow; faces add magenta and cyan.
vec3 viewTint(int i)
{
    const vec3 tints[6] = vec3[6](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0), vec3(1.0, 0.9, 0.2),
                                  vec3(1.0, 0.3, 1.0), vec3(0.2, 1.0, 1.0));
    return i < 0 ? vec3(1.0) : tints[i];
}
#endif
