/* CPU reference of the reflection formulas (RENDERING.md sections 2 and 4-9): the shaders are
 * tested against these, and the ground-truth tracer shades with them. No GL. Each formula names
 * its source; vectors are float[3], world coordinates (right-handed, Z up) unless noted. */
#ifndef RENDER_REFLECT_REF_H
#define RENDER_REFLECT_REF_H

#include "render/cube_data.h"
#include "render/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- section 2: the reflection vector ---------------------------------------------------- */

/* Seed 000 eq. 1: R = I - 2 (N.I) N, as GLSL's reflect (I incident, N unit; no normalising). */
void rd_ref_reflect(const float i[3], const float n[3], float r[3]);

/* ---- section 4: the corrected reflection vector (seed 002 eq. 10, Figs. 8-9) -------------- */

/* Box proxy [bmin, bmax] seen from the capture centre c (box projection):
 *   t = min over axes k of max((bmax_k - P_k) / R_k, (bmin_k - P_k) / R_k);  D = P + t R - c.
 * Guards: in the divisions a component with |R_k| < 1e-8 is replaced by copysign(1e-8, R_k)
 * (0/0 never happens); D itself uses the given R (so R = 0 gives D = P - c). P outside the box
 * or on its surface, a degenerate box (bmin_k >= bmax_k on any axis), a non-finite input or
 * result, or D = 0 -> D = R, return 0. Returns 1 when corrected. D is not normalised. */
int rd_ref_correct_box(const float p[3], const float r[3], const float bmin[3], const float bmax[3],
                       const float c[3], float d[3]);
/* Sphere proxy of radius rad around c: t = the positive root of |P + t R - c| = rad,
 * D = P + t R - c. P outside or on the sphere, rad <= 0, R = 0, or a non-finite input or
 * result -> D = R, return 0. Returns 1 when corrected. D is not normalised. */
int rd_ref_correct_sphere(const float p[3], const float r[3], const float c[3], float rad,
                          float d[3]);

/* ---- section 5: gloss-controlled blur (seed 002; seed 001 eq. 6) --------------------------- */

/* n(g) = 2^(13 g), g clamped to [0, 1] (NaN -> 0): g = 0 -> 1, g = 1 -> 8192. */
float rd_ref_gloss_exponent(float g);
/* The linear steps of the "depth" correction's search (reflect.glsl, correct_depth) for a
 * lookup of glossiness g: 32 for a mirror, where a step spans about 1.3 degrees as seen from
 * the probe (a thin rail in front of a wall), and as many as keep a step within the lobe's
 * half-width sqrt(2 ln 2 / n(g)) for a glossy one, 8 at the least: the lobe blurs whatever a
 * finer step would place (a basin's glaze, g = 0.6: 10 steps). */
int rd_depth_search_steps(float g);
/* The level of detail in a prefiltered chain of `levels` mip levels (level 0 = the mirror
 * image): lod(g) = (1 - g) (levels - 1), g clamped as above, levels < 1 taken as 1. */
float rd_ref_gloss_lod(float g, int levels);
/* The normalised Phong lobe ((n + 1) / (2 pi)) max(cos, 0)^n; it integrates to 1 over the
 * hemisphere around its axis. 0 for cos <= 0 (also for n = 0: the lobe lives on the
 * hemisphere); n clamped to [0, 1e6] (NaN -> 0); cos above 1 taken as 1. */
float rd_ref_lobe(float cos_angle, float n);
/* The exponent of level k of a prefiltered chain with `levels` levels: n(g_k) with
 * g_k = 1 - k / (levels - 1) (k clamped to 0 .. levels - 1; levels <= 1 -> g = 1). Level 0 is
 * the unblurred copy: its nominal exponent n(1) = 8192 is returned, but it is never convolved. */
float rd_ref_level_exponent(int level, int levels);

/* The solid angle of texel (i, j) of a face of `size` texels per side: the exact integral of
 * the area element over the texel, A(x, y) = atan2(x y, sqrt(x^2 + y^2 + 1)) at its four
 * corners in face coordinates [-1, 1] (as in AMD CubeMapGen and cmft). The 6 size^2 texels
 * sum to 4 pi. 0 outside the face. */
float rd_ref_texel_solid_angle(int i, int j, int size);

/* Brute-force convolution (section 5 "reference"; slow: for tests and ground truth). For each
 * destination texel direction d:
 *   dst(d) = sum over source texels l of w(d, l) min(src(l), clamp) / sum of w(d, l),
 *   w(d, l) = rd_ref_lobe(dot(d, dir_l), n) * solid_angle(l),
 * by direction over all six faces (no seams). clamp <= 0 (or NaN) means no clamp; the clamp
 * applies to RGB, alpha is averaged unclamped; non-finite source texels count as 0. If every
 * weight of a destination texel underflows to 0 (a huge n on a coarse source), it takes the
 * nearest source texel instead. dst is allocated at dst_size (free it with
 * rd_cube_data_free); on failure it is zeroed. Cost: 36 src_size^2 dst_size^2 lobe
 * evaluations. */
rd_result rd_ref_cube_convolve(const rd_cube_data *src, float n, float clamp, int dst_size,
                               rd_cube_data *dst);

/* ---- section 6: the reflection-intensity blend ------------------------------------------- */

typedef enum rd_blend_mode { RD_BLEND_MIX = 0, RD_BLEND_ADD, RD_BLEND_FRESNEL } rd_blend_mode;

/* Schlick's approximation as seed 001 eq. 15 uses it: F = f0 + (1 - f0) (1 - max(N.V, 0))^5.
 * f0 and N.V are clamped to [0, 1] (NaN N.V -> 0, giving F = 1). */
float rd_ref_fresnel(float f0, float n_dot_v);
/* kr clamped to [0, 1] (NaN -> 0), per channel:
 *   mix (seed 002):        C = (1 - kr) lit + kr refl
 *   add (seed 000 eq. 3, I' = I + k_s p_r C_t, k_s = the material's specular colour,
 *        p_r = kr):        C = lit + kr specular refl
 *   fresnel (seed 001 eqs. 7, 15): F = rd_ref_fresnel(kr, n_dot_v), C = (1 - F) lit + F refl
 * then out = max(emissive, C) (seed 002 eq. 7) as GLSL defines max: C if emissive < C, else
 * emissive (so a tie of +0 and -0 gives emissive, and a NaN C gives emissive).
 * With kr = 0, mix and add skip the reflection term: out = max(emissive, lit) bit for bit
 * (the formula's value, also when refl is not finite or lit is -0). */
void rd_ref_blend(rd_blend_mode mode, float kr, const float specular[3], const float lit[3],
                  const float refl[3], float n_dot_v, const float emissive[3], float out[3]);

/* ---- section 7: irradiance from 9 spherical-harmonic coefficients ------------------------ */

/* Ramamoorthi and Hanrahan 2001, "An efficient representation for irradiance environment
 * maps", eqs. 10-13 (seed 001 eqs. 8-12). Basis order L00, L1-1, L10, L11, L2-2, L2-1, L20,
 * L21, L22, in WORLD coordinates (z up), for a unit (x, y, z):
 *   Y00 = 0.282095;  Y1-1 = 0.488603 y, Y10 = 0.488603 z, Y11 = 0.488603 x;
 *   Y2-2 = 1.092548 xy, Y2-1 = 1.092548 yz, Y20 = 0.315392 (3z^2 - 1), Y21 = 1.092548 xz,
 *   Y22 = 0.546274 (x^2 - y^2).
 * coeff[k] holds the RGB of coefficient k. */
typedef struct rd_sh9 {
    float coeff[9][3];
} rd_sh9;
enum {
    RD_SH_00 = 0,
    RD_SH_1M1,
    RD_SH_10,
    RD_SH_11,
    RD_SH_2M2,
    RD_SH_2M1,
    RD_SH_20,
    RD_SH_21,
    RD_SH_22
};
/* The 9 basis values at a unit WORLD direction, in the order above. */
void rd_ref_sh9_basis(const float dir_world[3], float y[9]);
/* L_lm = sum over all texels of radiance * Y_lm(texel direction) * solid angle (eq. 10 of R&H
 * as a quadrature over the exact texel solid angles). Non-finite texels count as 0; an empty
 * cube gives zeros. */
void rd_ref_sh9_project(const rd_cube_data *c, rd_sh9 *out);
/* The irradiance E(n) itself (R&H eq. 13), NOT divided by pi: a white Lambertian surface
 * reflects E(n) / pi. n need not be unit length (normalised inside; zero or non-finite n gives
 * E = c4 L00 - c5 L20, the n-independent part).
 *   E(n) = c1 L22 (x^2 - y^2) + c3 L20 z^2 + c4 L00 - c5 L20
 *        + 2 c1 (L2-2 xy + L21 xz + L2-1 yz) + 2 c2 (L11 x + L1-1 y + L10 z),
 *   c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708
 * (seed 001 misprints c5 as 0.429043; R&H's value is used). */
void rd_ref_sh9_irradiance(const rd_sh9 *sh, const float n_world[3], float out[3]);

/* ---- section 9: sphere maps (seed 000 eqs. 2, 4, 5) --------------------------------------- */

/* In the map's own frame, where the viewer looks along -Z (so R = (0, 0, 1) points back at the
 * viewer and is the map's centre). Seed 000 eq. 4: A_z = sqrt((R_z + 1) / 2),
 * s_4 = A_x = R_x / (2 A_z), t_4 = A_y = R_y / (2 A_z), both in [-1, 1]; eq. 5 shifts to
 * [0, 1]: s = (s_4 + 1) / 2 = R_x / (4 A_z) + 1/2, t = R_y / (4 A_z) + 1/2 -- the same as
 * GL's GL_SPHERE_MAP texgen (m = 2 sqrt(R_x^2 + R_y^2 + (R_z + 1)^2) = 4 A_z for a unit R), and
 * computed in that form so that the rim stays exact. The map is the disc of radius 1/2 around
 * (1/2, 1/2). R need not be unit length. Guard at A_z -> 0 (R_z = -1, the rim): the point on
 * the rim in the direction of (R_x, R_y), or (1, 0.5) when both are 0. A zero or non-finite R
 * gives the centre (0.5, 0.5). Never NaN. */
void rd_ref_sphere_map_st(const float r[3], float *s, float *t);
/* The inverse, seed 000 eq. 2: A_x = 2s - 1, A_y = 2t - 1, A_z = sqrt(1 - A_x^2 - A_y^2),
 * R = (2 A_z A_x, 2 A_z A_y, 2 A_z^2 - 1), unit length. Outside the disc (s, t) is clamped to
 * the rim (R = (0, 0, -1)); non-finite s or t count as 0.5. */
void rd_ref_sphere_map_direction(float s, float t, float r[3]);
/* Fills a size x size RGBA float sphere map (row j holds t = (j + 0.5) / size, column i holds
 * s = (i + 0.5) / size) from a cube map, sampling bilinear by the direction of each texel.
 * The map's frame is the WORLD frame, i.e. the map is the one seen by a viewer looking down
 * world -Z: its centre shows world up (+Z), its rim world down; texels outside the disc get the
 * rim's direction (0, 0, -1). size 1 .. RD_CUBE_MAX_SIZE. */
rd_result rd_sphere_map_from_cube(const rd_cube_data *c, int size, float *rgba_out);

/* ---- section 9: refraction (seed 003) ---------------------------------------------------- */

/* As GLSL's refract: k = 1 - eta^2 (1 - (N.I)^2); k < 0 -> total internal reflection: T = 0,
 * return 0; else T = eta I - (eta (N.I) + sqrt(k)) N, return 1. eta = n1 / n2, I and N unit,
 * N facing against I. Non-finite input -> T = 0, return 0. */
int rd_ref_refract(const float i[3], const float n[3], float eta, float t[3]);

#ifdef __cplusplus
}
#endif

#endif
