// Contact shadows (contact.enabled): from the receiver, contact.steps points toward the light
// over contact.length world units, each looked up in the camera's depth of the casters
// (renderer/CameraDepthPass). A point behind the nearest front face there and in front of the
// nearest back face is inside that caster, so in its shadow; one behind both passes behind it,
// lit (a single depth layer cannot tell the two apart, and darkens everything behind a caster
// by a fixed thickness). contact.thickness still bounds how deep a caster may be, for one with
// no back faces (an open mesh). What the screen does not show is not known: the march stops at
// its edges. The lit pass takes the smaller of this and the map's visibility.
uniform sampler2D uCameraFront;     // window depth of the casters' front faces, this frame's camera, nearest
uniform sampler2D uCameraBack;      // ... of their back faces
uniform mat4 uCameraViewProjection; // camera-relative world -> clip
uniform vec3 uCameraForward;        // unit view direction
uniform vec2 uCameraPlanes;         // near and far
uniform float uContactLength;       // world units
uniform float uContactThickness;    // world units
uniform int uContactSteps;

// Distance along the view direction of a window depth of the camera's perspective projection.
float cameraViewDepth(float windowDepth)
{
    float n = uCameraPlanes.x, f = uCameraPlanes.y;
    return 2.0 * n * f / (f + n - (2.0 * windowDepth - 1.0) * (f - n));
}

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
    float stepLength = reach / float(uContactSteps);
    // Each pixel's steps start at its own offset (interleaved gradient noise): noise that
    // neighbours average, not bands.
    float start = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec2 size = vec2(textureSize(uCameraFront, 0));
    for (int i = 0; i < uContactSteps; ++i) {
        vec3 point = position + toLight * (stepLength * (float(i) + start));
        vec4 clip = uCameraViewProjection * vec4(point, 1.0);
        if (clip.w <= 0.0)
            break;
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
            break;
        ivec2 texel = ivec2(uv * size);
        float front = texelFetch(uCameraFront, texel, 0).r;
        if (front >= 1.0)
            continue;           // no caster there
        float pointDepth = dot(point, uCameraForward);
        float behind = pointDepth - cameraViewDepth(front);
        float back = texelFetch(uCameraBack, texel, 0).r;
        bool inside = back >= 1.0 || pointDepth < cameraViewDepth(back) + tolerance;
        if (behind > tolerance && behind < uContactThickness && inside)
            return 0.0;
    }
    return 1.0;
}
