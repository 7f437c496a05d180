// Shadow visibility from the shadow-map atlas (docs/rendering.md, "Shadows"). Prepended to
// lit.frag in the HAS_SHADOWS variant only, so programs without shadows carry none of it. The
// CPU twin is the shadow-ray code of render/ref/src/ref_shadow.c: the same disk of taps
// (rd_shadow_disk_tap), the same receiver offsets, a ray where this file reads the map; the
// tracer takes every tap, this file stops after two where they agree (shadow_visibility).
#ifdef HAS_SHADOWS
uniform sampler2DShadow u_shadow_atlas; // window depth of the nearest caster
uniform vec2 u_shadow_origin[MAX_LIGHTS]; // atlas uv of the light's first tile (face 0)
uniform int u_shadow_cube[MAX_LIGHTS];  // 1: six tiles, faces by major axis; 0: one tile
uniform mat4 u_shadow_matrix[MAX_LIGHTS]; // one-tile lights: world -> the light's clip space
uniform vec2 u_shadow_texel[MAX_LIGHTS];  // a texel's world size at distance d: x + y d
// Window depth of a view depth z: perspective A - B / z (x = A, y = B); orthographic: the
// depth range in metres (z).
uniform vec3 u_shadow_depth[MAX_LIGHTS];
uniform vec4 u_shadow_grid; // a tile's width and height in atlas uv, 1 / face texels, 0
uniform int u_shadow_taps;  // 1: hard (one bilinear comparison); else soft, on a Vogel disk
uniform float u_shadow_softness; // the disk's radius at the receiver, metres
uniform vec2 u_shadow_sample_offset; // the window's origin in the whole image, in samples
uniform vec2 u_shadow_disk[64]; // the unturned Vogel disk of u_shadow_taps (rd_shadow_disk_tap)

// One bilinear depth comparison in the tile at atlas uv `origin`, at tile-local uv; 1 = lit.
float shadow_compare(vec2 origin, vec2 uv, float ref)
{
    // A tap never reads a neighbouring tile: clamp a texel inside the tile's edge.
    uv = clamp(uv, vec2(u_shadow_grid.z), vec2(1.0 - u_shadow_grid.z));
    return texture(u_shadow_atlas, vec3(origin + uv * u_shadow_grid.xy, ref));
}

// Whether point q sees cube light i (a point light or a wide spot) in its shadow map; 1 = lit.
float shadow_cube_tap(int i, vec3 light_pos, vec3 q, float bias)
{
    // The face by the major axis, and (right, up) . d / fwd . d in that face's frame:
    // shadow.c renders face f with glm_lookat(L, L + fwd, up), fwd = +X, -X, +Y, -Y, +Z, -Z,
    // up = +Z for the four sides and +Y for the caps, so right = fwd x up is, in order,
    // -Y, +Y, +X, -X, -X, +X. Plain arithmetic: llvmpipe indexes constant arrays slowly.
    // Selects, not branches: llvmpipe runs both sides of a branch that varies per pixel.
    vec3 d = q - light_pos;
    vec3 a = abs(d);
    bool on_x = a.x >= a.y && a.x >= a.z, on_y = !on_x && a.y >= a.z;
    float z = max(on_x ? a.x : on_y ? a.y : a.z, 1e-9);
    vec2 xy = on_x ? vec2(d.x > 0.0 ? -d.y : d.y, d.z)
              : on_y ? vec2(d.y > 0.0 ? d.x : -d.x, d.z)
                     : vec2(d.z > 0.0 ? -d.x : d.x, d.y);
    float f = on_x ? (d.x > 0.0 ? 0.0 : 1.0) : on_y ? (d.y > 0.0 ? 2.0 : 3.0)
                                                   : (d.z > 0.0 ? 4.0 : 5.0);
    vec2 uv = xy / z * 0.5 + 0.5;
    // The bias is along the ray; along the face's axis it shrinks by z / |d|.
    float zb = max(z - bias * z / length(d), 1e-6);
    return shadow_compare(u_shadow_origin[i] + vec2(f * u_shadow_grid.x, 0.0), uv,
                          u_shadow_depth[i].x - u_shadow_depth[i].y / zb);
}

// Whether point q sees one-tile light i (a narrow spot or a directional light); 1 = lit.
float shadow_tile_tap(int i, vec3 light_pos, vec3 q, float bias)
{
    vec4 c = u_shadow_matrix[i] * vec4(q, 1.0);
    if (!(c.w > 0.0))
        return 1.0;
    vec3 ndc = c.xyz / c.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
        return 1.0; // outside the light's map: nothing there casts
    // Perspective (spot): clip w is the view depth; orthographic: window depth is linear.
    float ref = u_shadow_depth[i].z > 0.0
                    ? ndc.z * 0.5 + 0.5 - bias / u_shadow_depth[i].z
                    : u_shadow_depth[i].x - u_shadow_depth[i].y / max(c.w - bias * c.w / length(q - light_pos), 1e-6);
    return shadow_compare(u_shadow_origin[i], uv, ref);
}

// An orthonormal basis around unit a (Duff et al. 2017), as the tracer builds it.
void shadow_basis(vec3 a, out vec3 t, out vec3 b)
{
    float sign = a.z >= 0.0 ? 1.0 : -1.0;
    float p = -1.0 / (sign + a.z);
    float q = a.x * a.y * p;
    t = vec3(1.0 + sign * a.x * a.x * p, sign * q, -sign * a.x);
    b = vec3(q, sign + a.y * a.y * p, -a.y);
}

// This sample's disk axes, scaled by the softness (shadow_begin, once per fragment).
vec3 g_shadow_t, g_shadow_b;

// The disk lies in the receiver's tangent plane: it never shadows its own surface. A random turn
// per sample (interleaved gradient noise, Jimenez 2014, of the sample's place in the whole
// image) lets supersampling average differently placed taps; the turned disk is the disk in
// the turned frame, so no sine per tap.
void shadow_begin(vec3 N)
{
    if (u_shadow_taps <= 1)
        return;
    vec3 t, b;
    shadow_basis(N, t, b);
    vec2 sample_pos = floor(gl_FragCoord.xy) + u_shadow_sample_offset;
    float turn = 6.28318531 * fract(52.9829189 * fract(dot(sample_pos, vec2(0.06711056, 0.00583715))));
    float c = cos(turn), s = sin(turn);
    g_shadow_t = (c * t + s * b) * u_shadow_softness;
    g_shadow_b = (c * b - s * t) * u_shadow_softness;
}

// Tap k's lookup point around base: the disk turned by shadow_begin; hard shadows read base.
vec3 shadow_tap_point(vec3 base, int k)
{
    if (u_shadow_taps <= 1)
        return base;
    return base + u_shadow_disk[k].x * g_shadow_t + u_shadow_disk[k].y * g_shadow_b;
}

// The fraction of light i that reaches p (normal N, unit direction to the light L).
float shadow_visibility(int i, int type, vec3 light_pos, vec3 p, vec3 N, vec3 L)
{
    float dist = type == 2 ? 0.0 : length(light_pos - p);
    float texel = u_shadow_texel[i].x + u_shadow_texel[i].y * dist;
    // Bias guarded: a texel and a half, more on grazing surfaces, never more than six texels
    // (peter-panning); the lookup point moves a texel off the surface along its normal.
    float n_dot_l = clamp(dot(N, L), 0.05, 1.0);
    float slope = sqrt(1.0 - n_dot_l * n_dot_l) / n_dot_l;
    float bias = texel * min(1.5 + 2.0 * slope, 6.0);
    vec3 base = p + N * texel;
    // Loops where a branch on the light's kind would be: llvmpipe computes both sides of an if
    // (a cube tap and a one-tile tap, two texture reads, for every tap), but it leaves a loop
    // as soon as no pixel of the block needs another turn, so each light runs only its own
    // kind of tap, and none where the light does not reach (the caller's if).
    int taps = u_shadow_taps <= 1 ? 1 : u_shadow_taps;
    int cube = u_shadow_cube[i];
    // Adaptive taps: the two outermost taps of the disk first (137 degrees apart on it); where
    // both see the light, or both see none, the rest of the disk almost always agrees (no
    // penumbra reaches this sample), so the sample takes their answer; only where they disagree
    // does it take all its taps. Other samples of the pixel turn their disks differently, so a
    // penumbra the two taps missed is still found by its neighbours. Most of a print's pixels
    // lie outside any penumbra, so this saves most of their taps (docs/benchmarks.md).
    int first = taps > 2 ? 2 : taps;
    float sum = 0.0;
    for (int k = 0; k < (cube == 1 ? first : 0); k++)
        sum += shadow_cube_tap(i, light_pos, shadow_tap_point(base, taps - 1 - k), bias);
    for (int k = 0; k < (cube == 1 ? 0 : first); k++)
        sum += shadow_tile_tap(i, light_pos, shadow_tap_point(base, taps - 1 - k), bias);
    bool settled = taps > first && (sum >= float(first) - 1e-3 || sum <= 1e-3);
    int rest = settled ? 0 : taps - first;
    for (int k = 0; k < (cube == 1 ? rest : 0); k++)
        sum += shadow_cube_tap(i, light_pos, shadow_tap_point(base, taps - 1 - first - k), bias);
    for (int k = 0; k < (cube == 1 ? 0 : rest); k++)
        sum += shadow_tile_tap(i, light_pos, shadow_tap_point(base, taps - 1 - first - k), bias);
    return settled ? sum / float(first) : sum / float(taps);
}
#endif
