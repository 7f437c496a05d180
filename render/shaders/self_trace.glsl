// Self-reflections (render/src/self_trace.c): the reflected ray against the triangles of the
// fixtures the probe leaves out (its own product and its nearest neighbours), through their
// bounding-volume hierarchy. Layouts: build_node
// and pack_triangle in self_trace.c.
#ifdef SELF_TRACE
uniform samplerBuffer u_self_nodes; // 2 texels a node
uniform samplerBuffer u_self_tris;  // 7 texels a triangle
uniform int u_self_base;            // this object's first triangle in the probe's numbering, -1 none
uniform float u_self_epsilon;       // the tracer's ray offset (metres)

// Where the ray o + t d (inv = 1 / d) enters node i's box before t_max, or -1 if it does not.
float node_entry(int i, vec3 o, vec3 inv, float t_max, out vec4 lo, out vec4 hi)
{
    lo = texelFetch(u_self_nodes, 2 * i);
    hi = texelFetch(u_self_nodes, 2 * i + 1);
    vec3 ta = (lo.xyz - o) * inv, tb = (hi.xyz - o) * inv;
    vec3 near = min(ta, tb), far = max(ta, tb);
    float t_in = max(max(near.x, near.y), max(near.z, 0.0));
    float t_out = min(min(far.x, far.y), min(far.z, t_max));
    return t_in <= t_out ? t_in : -1.0;
}

// The nearest triangle the ray o + t d meets with epsilon < t < t_max, by the tracer's rules
// for secondary rays (ref_trace.c, hit_filter): not the triangle it leaves (gl_PrimitiveID),
// no back face of a closed mesh. -1 when none; else its barycentrics b1, b2 and t. The walk is
// stackless (a threaded hierarchy: Smits 1998, "Efficiency issues for ray tracing"): nodes in
// depth-first order, a box the ray misses (or enters beyond the nearest hit so far) skips its
// subtree. llvmpipe keeps a per-pixel stack in memory, lane by lane, which cost more than the
// boxes a nearer-child-first walk saves.
int self_trace(vec3 o, vec3 d, float t_max, out float t_hit, out vec2 bary)
{
    vec3 inv = safe_inverse(d);
    int own = u_self_base >= 0 ? u_self_base + gl_PrimitiveID : -1;
    int found = -1;
    t_hit = t_max;
    bary = vec2(0.0);
    vec4 lo = texelFetch(u_self_nodes, 0), hi = texelFetch(u_self_nodes, 1);
    int end = hi.w == 0.0 ? int(lo.w) : 1; // the root's subtree: every node
    int node = 0;
    while (node < end) {
        bool enters = node_entry(node, o, inv, t_hit, lo, hi) >= 0.0;
        int count = int(hi.w), first = int(lo.w);
        if (enters && count > 0) {
            for (int i = first; i < first + count; i++) {
                vec4 a = texelFetch(u_self_tris, 7 * i), e1 = texelFetch(u_self_tris, 7 * i + 1),
                     e2 = texelFetch(u_self_tris, 7 * i + 2);
                if (int(e1.w) == own)
                    continue;
                // Moeller and Trumbore 1997
                vec3 pv = cross(d, e2.xyz);
                float det = dot(e1.xyz, pv);
                if (abs(det) < 1e-30)
                    continue;
                float inv_det = 1.0 / det;
                vec3 tv = o - a.xyz;
                float u = dot(tv, pv) * inv_det;
                if (u < 0.0 || u > 1.0)
                    continue;
                vec3 qv = cross(tv, e1.xyz);
                float v = dot(d, qv) * inv_det;
                if (v < 0.0 || u + v > 1.0)
                    continue;
                float t = dot(e2.xyz, qv) * inv_det;
                if (t <= u_self_epsilon || t >= t_hit)
                    continue;
                if (e2.w < 0.5 && !(dot(cross(e1.xyz, e2.xyz), d) < 0.0))
                    continue; // a closed mesh's back face is never rasterised
                t_hit = t;
                bary = vec2(u, v);
                found = i;
            }
        }
        // Into the node's subtree, or past it: an inner node's skip index, a leaf's next node.
        node = enters || count > 0 ? node + 1 : first;
    }
    return found;
}
#endif
