// Lamps in sharp reflections (render/src/emitters.c): a sharp lookup intersects the reflected
// ray with each lamp's unit shape (render/include/render/primitives.h) in the shape's own
// space. The map there is affine, so the world ray P + t R arrives as o + t d with the same t.
#ifdef HAS_REFLECTION
uniform int u_emitter_count; // 0: the probe kept its lamps
uniform int u_emitter_shape[MAX_EMITTERS]; // rd_shape; negative: a plane seen from both sides
uniform mat4 u_emitter_to_local[MAX_EMITTERS];
uniform vec3 u_emitter_ambient[MAX_EMITTERS];
uniform vec3 u_emitter_diffuse[MAX_EMITTERS];
uniform vec3 u_emitter_specular[MAX_EMITTERS];
uniform vec3 u_emitter_emissive[MAX_EMITTERS];
uniform float u_emitter_shininess[MAX_EMITTERS];
uniform vec4 u_emitter_sphere[MAX_EMITTERS]; // world bounding sphere: centre, radius

// 1 / d with zero components as huge numbers of either sign: the slab tests below then give
// +-inf-like bounds instead of NaN (section 11, rays parallel to a box face).
vec3 safe_inverse(vec3 d)
{
    return vec3(abs(d.x) > 1e-30 ? 1.0 / d.x : 1e30, abs(d.y) > 1e-30 ? 1.0 / d.y : 1e30,
                abs(d.z) > 1e-30 ? 1.0 / d.z : 1e30);
}

// The unit box [-0.5, 0.5]^3 from outside: entry t (-1 if missed), n its face's normal.
float unit_box_hit(vec3 o, vec3 d, out vec3 n)
{
    vec3 inv = safe_inverse(d);
    vec3 ta = (-0.5 - o) * inv, tb = (0.5 - o) * inv;
    vec3 lo = min(ta, tb), hi = max(ta, tb);
    float t_in = max(lo.x, max(lo.y, lo.z)), t_out = min(hi.x, min(hi.y, hi.z));
    n = lo.x >= max(lo.y, lo.z) ? vec3(-sign(d.x), 0.0, 0.0)
        : lo.y >= lo.z          ? vec3(0.0, -sign(d.y), 0.0)
                                : vec3(0.0, 0.0, -sign(d.z));
    return t_in > 0.0 && t_in <= t_out ? t_in : -1.0;
}

// The sphere of radius 0.5 from outside.
float unit_sphere_hit(vec3 o, vec3 d, out vec3 n)
{
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 0.25;
    float disc = b * b - a * c;
    n = vec3(0.0, 0.0, 1.0);
    if (c <= 0.0 || disc < 0.0 || a <= 0.0)
        return -1.0;
    float t = (-b - sqrt(disc)) / a;
    n = o + t * d;
    return t;
}

// The unit square at z = 0, facing +Z; two_sided: seen from below too.
float unit_plane_hit(vec3 o, vec3 d, bool two_sided, out vec3 n)
{
    n = vec3(0.0, 0.0, o.z >= 0.0 ? 1.0 : -1.0);
    if (abs(d.z) < 1e-30 || (!two_sided && o.z <= 0.0))
        return -1.0;
    float t = -o.z / d.z;
    vec2 q = o.xy + t * d.xy;
    return all(lessThanEqual(abs(q), vec2(0.5))) ? t : -1.0;
}

// The capped cylinder of radius 0.5 about Z, z in [-0.5, 0.5], from outside: its side or a cap.
float unit_cylinder_hit(vec3 o, vec3 d, out vec3 n)
{
    n = vec3(0.0, 0.0, 1.0);
    float best = -1.0;
    float a = dot(d.xy, d.xy), b = dot(o.xy, d.xy), c = dot(o.xy, o.xy) - 0.25;
    float disc = b * b - a * c;
    if (a > 0.0 && c > 0.0 && disc >= 0.0) {
        float t = (-b - sqrt(disc)) / a;
        vec3 x = o + t * d;
        if (t > 0.0 && abs(x.z) <= 0.5) {
            best = t;
            n = vec3(x.xy, 0.0);
        }
    }
    if (abs(o.z) > 0.5 && abs(d.z) > 1e-30) {
        float t = (sign(o.z) * 0.5 - o.z) / d.z;
        vec2 q = o.xy + t * d.xy;
        if (t > 0.0 && dot(q, q) <= 0.25 && (best < 0.0 || t < best)) {
            best = t;
            n = vec3(0.0, 0.0, sign(o.z));
        }
    }
    return best;
}

// Nearest t > 0 where o + t d meets shape (rd_shape, sign as u_emitter_shape), or -1; n: the
// outward normal there, in the shape's space, not normalised.
float unit_shape_hit(int shape, vec3 o, vec3 d, out vec3 n)
{
    int s = abs(shape);
    return s == 1   ? unit_sphere_hit(o, d, n)
           : s == 2 ? unit_box_hit(o, d, n)
           : s == 3 ? unit_plane_hit(o, d, shape < 0, n)
                    : unit_cylinder_hit(o, d, n);
}

// The nearest lamp along p + t r with 0 < t < t_max: its index (-1 if none), t and the world
// normal there.
int nearest_emitter(vec3 p, vec3 r, float t_max, out float t_hit, out vec3 n_world)
{
    int hit = -1;
    t_hit = t_max;
    n_world = vec3(0.0, 0.0, 1.0);
    for (int i = 0; i < u_emitter_count; i++) {
        // Most rays pass far from every lamp: a test against its bounding sphere first (r is
        // a unit vector) spares them the shape's, which llvmpipe would otherwise run for all
        // four shapes on every pixel.
        vec3 oc = p - u_emitter_sphere[i].xyz;
        float b = dot(oc, r), c = dot(oc, oc) - u_emitter_sphere[i].w * u_emitter_sphere[i].w;
        if (c > 0.0 && (b > 0.0 || b * b < c))
            continue;
        vec3 o = (u_emitter_to_local[i] * vec4(p, 1.0)).xyz;
        vec3 d = mat3(u_emitter_to_local[i]) * r;
        vec3 n;
        float t = unit_shape_hit(u_emitter_shape[i], o, d, n);
        if (t > 0.0 && t < t_hit) {
            t_hit = t;
            hit = i;
            // Normals go by the inverse transpose of the model: the transpose of to_local.
            n_world = transpose(mat3(u_emitter_to_local[i])) * n;
        }
    }
    float l = length(n_world);
    n_world = l > 0.0 ? n_world / l : -r;
    return hit;
}
#endif
