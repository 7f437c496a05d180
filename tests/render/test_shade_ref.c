/* The CPU reference at the numerical extremes (RENDERING.md sections 1 and 11): every result
 * finite and in the expected range, and the formulas' special cases exactly as specified. */
#include "../common/check.h"
#include "render/shade_ref.h"

#include <math.h>
#include <string.h>

static int finite3(const float c[3])
{
    return isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2]);
}

int main(void)
{
    /* pow(N.H, n): pow(0, 0) = 1, n = 0 gives 1, N.H <= 0 gives 0, huge n finite. */
    CHECK(rd_ref_blinn_phong_power(0.0f, 0.0f) == 1.0f);
    CHECK(rd_ref_blinn_phong_power(0.3f, 0.0f) == 1.0f);
    CHECK(rd_ref_blinn_phong_power(-0.5f, 64.0f) == 0.0f);
    CHECK(rd_ref_blinn_phong_power(0.0f, 64.0f) == 0.0f);
    CHECK(rd_ref_blinn_phong_power(1.0f, 10000.0f) == 1.0f);
    CHECK(rd_ref_blinn_phong_power(1.0000001f, 1e6f) == 1.0f); /* rounding above 1 */
    CHECK(fabsf(rd_ref_blinn_phong_power(0.5f, 1.0f) - 0.5f) < 1e-6f);
    CHECK(fabsf(rd_ref_blinn_phong_power(0.9f, 64.0f) - powf(0.9f, 64.0f)) < 1e-6f);
    float tiny = rd_ref_blinn_phong_power(0.999f, 10000.0f);
    CHECK(isfinite(tiny) && tiny >= 0.0f && tiny < 1e-4f);
    CHECK(rd_ref_blinn_phong_power(NAN, 10.0f) == 0.0f);

    rd_material m = {.ambient = {0.1f, 0.1f, 0.1f},
                     .diffuse = {0.5f, 0.5f, 0.5f},
                     .specular = {1, 1, 1},
                     .shininess = 10000.0f};
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0, 0, 1},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 0}};
    float ia[3] = {1, 1, 1}, p[3] = {0, 0, 0}, n[3] = {0, 0, 1}, eye[3] = {0, 0, 2}, c[3];

    /* Light and eye straight above: N.L = 1, N.H = 1: ambient + diffuse + full specular. */
    rd_ref_shade(&m, NULL, p, n, eye, &l, 1, ia, c);
    CHECK(fabsf(c[0] - (0.1f + 0.5f + 1.0f)) < 1e-5f);

    /* Light below the surface: no diffuse, no specular. */
    l.position[2] = -1.0f;
    rd_ref_shade(&m, NULL, p, n, eye, &l, 1, ia, c);
    CHECK(fabsf(c[0] - 0.1f) < 1e-6f);
    l.position[2] = 1.0f;

    /* Emissive max per channel: wins in red, loses in green and blue. */
    m.emissive[0] = 5.0f;
    m.emissive[1] = 0.01f;
    rd_ref_shade(&m, NULL, p, n, eye, &l, 1, ia, c);
    CHECK(c[0] == 5.0f && fabsf(c[1] - 1.6f) < 1e-5f && fabsf(c[2] - 1.6f) < 1e-5f);
    memset(m.emissive, 0, sizeof m.emissive);

    /* Zero-length normal, eye at the point, light at the point, back-facing normal. */
    float zero[3] = {0, 0, 0};
    rd_ref_shade(&m, NULL, p, zero, eye, &l, 1, ia, c);
    CHECK(finite3(c));
    rd_ref_shade(&m, NULL, p, n, p, &l, 1, ia, c);
    CHECK(finite3(c));
    l.attenuation[0] = 0.0f;
    l.attenuation[2] = 1.0f;
    memcpy(l.position, p, sizeof p);
    rd_ref_shade(&m, NULL, p, n, eye, &l, 1, ia, c);
    CHECK_MSG(finite3(c), "light at the surface point with pure inverse-square attenuation");
    float back[3] = {0, 0, -1};
    l.position[2] = 1.0f;
    rd_ref_shade(&m, NULL, p, back, eye, &l, 1, ia, c);
    CHECK(finite3(c) && fabsf(c[0] - 0.1f) < 1e-6f);

    /* Spot: full inside the inner cone, zero outside the outer, smooth and safe when equal. */
    rd_light s = {.type = RD_LIGHT_SPOT,
                  .position = {0, 0, 1},
                  .direction = {0, 0, -1},
                  .attenuation = {1, 0, 0},
                  .spot_inner_cos = cosf(0.2f),
                  .spot_outer_cos = cosf(0.4f)};
    float L[3], k;
    rd_ref_light_incidence(&s, p, n, L, &k);
    CHECK(fabsf(k - 1.0f) < 1e-6f);
    float far_p[3] = {10, 0, 0};
    rd_ref_light_incidence(&s, far_p, n, L, &k);
    CHECK(k == 0.0f);
    s.spot_outer_cos = s.spot_inner_cos;
    rd_ref_light_incidence(&s, far_p, n, L, &k);
    CHECK(isfinite(k));

    /* Scenes from 1 mm to 10 km: attenuation stays finite and positive. */
    rd_light d = l;
    d.attenuation[0] = 1.0f;
    float p_far[3] = {1e4f, 0, 0};
    rd_ref_light_incidence(&d, p_far, n, L, &k);
    CHECK(isfinite(k) && k > 0.0f);

    /* Tone map: HDR 1e6, NaN and Inf give display values in [0, 1]; black stays black. */
    float hdr[3] = {1e6f, 1e6f, 1e6f}, out[3];
    rd_ref_tonemap(hdr, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, out);
    CHECK(out[0] == 1.0f && out[1] == 1.0f && out[2] == 1.0f);
    float bad[3] = {NAN, INFINITY, -1.0f};
    rd_ref_tonemap(bad, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, out);
    CHECK(finite3(out) && out[0] >= 0.0f && out[0] <= 1.0f && out[2] >= 0.0f);
    float black[3] = {0, 0, 0};
    rd_ref_tonemap(black, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, out);
    CHECK(out[0] == 0.0f);
    /* Reinhard eq. 4: L_white maps to 1, and L = 1 maps to (1 + 1/16) / 2 for L_white = 4. */
    float white[3] = {4, 4, 4};
    rd_ref_tonemap(white, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, out);
    CHECK(fabsf(out[1] - 1.0f) < 1e-5f);
    float one[3] = {1, 1, 1};
    rd_ref_tonemap(one, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, out);
    CHECK(fabsf(out[1] - 0.53125f) < 1e-5f);
    rd_ref_tonemap(one, 1.0f, RD_TONEMAP_CLAMP, 0.0f, out);
    CHECK(out[0] == 1.0f);
    float half[3] = {0.25f, 0.25f, 0.25f};
    rd_ref_tonemap(half, 1.0f, RD_TONEMAP_CLAMP, 0.0f, out);
    CHECK(fabsf(out[0] - 0.5f) < 1e-6f);

    /* sRGB: the two ends and the linear segment. */
    CHECK(rd_ref_srgb_encode(0.0f) == 0.0f);
    CHECK(fabsf(rd_ref_srgb_encode(1.0f) - 1.0f) < 1e-6f);
    CHECK(fabsf(rd_ref_srgb_encode(0.001f) - 0.01292f) < 1e-7f);
    CHECK(fabsf(rd_ref_srgb_encode(0.5f) - 0.7353569f) < 1e-5f);
    return check_report("shade_ref");
}
