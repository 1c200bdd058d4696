// Shared by the 4-moment techniques (shadow/msm.glsl, shadow/msm-hausdorff.glsl): what the
// moments pass stores (depth to the first to fourth power, through the authors' optimised
// quantisation at 16 bits), how the depth-map view reads it, and, in the lit pass, the
// filtered moments and the three-depth distribution both reconstructions start from (Peters
// and Klein 2015).
#include "moments_common.glsl"

#ifdef MOMENTS_16BIT
// Column-major: the authors' row-vector matrix, written row by row.
const mat4 kQuantise = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                            32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                            -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                            39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const mat4 kDequantise = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                              0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                              0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                              0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const float kQuantiseOffset = 0.035955884801;
#endif

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    float square = depth * depth;
    vec4 moments = vec4(depth, square, square * depth, square * square);
#ifdef MOMENTS_16BIT
    vec4 quantised = kQuantise * moments;
    quantised.x += kQuantiseOffset;
    return quantised;
#else
    return moments;
#endif
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
#ifdef MOMENTS_16BIT
    stored.x -= kQuantiseOffset;
    stored = kDequantise * stored;
#endif
    return stored;              // depth to the first to fourth power, each in [0, 1]
}
#else
// a / b with b kept away from 0 (keeping its sign), so degenerate moments give a finite answer.
float safeDivide(float a, float b)
{
    return a / (abs(b) < 1e-12 ? (b < 0.0 ? -1e-12 : 1e-12) : b);
}

// The filtered moments at `uv`, dequantised and blended toward a flat distribution by
// filter.moment_bias, which keeps their Hankel matrix positive definite.
vec4 biasedMoments(vec2 uv)
{
    vec4 stored = filteredMoments(uv);
#ifdef MOMENTS_16BIT
    stored.x -= kQuantiseOffset;
    stored = kDequantise * stored;
#endif
    return mix(stored, vec4(0.5), uMomentBias);
}

// The depths z.y <= z.z that, with the receiver's z.x = depth, carry a distribution matching
// the moments b: the roots of the quadratic the Cholesky factorisation of b's Hankel matrix
// gives for the receiver.
vec3 momentDepths(vec4 b, float depth)
{
    float L32D22 = -b.x * b.y + b.z;
    float D22 = max(-b.x * b.x + b.y, 1e-12);
    float squaredDepthVariance = -b.y * b.y + b.w;
    float D33D22 = dot(vec2(squaredDepthVariance, -L32D22), vec2(D22, L32D22));
    float invD22 = 1.0 / D22;
    float L32 = L32D22 * invD22;
    // Solve L D L^T c = (1, depth, depth^2) for the quadratic's coefficients.
    vec3 c = vec3(1.0, depth, depth * depth);
    c.y -= b.x;
    c.z -= b.y + L32 * c.y;
    c.y *= invD22;
    c.z *= safeDivide(D22, D33D22);
    c.y -= L32 * c.z;
    c.x -= dot(c.yz, b.xy);
    float p = safeDivide(c.y, c.z);
    float q = safeDivide(c.x, c.z);
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    return vec3(depth, -0.5 * p - r, -0.5 * p + r);
}

// The shadow of the three-depth distribution: the mass at the depths in front of the receiver.
float threeDepthShadow(vec4 b, vec3 z)
{
    vec4 weights = z.z < z.x ? vec4(z.y, z.x, 1.0, 1.0) : (z.y < z.x ? vec4(z.x, z.y, 0.0, 1.0) : vec4(0.0));
    float quotient = safeDivide(weights.x * z.z - b.x * (weights.x + z.z) + b.y, (z.z - weights.y) * (z.x - z.y));
    return clamp(weights.z + weights.w * quotient, 0.0, 1.0);
}
#endif
