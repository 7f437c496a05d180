/* CPU reference of the renderer's formulas: the tests compare the GPU against these, and the
 * ground-truth tracer (render/ref) shades with them. RENDERING.md sections 1 and 9-HDR. */
#ifndef RENDER_SHADE_REF_H
#define RENDER_SHADE_REF_H

#include "render/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* max(N.H, 0)^n with pow(0, 0) = 1, n <= 0 treated as 0, finite for n up to 1e6. */
float rd_ref_blinn_phong_power(float n_dot_h, float n);

/* Direction to the light L and the factor (attenuation x spot cone) at point p. */
void rd_ref_light_incidence(const rd_light *light, const float p[3], const float n[3], float l[3],
                            float *factor);

/* Rectangle lights and portals (area_light_ref.c, the twin of shaders/area_light.glsl). */
/* The form factor (cosine-weighted solid angle over pi) of rectangle light l seen from p with
 * unit normal n, clipped to p's horizon; 0 behind the light. A Lambertian surface of albedo
 * C_d under radiance I_d reflects C_d I_d times this. */
float rd_ref_rect_form_factor(const float p[3], const float n[3], const rd_light *l);
/* The solid angle of l seen from p (area x cosine / distance^2 at its centre, at most 2 pi). */
float rd_ref_rect_solid_angle(const float p[3], const rd_light *l);
/* The point of l that stands for it in the highlight of the reflected direction r. */
void rd_ref_rect_representative_point(const float p[3], const float r[3], const rd_light *l,
                                      float q[3]);
/* The part of a light's solid angle a Blinn-Phong lobe of exponent n can take in. */
float rd_ref_rect_specular_solid_angle(float solid_angle, float shininess);
/* 1 when the ray from p along l_dir (towards a directional light) passes through l's portal
 * (or l has none), else 0. */
float rd_ref_portal_factor(const float p[3], const float l_dir[3], const rd_light *l);

/* The lit colour of one surface point, section 1: max(C_emissive, C_a I_a + sum(C_d I_d N.L +
 * C_s I_s (N.H)^n)). albedo_scale multiplies C_a and C_d (the diffuse texture), NULL = 1.
 * n is the shading normal after the front-face flip; it need not be unit length. */
void rd_ref_shade(const rd_material *m, const float albedo_scale[3], const float p[3],
                  const float n[3], const float eye[3], const rd_light *lights, int light_count,
                  const float ambient_light[3], float out[3]);

/* Tile joints (rd_material.joint_width; CPU twin of shaders/grout.glsl). The fraction of a
 * pixel footprint of footprint[0] x footprint[1] UV units (the GPU's fwidth) centred at uv
 * that falls in the joint band (a box filter per axis, combined as a union); footprint 0:
 * a point sample, 0 or 1. */
float rd_ref_joint_coverage(const float uv[2], const float joint_width[2],
                            const float footprint[2]);
/* The texture coordinate read for uv (isotropically, at the level log2(texels)): kept four mip
 * texels (texels: the level-0 texels of a
 * tex_w x tex_h image the footprint spans, GLSL's rho; 0 for a point sample) inside the joint
 * band's inner edge, so bilinear and mip filtering never reach the image's grout border. */
void rd_ref_joint_texcoord(const float uv[2], const float joint_width[2], int tex_w, int tex_h,
                           float texels, float st[2]);

/* Wood grain (rd_material.pattern RD_PATTERN_WOOD; CPU twin of shaders/wood.glsl): the scale
 * on C_a and C_d at object-space point p (metres), about 1 with mean 1, the grain running along
 * the object's x axis. footprint is the pixel's size on the surface in metres (the GPU's
 * fwidth; 0 = a point sample): detail finer than it fades to its mean. The shader is compiled
 * with these same constants. */
#define RD_WOOD_RING_SPACING 0.0045f /* m between growth rings (oak: 2-6 mm) */
#define RD_WOOD_AXIS_Y (-0.37f)      /* the log's axis, off the board: long, shallow arcs */
#define RD_WOOD_AXIS_Z (-0.61f)
#define RD_WOOD_WOBBLE 0.011f       /* m of noise on the ring radius */
#define RD_WOOD_RING_CONTRAST 0.22f /* late wood: the scale dips by up to 0.18 */
#define RD_WOOD_BAND_CONTRAST 0.09f /* runs of light and dark years, 1.7 cm */
#define RD_WOOD_PORE_CONTRAST 0.035f
#define RD_WOOD_FIGURE_CONTRAST 0.035f
float rd_ref_wood_grain(const float p[3], float footprint);
/* The grain's direction (rd_material.grain_angle_deg, in the object's x-z plane) as its cosine
 * and sine: the GPU gets these two floats as u_wood_grain_dir, so both sides turn the point by
 * the same numbers. */
void rd_ref_wood_grain_dir(float angle_deg, float dir[2]);
/* The object-space point p turned about y so that the grain's direction lies along x, the
 * point rd_ref_wood_grain takes (lit.vert's v_object); dir (1, 0) leaves p as it is. */
void rd_ref_wood_grain_point(const float p[3], const float dir[2], float q[3]);

/* The tone curves alone, on exposed linear RGB (>= 0), giving display-linear values in [0, 1];
 * NaN in, 0 out. The GPU twins are in shaders/tonemap.glsl. */
void rd_ref_tone_curve(const float c[3], rd_tonemap mode, float white, float out[3]);
/* White balance (matrix of rd_white_balance_matrix) then exposure: the linear values the
 * tone map and rd_read_linear see, clamped to [0, 1e30], NaN to 0. */
void rd_ref_expose(const float radiance[3], float exposure_ev, const float wb[9], float out[3]);
/* Exposure then the tone map, giving display values in [0, 1] (before sRGB encoding). */
void rd_ref_tonemap(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                    float out[3]);
float rd_ref_srgb_encode(float linear);
/* radiance -> the 8-bit sRGB bytes the GPU path writes. */
void rd_ref_display_rgb8(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                         unsigned char out[3]);

#ifdef __cplusplus
}
#endif
#endif
