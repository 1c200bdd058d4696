// Page requests of a virtual shadow map: each receiver pixel the camera sees writes the page it
// needs (virtual_pages.glsl), packed by virtualPackRequest (shared/virtual_levels.glsl); 0 where
// nothing that receives a shadow is seen. Read back and deduplicated on the CPU.
#include "virtual_pages.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vColour;
in vec4 vShadowCoord;

uniform bool uReceives;

layout(location = 0) out uint request;

void main()
{
    vec2 q0 = (uVirtualLight * vec4(vPosition, 1.0)).xy;
    vec2 dqx = dFdx(q0), dqy = dFdy(q0);
    vec2 q;
    int level = virtualRequestLevel(q0, dqx, dqy, q);
    if (!uReceives || level < 0) {
        request = 0u;
        return;
    }
    ivec2 page = clamp(ivec2(floor(q)), ivec2(0), ivec2(kVirtualLevelPages - 1));
    request = virtualPackRequest(level, page);
}
