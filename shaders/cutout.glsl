// Cut-out surfaces (glTF alphaMode MASK: leaves, fences): where the object's texture alpha is
// below its cut-off the surface is not there. The casters' passes include this with
// ALPHA_CUTOUT, for cut-out objects only. The light's passes read the mask at full resolution
// (CUTOUT_FULL_RESOLUTION), the one the ray-traced reference traces through; the camera's pass
// reads it as the lit pass does, so the march sees what the eye sees.
in vec2 vUv;

uniform sampler2D uCutoutTexture;   // the object's base-colour texture (unit 0)
uniform float uAlphaCutoff;         // textureAlphaCutoff(): the base alpha folded in

bool cutAway()
{
#ifdef CUTOUT_FULL_RESOLUTION
    return textureLod(uCutoutTexture, vUv, 0.0).a < uAlphaCutoff;
#else
    return texture(uCutoutTexture, vUv).a < uAlphaCutoff;
#endif
}
