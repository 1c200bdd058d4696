// Contact shadows (contact.enabled): from the receiver, contact.steps points toward the light
// over contact.length world units, each looked up in the camera's depth of the casters
// (renderer/CameraDepthPass). A point behind the nearest front face there and in front of the
// nearest back face is inside that caster, so in its shadow; one behind both passes behind it,
// lit (a single depth layer cannot tell the two apart, and darkens everything behind a caster
// by a fixed thickness). contact.thickness still bounds how deep a caster may be, for one with
// no back faces (an open mesh). What the screen does not show is not known: the march stops at
// its edges. The lit pass takes the smaller of this and the map's visibility.
uniform sampler2D uCameraDepths;    // the casters' distance along the view: nearest front faces (r), back faces (g); kNoCasterDepth none
#include LitFrameBlock               // uCameraViewProjection, uCameraForward, uContact*

// 1 lit, 0 in a caster's contact shadow. Called in uniform control flow: it takes derivatives.
float contactVisibility(vec3 position, vec3 toLight)
{
    float depth = dot(position, uCameraForward);
    // A pixel's depth sample may lie up to about a pixel's depth change in front of the very
    // surface the march starts from, where the camera sees it at a grazing angle.
    float tolerance = 1.5 * fwidth(depth) + 1e-4 * depth;
    float reach = uContactLength;
#ifdef LIGHT_PERSPECTIVE
    reach = min(reach, distance(uLightPosition, position));     // never past the light
#endif
    // The march's ends on screen: clip coordinates are linear in the point, so each step is
    // a blend of the two, and so is its depth along the view.
    vec4 clipStart = uCameraViewProjection * vec4(position, 1.0);
    vec4 clipEnd = uCameraViewProjection * vec4(position + toLight * reach, 1.0);
    float depthEnd = dot(position + toLight * reach, uCameraForward);
    // Each pixel's steps start at its own offset (interleaved gradient noise): noise that
    // neighbours average, not bands.
    float start = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec2 size = vec2(textureSize(uCameraDepths, 0));
    for (int i = 0; i < uContactSteps; ++i) {
        float t = (float(i) + start) / float(uContactSteps);
        vec4 clip = mix(clipStart, clipEnd, t);
        if (clip.w <= 0.0)
            break;
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
            break;
        vec2 faces = texelFetch(uCameraDepths, ivec2(uv * size), 0).rg;
        // Behind the front face by more than the tolerance and less than the thickness, and
        // in front of the back face (or there is none): inside a caster.
        float pointDepth = mix(depth, depthEnd, t);
        float behind = pointDepth - faces.r;
        if (behind > tolerance && behind < uContactThickness && (faces.g >= kNoCasterDepth || pointDepth < faces.g + tolerance))
            return 0.0;
    }
    return 1.0;
}
