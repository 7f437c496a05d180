// Reflection lookup, shared by the programs that reflect. RENDERING.md sections 2-6; the CPU
// twins are in render/src/reflect_ref.c and render/src/cube_*.c.

// World (Z up) to GL's cube-map coordinates: seed 000 eq. 7, M_rot (x, y, z) -> (x, -z, y).
vec3 world_to_cmcs(vec3 w)
{
    return vec3(w.x, -w.z, w.y);
}

// Section 4, box proxy: t = min over axes of max((bmax - P)/R, (bmin - P)/R); D = P + tR - c.
// A zero component of R is nudged to +-1e-8 so 0/0 never happens; P outside the box, a
// degenerate box or a non-finite result fall back to R.
vec3 correct_box(vec3 p, vec3 r, vec3 bmin, vec3 bmax, vec3 c)
{
    if (any(greaterThanEqual(bmin, bmax)) || any(lessThanEqual(p, bmin)) ||
        any(greaterThanEqual(p, bmax)))
        return r;
    vec3 rs = vec3(r.x >= 0.0 ? max(r.x, 1e-8) : min(r.x, -1e-8),
                   r.y >= 0.0 ? max(r.y, 1e-8) : min(r.y, -1e-8),
                   r.z >= 0.0 ? max(r.z, 1e-8) : min(r.z, -1e-8));
    vec3 far_t = max((bmax - p) / rs, (bmin - p) / rs);
    float t = min(min(far_t.x, far_t.y), far_t.z);
    vec3 d = p + t * r - c;
    return (isinf(t) || isnan(t) || dot(d, d) == 0.0) ? r : d;
}

// The far end of the box proxy along the ray from p (the t of correct_box), or -1 when the box
// gives none (p outside it, a degenerate box).
float box_exit(vec3 p, vec3 r, vec3 bmin, vec3 bmax)
{
    if (any(greaterThanEqual(bmin, bmax)) || any(lessThanEqual(p, bmin)) ||
        any(greaterThanEqual(p, bmax)))
        return -1.0;
    vec3 rs = vec3(r.x >= 0.0 ? max(r.x, 1e-8) : min(r.x, -1e-8),
                   r.y >= 0.0 ? max(r.y, 1e-8) : min(r.y, -1e-8),
                   r.z >= 0.0 ? max(r.z, 1e-8) : min(r.z, -1e-8));
    vec3 far_t = max((bmax - p) / rs, (bmin - p) / rs);
    float t = min(min(far_t.x, far_t.y), far_t.z);
    return (isinf(t) || isnan(t) || t <= 0.0) ? -1.0 : t;
}

// How far the point o (relative to the probe centre) lies in front of what the probe saw in
// its direction: the stored distance minus |o|; > 0 in front of the surface, < 0 behind it.
float depth_gap(samplerCube dist, vec3 o)
{
    return textureLod(dist, world_to_cmcs(o), 0.0).a - length(o);
}

// "depth" correction: distance impostors (Szirmay-Kalos, Aszodi, Lazanyi and Premecz 2005,
// "Approximate ray-tracing on the GPU with distance impostors"). The capture stored in alpha
// the distance from the probe centre c to the surface it saw in each direction, so the
// reflected ray P + tR can be intersected with what the probe saw instead of with a proxy:
// a linear search for the first step that passes from in front of the stored surface to
// behind it, then secant steps between the two. The steps are uniform in a = t / (t + s)
// (s = |P - c|, the homogeneous parameter of the paper), so they are dense where the ray's
// image on the cube map moves fast, near P, and sparse far away; the search ends at the box
// proxy's far wall (nothing of the room lies beyond it). A crossing whose secant does not
// converge onto the stored surface is a silhouette (the ray passes behind a nearer object
// as seen from c) and the search goes on. No crossing: the box-corrected direction.
// u_depth_steps linear steps (rd_depth_search_steps): 32 for a mirror, fewer for a glossy
// lobe, whose blur hides what finer steps would place.
uniform int u_depth_steps;

// The t along the ray o + t r (o relative to the probe centre) of the first crossing after
// t_start that lands on the stored surface, or -1 when the search finds none before t_end;
// `steps` linear steps.
float search_depth(samplerCube dist, vec3 o, vec3 r, float t_start, float t_end, int steps)
{
    const int SECANT_STEPS = 5;
    int LINEAR_STEPS = clamp(steps, 1, 128);
    float s = max(length(o), 1e-3 * t_end);
    float a_start = t_start / (s + t_start), a_end = t_end / (s + t_end);
    float t_prev = t_start, g_prev = t_start > 0.0 ? depth_gap(dist, o + t_start * r) : -1.0;
    for (int i = 1; i <= LINEAR_STEPS; i++) {
        float a = a_start + (a_end - a_start) * float(i) / float(LINEAR_STEPS);
        float t = i == LINEAR_STEPS ? t_end : s * a / (1.0 - a);
        float g = depth_gap(dist, o + t * r);
        if (g <= 0.0 && g_prev > 0.0) {
            // Secant between the last point in front (t_lo, g_lo > 0) and this one behind.
            float t_lo = t_prev, g_lo = g_prev, t_hi = t, g_hi = g, t_hit = t;
            for (int k = 0; k < SECANT_STEPS; k++) {
                t_hit = t_lo + (t_hi - t_lo) * g_lo / max(g_lo - g_hi, 1e-20);
                float gm = depth_gap(dist, o + t_hit * r);
                if (gm > 0.0) {
                    t_lo = t_hit;
                    g_lo = gm;
                } else {
                    t_hi = t_hit;
                    g_hi = gm;
                }
            }
            vec3 hit = o + t_hit * r;
            // On the stored surface within a few per cent of its distance: a hit.
            if (abs(depth_gap(dist, hit)) < 0.03 * length(hit) + 0.25 * (t - t_prev))
                return t_hit;
        }
        t_prev = t;
        g_prev = g;
    }
    return -1.0;
}

vec3 correct_depth(samplerCube dist, vec3 p, vec3 r, vec3 bmin, vec3 bmax, vec3 c)
{
    float t_end = box_exit(p, r, bmin, bmax);
    vec3 fallback = correct_box(p, r, bmin, bmax, c);
    if (t_end <= 0.0)
        return fallback;
    float t = search_depth(dist, p - c, r, 0.0, t_end, u_depth_steps);
    return t > 0.0 ? p - c + t * r : fallback;
}

// Section 4, sphere proxy of radius rad around c: the t > 0 root of |P + tR - c| = rad.
vec3 correct_sphere(vec3 p, vec3 r, vec3 c, float rad)
{
    vec3 o = p - c;
    float a = dot(r, r), b = dot(o, r), cc = dot(o, o) - rad * rad;
    if (rad <= 0.0 || cc >= 0.0 || a <= 0.0)
        return r;
    float t = (-b + sqrt(max(b * b - a * cc, 0.0))) / a;
    vec3 d = o + t * r;
    return (isinf(t) || isnan(t)) ? r : d;
}

// Section 6. Schlick's Fresnel (seed 001): F = f0 + (1 - f0)(1 - max(N.V, 0))^5.
float fresnel_schlick(float f0, float n_dot_v)
{
    float m = 1.0 - clamp(n_dot_v, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * m2 * m2 * m;
}

// mix (seed 002), add (seed 000 eq. 3: I' = I + k_s p_r C_t), fresnel (seed 001).
vec3 blend_reflection(int mode, float kr, vec3 specular, vec3 lit, vec3 refl, float n_dot_v)
{
    if (mode == 1)
        return lit + kr * specular * refl;
    float f = mode == 2 ? fresnel_schlick(kr, n_dot_v) : kr;
    return (1.0 - f) * lit + f * refl;
}

// Seed 000 eq. 4 with eq. 5's shift to [0, 1] (GL's GL_SPHERE_MAP): s = R_x / (4 A_z) + 1/2,
// t = R_y / (4 A_z) + 1/2, A_z = sqrt((R_z + 1) / 2), R in view space. At the rim (R_z -> -1)
// A_z -> 0: the point on the rim in the direction of (R_x, R_y) instead of a division by zero.
vec2 sphere_map_st(vec3 r)
{
    r = normalize(r);
    float az = sqrt(max((r.z + 1.0) * 0.5, 0.0));
    vec2 xy = r.xy;
    float len = length(xy);
    if (az < 1e-4)
        return len > 0.0 ? 0.5 + 0.5 * xy / len : vec2(1.0, 0.5);
    return xy / (4.0 * az) + 0.5;
}

// The inverse: the view-space direction a texel of the sphere map shows (outside the disc, the
// rim). With a = 2s - 1, b = 2t - 1, q = a^2 + b^2: R = (2a sqrt(1-q), 2b sqrt(1-q), 1 - 2q).
vec3 sphere_map_direction(vec2 st)
{
    vec2 ab = st * 2.0 - 1.0;
    float q = dot(ab, ab);
    if (q > 1.0) {
        ab /= sqrt(q);
        q = 1.0;
    }
    float k = 2.0 * sqrt(1.0 - q);
    return vec3(ab * k, 1.0 - 2.0 * q);
}
