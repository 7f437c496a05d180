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
