// Rectangle lights and window portals (docs/rendering.md, "Area lights"). Prepended to
// lit.frag in the AREA_LIGHTS variant only (a scene with a rectangle light or a portal), so
// other programs carry none of it. CPU twin: render/src/area_light_ref.c, line for line.
#ifdef AREA_LIGHTS
// A rectangle light's two half edges (world vectors, metres) around its position; for a
// directional light, its portal's (zero: none).
uniform vec3 u_light_half_width[MAX_LIGHTS];
uniform vec3 u_light_half_height[MAX_LIGHTS];
uniform int u_rect_count;             // the rectangle lights among them
uniform int u_rect_index[MAX_LIGHTS]; // their indices

// One edge's term of Lambert's polygon formula, angle(a, b) n.unit(a x b), for unit a and b:
// theta / sin(theta) / (2 pi) by the rational fit of Hill and Heitz 2016 ("Real-time area lighting: a
// journey from research to production", SIGGRAPH course, the LTC code's IntegrateEdge), so no
// acos or atan: those cost llvmpipe more than the rest of a rectangle light together.
float rect_edge(vec3 a, vec3 b, vec3 n)
{
    float x = dot(a, b), y = abs(x);
    float v = (0.8543985 + (0.4965155 + 0.0145206 * y) * y) / (3.4175940 + (4.1616724 + y) * y);
    float theta_over_sin = x > 0.0 ? v : 0.5 * inversesqrt(max(1.0 - x * x, 1e-7)) - v;
    return dot(n, cross(a, b)) * theta_over_sin;
}

// Edge a -> b of the polygon clipped to n.x >= 0 (Sutherland-Hodgman, one edge at a time):
// its part above the horizon, and where it leaves (exit) or enters (entry) the upper side.
// The clipped polygon's closing edge runs along the horizon from the exit to the entry.
// Selects, not branches: llvmpipe would run every side of them.
float rect_clipped_edge(vec3 a, vec3 b, vec3 n, inout vec3 exit_p, inout vec3 entry_p)
{
    float da = dot(n, a), db = dot(n, b);
    float dd = da - db;
    vec3 x = a + (da / (dd != 0.0 ? dd : 1.0)) * (b - a);
    float xl = length(x);
    x = xl > 1e-20 ? x / xl : a;
    bool in_a = da >= 0.0, in_b = db >= 0.0;
    exit_p = in_a && !in_b ? x : exit_p;
    entry_p = !in_a && in_b ? x : entry_p;
    float t = rect_edge(in_a ? a : x, in_b ? b : x, n);
    return in_a || in_b ? t : 0.0;
}

// The form factor (cosine-weighted solid angle over pi) of the rectangle (centre c, half edges
// u and v, lighting the side `dir` points to) seen from p with unit normal n, clipped to p's
// horizon. Lambert's polygon formula (Baum, Rushmeier and Winget 1989, eq. 4; Heitz et al.
// 2016, "Real-time polygonal-light shading with linearly transformed cosines", eq. 11). No
// arrays: llvmpipe spills dynamically indexed arrays to memory, which made this ten times
// dearer.
float rect_form_factor(vec3 p, vec3 n, vec3 c, vec3 dir, vec3 u, vec3 v)
{
    if (!(dot(p - c, dir) > 0.0))
        return 0.0;
    // Unit corners: the clipped points lie on the great circles between them (normalised).
    vec3 c0 = normalize(c - u - v - p), c1 = normalize(c + u - v - p), c2 = normalize(c + u + v - p),
         c3 = normalize(c - u + v - p);
    vec3 exit_p = vec3(0.0), entry_p = vec3(0.0);
    float sum = rect_clipped_edge(c0, c1, n, exit_p, entry_p) +
                rect_clipped_edge(c1, c2, n, exit_p, entry_p) +
                rect_clipped_edge(c2, c3, n, exit_p, entry_p) +
                rect_clipped_edge(c3, c0, n, exit_p, entry_p);
    sum += rect_edge(exit_p, entry_p, n); // zero when nothing was clipped (both at the origin)
    return min(abs(sum), 1.0); // the fit carries the 1 / (2 pi)
}

// The light's solid angle from p: area x cosine / distance^2 at its centre, at most 2 pi.
float rect_solid_angle(vec3 p, vec3 c, vec3 dir, vec3 u, vec3 v)
{
    vec3 d = c - p;
    float d2 = dot(d, d);
    float area = 4.0 * sqrt(dot(u, u) * dot(v, v));
    float cos_l = -dot(d, dir) / max(sqrt(d2), 1e-20);
    if (!(cos_l > 0.0))
        return 0.0;
    return min(area * cos_l / max(d2, 1e-20), 6.28318530718);
}

// The point of the rectangle that stands for it in the highlight of the reflected direction r
// (Karis 2013, "Real shading in Unreal Engine 4"; Drobot 2014, GPU Pro 5): where r meets its
// plane (or would, going backwards), clamped into it.
vec3 rect_representative_point(vec3 p, vec3 r, vec3 c, vec3 dir, vec3 u, vec3 v)
{
    float denom = dot(r, dir);
    float t = abs(denom) > 1e-6 ? dot(c - p, dir) / denom : 0.0;
    vec3 x = p + abs(t) * r - c;
    float s = clamp(dot(x, u) / max(dot(u, u), 1e-20), -1.0, 1.0);
    float w = clamp(dot(x, v) / max(dot(v, v), 1e-20), -1.0, 1.0);
    return c + s * u + w * v;
}

// The part of a light's solid angle an unnormalised Blinn-Phong lobe takes in: about
// 8 pi / (n + 1) sr of light directions (Karis 2013's energy normalisation, Phong form).
float rect_specular_solid_angle(float solid_angle, float shininess)
{
    float lobe = shininess > 0.0 ? 25.1327412287 / (shininess + 1.0) : 6.28318530718;
    return min(solid_angle, min(lobe, 6.28318530718));
}

// 1 when the ray from p along L passes through light i's portal (or it has none), else 0.
float portal_factor(int i, vec3 p, vec3 L, vec3 centre)
{
    vec3 u = u_light_half_width[i], v = u_light_half_height[i];
    float uu = dot(u, u), vv = dot(v, v);
    if (!(uu > 0.0 && vv > 0.0))
        return 1.0;
    vec3 nrm = cross(u, v);
    float denom = dot(L, nrm);
    if (abs(denom) < 1e-12)
        return 0.0;
    float t = dot(centre - p, nrm) / denom;
    if (!(t > 0.0))
        return 0.0;
    vec3 x = p + t * L - centre;
    return abs(dot(x, u)) <= uu && abs(dot(x, v)) <= vv ? 1.0 : 0.0;
}

// Rectangle light i at p (unit normal N, unit view V): its diffuse factor (the form factor,
// times C_d I_d) in .x and its specular factor (times C_s I_s) in .y; L gets the direction to
// its representative point, for the shadow lookup.
vec2 rect_light_terms(int i, vec3 centre, vec3 dir, vec3 p, vec3 N, vec3 V, float shininess,
                      out vec3 L)
{
    vec3 u = u_light_half_width[i], v = u_light_half_height[i];
    float ff = rect_form_factor(p, N, centre, dir, u, v);
    L = N;
    if (!(ff > 0.0))
        return vec2(0.0);
    vec3 q = rect_representative_point(p, reflect(-V, N), centre, dir, u, v);
    vec3 d = q - p;
    float dl = length(d);
    L = dl > 1e-20 ? d / dl : N;
    float spec = 0.0;
    if (dot(N, L) > 0.0) {
        vec3 h = L + V;
        float hl = length(h);
        h = hl > 1e-20 ? h / hl : N;
        float nh = dot(N, h);
        float power = shininess <= 0.0 ? 1.0 : nh <= 0.0 ? 0.0 : exp2(shininess * log2(min(nh, 1.0)));
        spec = power * rect_specular_solid_angle(rect_solid_angle(p, centre, dir, u, v), shininess) /
               3.14159265;
    } else {
        L = normalize(centre - p); // the shadow lookup's direction
    }
    return vec2(ff, spec);
}
#endif
