/* CPU twin of shaders/area_light.glsl: rectangle lights and window portals (docs/rendering.md,
 * "Area lights"). The tests hold the shader to these lines, and the reference tracer shades
 * with them through rd_ref_shade. */
#include "render/shade_ref.h"

#include <math.h>

#define PI_F 3.14159265358979323846f

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize3(float v[3])
{
    float l = sqrtf(dot3(v, v));
    if (l > 1e-20f)
        for (int k = 0; k < 3; k++)
            v[k] /= l;
}

/* One edge's term of Lambert's polygon formula, angle(a, b) n.unit(a x b), for unit a and b:
 * theta / sin(theta) / (2 pi) by the rational fit of Hill and Heitz 2016 ("Real-time area lighting:
 * a journey from research to production", the LTC code's IntegrateEdge), as the shader does. */
static float edge_term(const float a[3], const float b[3], const float n[3])
{
    float x = dot3(a, b), y = fabsf(x);
    float v =
        (0.8543985f + (0.4965155f + 0.0145206f * y) * y) / (3.4175940f + (4.1616724f + y) * y);
    float theta_over_sin = x > 0.0f ? v : 0.5f / sqrtf(fmaxf(1.0f - x * x, 1e-7f)) - v;
    float axb[3];
    cross3(a, b, axb);
    return dot3(n, axb) * theta_over_sin;
}

float rd_ref_rect_form_factor(const float p[3], const float n[3], const rd_light *l)
{
    const float *c = l->position, *u = l->half_width, *v = l->half_height;
    float to_p[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
    if (!(dot3(to_p, l->direction) > 0.0f))
        return 0.0f; /* behind the emitting side */
    /* The unit directions to the corners, clipped to p's horizon (Sutherland-Hodgman against
     * n.x >= 0, one edge at a time): a clipped point lies on the great circle between two
     * corners. The clipped polygon's closing edge runs along the horizon from where it leaves
     * the upper side to where it comes back. */
    const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    float corner[4][3];
    for (int i = 0; i < 4; i++) {
        for (int k = 0; k < 3; k++)
            corner[i][k] = c[k] + su[i] * u[k] + sv[i] * v[k] - p[k];
        normalize3(corner[i]);
    }
    /* Lambert's polygon formula: the cosine-weighted solid angle over pi is
     * 1 / (2 pi) sum over edges of angle(a, b) * n . unit(a x b) (Baum, Rushmeier and Winget
     * 1989, "Improving radiosity solutions through the use of analytically determined
     * form-factors", eq. 4; the same edge integral as Heitz et al. 2016, "Real-time
     * polygonal-light shading with linearly transformed cosines", eq. 11). */
    float sum = 0.0f, exit_p[3] = {0, 0, 0}, entry_p[3] = {0, 0, 0};
    for (int i = 0; i < 4; i++) {
        const float *a = corner[i], *b = corner[(i + 1) % 4];
        float da = dot3(n, a), db = dot3(n, b), dd = da - db, x[3];
        for (int k = 0; k < 3; k++)
            x[k] = a[k] + da / (dd != 0.0f ? dd : 1.0f) * (b[k] - a[k]);
        normalize3(x);
        int in_a = da >= 0.0f, in_b = db >= 0.0f;
        for (int k = 0; k < 3 && in_a && !in_b; k++)
            exit_p[k] = x[k];
        for (int k = 0; k < 3 && !in_a && in_b; k++)
            entry_p[k] = x[k];
        if (in_a || in_b)
            sum += edge_term(in_a ? a : x, in_b ? b : x, n);
    }
    sum += edge_term(exit_p, entry_p, n); /* zero when nothing was clipped */
    float ff = fabsf(sum);                /* the fit carries the 1 / (2 pi) */
    return fminf(ff, 1.0f);
}

float rd_ref_rect_solid_angle(const float p[3], const rd_light *l)
{
    float d[3] = {l->position[0] - p[0], l->position[1] - p[1], l->position[2] - p[2]};
    float d2 = dot3(d, d);
    float area =
        4.0f * sqrtf(dot3(l->half_width, l->half_width) * dot3(l->half_height, l->half_height));
    float cos_l = -dot3(d, l->direction) / fmaxf(sqrtf(d2), 1e-20f);
    if (!(cos_l > 0.0f))
        return 0.0f;
    return fminf(area * cos_l / fmaxf(d2, 1e-20f), 2.0f * PI_F);
}

void rd_ref_rect_representative_point(const float p[3], const float r[3], const rd_light *l,
                                      float q[3])
{
    const float *c = l->position, *u = l->half_width, *v = l->half_height;
    /* Karis 2013 ("Real shading in Unreal Engine 4", area lights): the point of the light
     * nearest the reflected ray stands for the whole light in the specular term. For a
     * rectangle: where the ray meets its plane, clamped into it (Drobot 2014, "Physically
     * based area lights", GPU Pro 5); a ray that runs away from the plane takes the point of
     * the plane it would meet going backwards, clamped the same way, which is the edge nearest
     * its direction. */
    float cp[3] = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
    float denom = dot3(r, l->direction);
    float t = fabsf(denom) > 1e-6f ? dot3(cp, l->direction) / denom : 0.0f;
    float x[3];
    for (int k = 0; k < 3; k++)
        x[k] = p[k] + fabsf(t) * r[k] - c[k];
    float uu = fmaxf(dot3(u, u), 1e-20f), vv = fmaxf(dot3(v, v), 1e-20f);
    float s = fminf(fmaxf(dot3(x, u) / uu, -1.0f), 1.0f);
    float w = fminf(fmaxf(dot3(x, v) / vv, -1.0f), 1.0f);
    for (int k = 0; k < 3; k++)
        q[k] = c[k] + s * u[k] + w * v[k];
}

float rd_ref_rect_specular_solid_angle(float solid_angle, float shininess)
{
    /* The unnormalised Blinn-Phong lobe (N.H)^n covers about 8 pi / (n + 1) sr of light
     * directions (2 pi / (n + 1) in half-vectors, four times that in L near normal incidence):
     * a light larger than that adds no more highlight (Karis 2013's energy normalisation in
     * the Phong form). */
    float lobe = shininess > 0.0f ? 8.0f * PI_F / (shininess + 1.0f) : 2.0f * PI_F;
    return fminf(solid_angle, fminf(lobe, 2.0f * PI_F));
}

float rd_ref_portal_factor(const float p[3], const float l_dir[3], const rd_light *l)
{
    const float *u = l->half_width, *v = l->half_height;
    float uu = dot3(u, u), vv = dot3(v, v);
    if (!(uu > 0.0f && vv > 0.0f))
        return 1.0f; /* no portal */
    float nrm[3];
    cross3(u, v, nrm);
    float denom = dot3(l_dir, nrm);
    if (fabsf(denom) < 1e-12f)
        return 0.0f; /* the light grazes the opening */
    float cp[3] = {l->position[0] - p[0], l->position[1] - p[1], l->position[2] - p[2]};
    float t = dot3(cp, nrm) / denom;
    if (!(t > 0.0f))
        return 0.0f; /* the opening lies the other way */
    float x[3];
    for (int k = 0; k < 3; k++)
        x[k] = p[k] + t * l_dir[k] - l->position[k];
    return fabsf(dot3(x, u)) <= uu && fabsf(dot3(x, v)) <= vv ? 1.0f : 0.0f;
}
