// Direct light: ambient + Lambert diffuse + Blinn-Phong specular, combined with the emissive
// colour by a per-channel max. RENDERING.md section 1, seed 002 eqs. 1-7. The CPU reference
// render/src/shade_ref.c implements the same lines and the tests hold the two together.
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
#ifdef WOOD_GRAIN
in vec3 v_object;
#endif

uniform vec3 u_eye;
uniform vec3 u_ambient_light; // I_a
uniform float u_specular_scale; // 1; 0 in probe captures that leave highlights out
uniform float u_store_distance; // 1 in probe captures: alpha = distance from u_eye (the centre)
#ifdef SH9_AMBIENT
// A variant of its own: even behind a uniform branch llvmpipe pays for the SH code on every
// pixel, so the constant model's programs do not contain it (section 8).
uniform vec3 u_sh[9]; // L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (world, Z up)
#endif

uniform int u_light_count;
uniform int u_light_type[MAX_LIGHTS]; // 0 point, 1 spot, 2 directional, 3 rect, 4 rect as a point
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_direction[MAX_LIGHTS]; // unit, the direction the light travels
uniform vec3 u_light_diffuse[MAX_LIGHTS];   // I_d
uniform vec3 u_light_specular[MAX_LIGHTS];  // I_s
uniform vec3 u_light_attenuation[MAX_LIGHTS];
uniform vec2 u_light_spot[MAX_LIGHTS]; // cos(inner), cos(outer)
// The main loop's lights by two lists: point and spot lights (and rectangles as points in live
// frames), and the rest (directional); rectangle lights (type 3) have their own loop below.
uniform int u_local_count;
uniform int u_local_index[MAX_LIGHTS];
uniform int u_other_count;
uniform int u_other_index[MAX_LIGHTS];

uniform vec3 u_mat_ambient;
#ifdef BAKED_LIGHT
// The bake's ambient intensity (indirect irradiance / pi, ref/ref_bake.h) replaces I_a.
in vec4 v_baked;
in vec2 v_lightmap_uv;
uniform sampler2D u_lightmap;
uniform int u_bake_from_lightmap;
#endif
uniform vec3 u_mat_diffuse;
uniform vec3 u_mat_specular;
uniform vec3 u_mat_emissive;
uniform float u_mat_shininess;
#ifdef HAS_DIFFUSE_TEXTURE
uniform sampler2D u_diffuse_texture;
uniform vec2 u_uv_scale;
#endif

#ifdef PER_VERTEX_REFLECTION
in vec3 v_reflect;
#endif
#ifdef SPHERE_MAP
uniform sampler2D u_sphere_map;
uniform mat3 u_view_rot; // world to view: the viewer looks down -Z
#endif
#ifdef PLANAR_REFLECTION
uniform sampler2D u_planar;       // a flat mirror's capture from the eye's image (probe_planar.c)
uniform mat4 u_planar_view_proj; // world -> that capture's clip space
#endif
#ifdef HAS_REFLECTION
uniform samplerCube u_probe;
uniform vec3 u_probe_centre;
uniform int u_correction; // 1 none, 2 box, 3 sphere, 4 depth (the stored distances, box beyond)
uniform samplerCube u_probe_distance; // the capture: alpha = distance from the probe centre
uniform samplerCube u_probe_surface;  // "depth" probes: octahedral normal, specular, shininess
uniform int u_surface_highlights;     // 1: the capture left highlights to reflected_highlight
// The room probe (probe.c): the whole scene, its owners included, seen from the room's centre,
// searched beside the object's own probe by the "depth" lookup for what the own centre cannot
// see (behind a nearer object) or leaves out (the object's own product).
uniform int u_room_active;
uniform samplerCube u_room_probe;    // radiance, blurred as u_probe is
uniform samplerCube u_room_distance; // the capture: alpha = distance from u_room_centre
uniform samplerCube u_room_surface;
uniform vec3 u_room_centre;
uniform vec3 u_group_min, u_group_max;   // its probe's objects' joint world box
uniform float u_room_lod;
uniform float u_lobe_exponent;        // n(g) of the blur lobe; 0 for a mirror
uniform vec3 u_proxy_min, u_proxy_max;
uniform float u_proxy_radius;
uniform float u_kr;
uniform float u_lod; // level of detail for the glossiness (0 for a mirror)
uniform int u_blend; // 0 mix, 1 add, 2 fresnel
uniform float u_transparency, u_ior, u_dispersion;
uniform int u_thin; // a double-sided sheet: light passes straight through
// 1: a thin pane blended over what a planar mirror's capture drew behind it (draw.c): the colour
// leaves out what is seen through the pane, alpha is the weight the blend gives it.
uniform int u_pane_over;
#endif

#ifdef GLAZE
// A glaze (glaze.c: glossy tiles and ceramic without a probe of their own) reflects the room
// probe (probe.c), box-corrected to the room and blurred for its highlight's lobe.
uniform samplerCube u_room_probe;
uniform vec3 u_room_centre;
uniform vec3 u_proxy_min, u_proxy_max;
uniform float u_room_lod;
#endif

layout(location = 0) out vec4 frag_color;
// Probe captures of "depth" probes: what a highlight seen from elsewhere needs (probe.c).
layout(location = 1) out vec4 frag_surface;

#ifdef SH9_AMBIENT
// Irradiance from nine SH coefficients, Ramamoorthi and Hanrahan 2001 eq. 13, with their
// c5 = 0.247708 (seed 001 misprints it as 0.429043). CPU twin: rd_ref_sh9_irradiance.
vec3 sh9_irradiance(vec3 n)
{
    const float c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708;
    return c1 * u_sh[8] * (n.x * n.x - n.y * n.y) + c3 * u_sh[6] * n.z * n.z + c4 * u_sh[0] -
           c5 * u_sh[6] + 2.0 * c1 * (u_sh[4] * n.x * n.y + u_sh[7] * n.x * n.z + u_sh[5] * n.y * n.z) +
           2.0 * c2 * (u_sh[3] * n.x + u_sh[1] * n.y + u_sh[2] * n.z);
}
#endif

// max(N.H, 0)^n with pow(0, 0) and n = 0 defined as 1 and n up to 1e6 finite (section 1).
float blinn_phong_power(float n_dot_h, float n)
{
    if (n <= 0.0)
        return 1.0;
    if (n_dot_h <= 0.0)
        return 0.0;
    return exp2(n * log2(min(n_dot_h, 1.0)));
}

// Smooth cone falloff between the outer and the inner cosine; safe when they are equal.
float spot_factor(float cos_angle, vec2 inner_outer)
{
    float t = clamp((cos_angle - inner_outer.y) / max(inner_outer.x - inner_outer.y, 1e-6), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Point or spot light i as seen from x: its unit direction L and the factor of its distance
// attenuation and spot cone; n stands in for L at the light's own position. The main loop's
// point and spot lights take this alone: llvmpipe runs every side of a branch on the type, so
// light_towards' other cases would cost each of them. A rectangle as a point light of its
// power (4, a live frame's main loop) comes with the attenuation (0, 0, pi / A) of its area A
// (draw.c), so k is A / (pi d^2), and turns it into area_light.glsl's rect_solid_angle / pi,
// A cos / (pi d^2) at most 2, by its emitting cosine.
float local_light_towards(int i, vec3 x, vec3 n, out vec3 L)
{
    vec3 d = u_light_position[i] - x;
    float dist = length(d);
    L = dist > 0.0 ? d / dist : n;
    vec3 a = u_light_attenuation[i];
    float k = 1.0 / max(a.x + a.y * dist + a.z * dist * dist, 1e-4);
    float cos_out = dot(-L, u_light_direction[i]);
    if (u_light_type[i] == 1)
        k *= spot_factor(cos_out, u_light_spot[i]);
    else if (u_light_type[i] == 4)
        k = min(k * max(cos_out, 0.0), 2.0);
    return k;
}

// Light i of any type as seen from x: as local_light_towards, 1 for a directional light.
float light_towards(int i, vec3 x, vec3 n, out vec3 L)
{
    if (u_light_type[i] == 2) {
        L = -u_light_direction[i];
#ifdef AREA_LIGHTS
        return portal_factor(i, x, L, u_light_position[i]); // area_light.glsl
#else
        return 1.0;
#endif
    }
    float k = local_light_towards(i, x, n, L);
#ifdef AREA_LIGHTS
    // A rectangle as a point light of its power: the lookups of probe captures (3), and the
    // lookups of a live view's moving frames (4, rd_view.live), which skip its own loop.
    if (u_light_type[i] >= 3)
        return rect_solid_angle(x, u_light_position[i], u_light_direction[i], u_light_half_width[i],
                                u_light_half_height[i]) / 3.14159265;
#endif
    return k;
}

// Octahedral normal encoding (Cigolle et al. 2014, "A survey of efficient representations for
// independent unit vectors"): a unit vector in two numbers.
vec2 sign_not_zero(vec2 v)
{
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

vec2 oct_encode(vec3 n)
{
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
    return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
}

#ifdef HAS_REFLECTION
vec3 oct_decode(vec2 e)
{
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0)
        n.xy = (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
    float l = length(n);
    return l > 0.0 ? n / l : vec3(0.0, 0.0, 1.0);
}

// The highlight (eqs. 3-5) of the surface a "depth" probe saw in direction d, seen from the
// reflecting point p instead of from the probe centre: what the reference's secondary ray
// shades (docs/reference.md). The capture stored that surface's distance, normal, specular and
// shininess and left its highlight out, since a highlight depends on where it is seen from.
vec3 reflected_highlight(samplerCube surface, samplerCube distance, vec3 centre, vec3 d, vec3 p)
{
    vec3 cm = world_to_cmcs(d);
    vec4 sf = textureLod(surface, cm, 0.0);
    float dist = textureLod(distance, cm, 0.0).a;
    float dl = length(d);
    if (sf.w < 0.0 || sf.z <= 0.0 || dist > 6e4 || dl <= 0.0)
        return vec3(0.0);
    vec3 x = centre + d / dl * dist;
    vec3 n = oct_decode(sf.xy);
    // A glossy lookup sees the highlight through its lobe: as Gaussians, a highlight
    // (N.H)^m is exp(-m a^2 / 8) in the reflected direction's angle a and the normalised lobe
    // of exponent b has precision b, so their convolution has exponent m b / (m / 4 + b) and
    // peak b / (m / 4 + b).
    float shininess = sf.w, peak = 1.0;
    if (u_lobe_exponent > 0.0) {
        peak = u_lobe_exponent / (0.25 * shininess + u_lobe_exponent);
        shininess *= peak;
    }
    vec3 v = p - x;
    float vl = length(v);
    v = vl > 0.0 ? v / vl : n;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; i++) {
        vec3 L;
        float k = light_towards(i, x, n, L);
        if (dot(n, L) <= 0.0)
            continue;
        sum += k * sf.z * u_light_specular[i] * blinn_phong_power(dot(n, normalize(L + v)), shininess);
    }
    return peak * sum;
}
#endif

#ifdef HAS_REFLECTION
// A surface at x with unit normal n, seen along the ray direction r (from the reflecting
// point), shaded by eqs. 1-7 with every light and no shadow: how a probe capture draws what it
// sees and the tracer's secondary ray shades it (ref_trace.c, secondary_radiance).
vec3 plain_shade(vec3 x, vec3 n, vec3 r, vec3 c_a, vec3 c_d, vec3 c_s, vec3 c_e, float shininess)
{
#ifdef SH9_AMBIENT
    vec3 lit = c_a * max(sh9_irradiance(n), vec3(0.0)) / 3.14159265;
#else
    vec3 lit = c_a * u_ambient_light;
#endif
    for (int j = 0; j < u_light_count; j++) {
        vec3 L;
        float k = light_towards(j, x, n, L);
        float n_dot_l = dot(n, L);
        if (n_dot_l <= 0.0)
            continue;
        lit += k * c_d * u_light_diffuse[j] * n_dot_l;
        lit += k * c_s * u_light_specular[j] * blinn_phong_power(dot(n, normalize(L - r)), shininess);
    }
    return max(c_e, lit); // eq. 7
}
#endif

#if defined(HAS_REFLECTION) && !defined(PLANAR_REFLECTION)
// What a sharp lookup sees where its ray from p meets a lamp (emitters.glsl) before t_max:
// the lamp shaded by eqs. 1-7 as the tracer's secondary ray shades it, seen from p, without
// shadows or texture as captures draw it. The probe was captured without the lamps
// (emitters.c), so this takes the texel's place; false where the ray meets none.
bool emitter_reflection(vec3 p, vec3 r, float t_max, out vec3 colour)
{
    float t;
    vec3 n;
    int i = nearest_emitter(p, r, t_max, t, n);
    colour = vec3(0.0);
    if (i < 0)
        return false;
    colour = plain_shade(p + t * r, n, r, u_emitter_ambient[i], u_emitter_diffuse[i],
                         u_emitter_specular[i], u_emitter_emissive[i], u_emitter_shininess[i]);
    return true;
}
#endif

#ifdef SELF_TRACE
uniform vec3 u_self_ambient[MAX_SELF_PARTS];
uniform vec3 u_self_diffuse[MAX_SELF_PARTS];
uniform vec3 u_self_specular[MAX_SELF_PARTS];
uniform vec3 u_self_emissive[MAX_SELF_PARTS];
uniform float u_self_shininess[MAX_SELF_PARTS];
uniform float u_self_kr[MAX_SELF_PARTS]; // reflection intensity (section 6), 0: not reflective
uniform int u_self_blend[MAX_SELF_PARTS];
uniform int u_self_slot[MAX_SELF_PARTS]; // its diffuse texture's u_self_textures slot, -1 none
uniform vec2 u_self_uv_scale[MAX_SELF_PARTS];
uniform int u_self_rays; // lobe directions a sample traces (blurred lookups)
uniform sampler2D u_self_textures[MAX_SELF_TEXTURES];

// A sampler array is indexed by constants only where the index is not dynamically uniform.
vec3 self_texture(int slot, vec2 uv)
{
    vec3 c = vec3(1.0);
    if (slot == 0)
        c = textureLod(u_self_textures[0], uv, 0.0).rgb;
    else if (slot == 1)
        c = textureLod(u_self_textures[1], uv, 0.0).rgb;
    else if (slot == 2)
        c = textureLod(u_self_textures[2], uv, 0.0).rgb;
    else if (slot == 3)
        c = textureLod(u_self_textures[3], uv, 0.0).rgb;
    return c;
}

// What the ray from p in direction r meets of the traced fixtures (the product's own parts and
// its nearest neighbours, which the probe leaves out) before t_max (self_trace.glsl), shaded as the tracer's secondary ray shades it (ref_trace.c: the shading
// normal interpolated and turned towards the ray, the texture, eqs. 1-7 seen from p, no
// shadow); false where it meets none. t_max gets the hit's distance.
bool self_reflection(vec3 p, vec3 r, inout float t_max, out vec3 colour)
{
    float t;
    vec2 b;
    colour = vec3(0.0);
    int i = self_trace(p, r, t_max, t, b);
    if (i < 0)
        return false;
    t_max = t;
    vec4 a = texelFetch(u_self_tris, 7 * i), e1 = texelFetch(u_self_tris, 7 * i + 1),
         e2 = texelFetch(u_self_tris, 7 * i + 2), n0 = texelFetch(u_self_tris, 7 * i + 3),
         n1 = texelFetch(u_self_tris, 7 * i + 4), n2 = texelFetch(u_self_tris, 7 * i + 5),
         uv = texelFetch(u_self_tris, 7 * i + 6);
    float b0 = 1.0 - b.x - b.y;
    vec3 n = b0 * n0.xyz + b.x * n1.xyz + b.y * n2.xyz;
    float n_len = length(n);
    n = n_len > 1e-20 ? n / n_len : -r;
    if (!(dot(cross(e1.xyz, e2.xyz), r) < 0.0))
        n = -n; // a back face is lit on the side the ray sees
    int part = int(a.w);
    vec3 albedo = vec3(1.0);
    if (u_self_slot[part] >= 0) {
        vec2 st = b0 * vec2(n0.w, n1.w) + b.x * vec2(n2.w, uv.x) + b.y * uv.yz;
        albedo = self_texture(u_self_slot[part], st * u_self_uv_scale[part]);
    }
    vec3 x = p + t * r;
    colour = plain_shade(x, n, r, u_self_ambient[part] * albedo, u_self_diffuse[part] * albedo,
                         u_self_specular[part], vec3(0.0), u_self_shininess[part]);
    // A reflective part (chrome seen in chrome, or through a pane) shows what it reflects: a
    // second bounce read from the tracing object's probe, box-corrected from the hit (a
    // depth search here costs a third more of a 4K print for no measurable gain), at the
    // level this object's own lookup reads (a level the probe holds). Plain, a chrome part
    // would be its dark diffuse colour where the tracer shows the room in it.
    if (u_self_kr[part] > 0.0) {
        vec3 r2 = reflect(r, n);
        vec3 d2 = correct_box(x, r2, u_proxy_min, u_proxy_max, u_probe_centre);
        vec3 seen = textureLod(u_probe, world_to_cmcs(d2), u_lod).rgb, lamp;
        // A lamp the probe leaves out (emitters.c), met along the reflected ray.
        if (u_emitter_count > 0 && emitter_reflection(x, r2, 1e30, lamp))
            seen = lamp;
        colour = blend_reflection(u_self_blend[part], u_self_kr[part], u_self_specular[part], colour,
                                  seen, dot(n, -r));
    }
    colour = max(u_self_emissive[part], colour); // eq. 7
    return true;
}

// Direction k of `count` a sample from the normalised Phong lobe of exponent n around the
// unit axis, sampled as the tracer samples it (ref_trace.c, lobe_radiance): cos = u^(1 /
// (n + 1)), phi = 2 pi v, u stratified ((stratum + jitter) / strata) and v a shifted golden-
// ratio sequence. The s x s samples of a pixel (u_self_grid = s) share the jitter and shift,
// hashed from the pixel, and take strata of their own, so a pixel's samples stratify its lobe
// together as the tracer's samples of a pixel do. n = 0: the axis (a mirror).
uniform int u_self_grid;

uint hash_u32(uint h)
{
    h = (h ^ (h >> 16)) * 0x7feb352du;
    h = (h ^ (h >> 15)) * 0x846ca68bu;
    return h ^ (h >> 16);
}

vec3 lobe_direction(vec3 axis, float n, int k, int count)
{
    if (n <= 0.0)
        return axis;
    uint grid = uint(max(u_self_grid, 1));
    uvec2 q = uvec2(gl_FragCoord.xy), pixel = q / grid, sub = q % grid;
    int per_pixel = int(grid * grid);
    int stratum = k * per_pixel + int(sub.y * grid + sub.x), strata = count * per_pixel;
    uint h = hash_u32(pixel.x * 1973u + pixel.y * 9277u + 26699u);
    uint j = hash_u32(h + uint(stratum) * 7919u);
    float u = (float(stratum) + float(j & 0xffffu) / 65536.0) / float(strata);
    float v = fract(float(h >> 16) / 65536.0 + float(stratum) * 0.6180339887);
    float cos_t = pow(max(1.0 - u, 1e-30), 1.0 / (n + 1.0));
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    vec3 t = normalize(abs(axis.x) < 0.9 ? cross(axis, vec3(1.0, 0.0, 0.0))
                                         : cross(axis, vec3(0.0, 1.0, 0.0)));
    vec3 bt = cross(axis, t);
    float phi = 6.28318530718 * v;
    return cos_t * axis + sin_t * (cos(phi) * t + sin(phi) * bt);
}
#endif

// Light i's diffuse and specular at the shaded point (eqs. 2-5), given light_towards' factor k
// and direction L; nothing from behind the surface.
vec3 light_contribution(int i, float k, vec3 L, vec3 N, vec3 V, vec3 c_d)
{
    float n_dot_l = dot(N, L);
    if (n_dot_l <= 0.0)
        return vec3(0.0);
#ifdef HAS_SHADOWS
    if (k > 0.0) // no lookup where the light does not reach (outside a spot's cone)
        k *= shadow_visibility(i, u_light_type[i], u_light_position[i], v_world, N, L);
#endif
    vec3 c = k * c_d * u_light_diffuse[i] * n_dot_l; // eq. 2
#ifndef NO_SPECULAR
    // Probe captures that leave highlights to the lookup compile this out (a variant of its
    // own): llvmpipe would evaluate the power for every texel only to scale it by 0.
    vec3 H = normalize(L + V);
    c += u_specular_scale * k * u_mat_specular * u_light_specular[i] *
         blinn_phong_power(dot(N, H), u_mat_shininess); // eqs. 3-5
#endif
    return c;
}

#if defined(HAS_REFLECTION) && !defined(BOX_REFLECTION) && !defined(PER_VERTEX_REFLECTION)
// The "depth" lookup with two probes: the object's own and the room's. Each is searched along
// the reflected ray; a hit of the own probe is a point it saw, but possibly the silhouette of
// a nearer object the ray passes behind as seen from its centre, and the own probe leaves its
// product out. So the room's hit is taken when it lies nearer along the ray (the own probe
// left it out), or when the own hit lies in empty space as the room probe sees it (the own
// centre was looking past an edge). No hit in either: the own probe's box direction.
vec3 pick_depth_hit(vec3 p, vec3 r, out int room)
{
    room = 0;
    vec3 fallback = correct_box(p, r, u_proxy_min, u_proxy_max, u_probe_centre);
    float t_end = box_exit(p, r, u_proxy_min, u_proxy_max);
    if (t_end <= 0.0)
        return fallback;
    vec3 o_own = p - u_probe_centre, o_room = p - u_room_centre;
    float t_own = search_depth(u_probe_distance, o_own, r, 0.0, t_end, u_depth_steps);
    // The room probe sees this object too, so its search starts a texel's width (as the room
    // probe sees p) away from the surface the ray leaves: nearer, the stored surface is p's own.
    // Beyond, the object may meet itself (a model's spout its body), as the tracer's rays do.
    // Its centre is far from p, so the steps, uniform in t / (t + |p - c|), are nearly uniform
    // in t and coarse near p: so twice the own probe's steps.
    float texel = 1.5707963 * length(o_room) / float(textureSize(u_room_distance, 0).x);
    float t_start = min(texel, t_end);
    float t_room = search_depth(u_room_distance, o_room, r, t_start, t_end, 2 * u_depth_steps);
    // Both probes usually find the same surface, and the own probe, nearer the point, places
    // it better: the room's is taken when it is clearly nearer (by a tenth, or 1 cm) and on
    // the product the own probe leaves out (inside its box); elsewhere a nearer room hit is
    // more likely a silhouette the room's centre looks past.
    vec3 h_room = p + t_room * r;
#ifdef SELF_TRACE
    bool on_group = false; // the product's own parts are traced (self_reflection)
#else
    bool on_group = all(greaterThan(h_room, u_group_min)) && all(lessThan(h_room, u_group_max));
#endif
    bool take = t_room > 0.0 && (t_own <= 0.0 || (on_group && t_room < 0.9 * t_own - 0.01));
    if (!take && t_room > 0.0) {
        vec3 h = o_room + t_own * r;
        take = depth_gap(u_room_distance, h) > 0.05 * length(h);
    }
    if (!take)
        return t_own > 0.0 ? o_own + t_own * r : fallback;
    room = 1;
    return o_room + t_room * r;
}
#endif

void main()
{
    vec3 V = u_eye - v_world;
    float v_len = length(V);
    V = v_len > 0.0 ? V / v_len : vec3(0.0, 0.0, 1.0);

    // Zero-length normals face the viewer; back faces (room walls seen from inside, single
    // sided sheets) are lit on the side we see (section 11).
    float n_len = length(v_normal);
    vec3 N = n_len > 1e-20 ? v_normal / n_len : V;
    if (!gl_FrontFacing)
        N = -N;

    vec3 albedo_scale = vec3(1.0);
    float joint = 0.0; // tile joints (grout.glsl)
#ifdef HAS_DIFFUSE_TEXTURE
    albedo_scale = tile_texture(u_diffuse_texture, v_uv * u_uv_scale, joint);
#endif
#ifdef WOOD_GRAIN
    vec3 fw = fwidth(v_object);
    albedo_scale *= wood_grain(v_object, max(fw.x, max(fw.y, fw.z)));
#endif
    vec3 c_a = mix(u_mat_ambient * albedo_scale, u_joint_color, joint);
    vec3 c_d = mix(u_mat_diffuse * albedo_scale, u_joint_color, joint);

    // eq. 1; with SH9 the ambient intensity is the irradiance over pi (a Lambertian surface)
#if defined(BAKED_LIGHT)
    // The glossy lobe reflects C_s (N.V)^2 of the smooth bounced light too (ref_bake_gather.c).
    float n_dot_v = clamp(dot(N, V), 0.0, 1.0);
    vec3 lit = (c_a + u_mat_specular * (n_dot_v * n_dot_v)) *
               (u_bake_from_lightmap != 0 ? texture(u_lightmap, v_lightmap_uv).rgb : v_baked.rgb);
#elif defined(SH9_AMBIENT)
    vec3 lit = c_a * max(sh9_irradiance(N), vec3(0.0)) / 3.14159265;
#else
    vec3 lit = c_a * u_ambient_light;
#endif
#ifdef HAS_SHADOWS
    shadow_begin(N); // this sample's soft-shadow disk, shared by the lights (shadow.glsl)
#endif
    // A fixed-light program (programs.c, rd_lit_program_fixed) knows the lists' lengths: its
    // loops unroll, and each light's uniforms are read once, not per pixel.
#ifdef FIXED_LOCAL_LIGHTS
    for (int j = 0; j < FIXED_LOCAL_LIGHTS; j++) {
#else
    for (int j = 0; j < u_local_count; j++) {
#endif
        int i = u_local_index[j];
        vec3 L;
        float k = local_light_towards(i, v_world, N, L);
        lit += light_contribution(i, k, L, N, V, c_d);
    }
#ifdef FIXED_OTHER_LIGHTS
    for (int j = 0; j < FIXED_OTHER_LIGHTS; j++) {
#else
    for (int j = 0; j < u_other_count; j++) {
#endif
        int i = u_other_index[j];
        vec3 L;
        float k = light_towards(i, v_world, N, L);
        lit += light_contribution(i, k, L, N, V, c_d);
    }
#if defined(AREA_LIGHTS) && !defined(FIXED_LOCAL_LIGHTS)
    // Rectangle lights (area_light.glsl), by a list of their own: a loop bound every pixel
    // shares, where a branch on the light's type would make llvmpipe run this for every light.
    for (int r = 0; r < u_rect_count; r++) {
        int i = u_rect_index[r];
        vec3 L;
        vec2 t = rect_light_terms(i, u_light_position[i], u_light_direction[i], v_world, N, V,
                                  u_mat_shininess, L);
#ifdef HAS_SHADOWS
        if (t.x > 0.0)
            t *= shadow_visibility(i, 3, u_light_position[i], v_world, N, L);
#endif
        lit += t.x * c_d * u_light_diffuse[i];
#ifndef NO_SPECULAR
        lit += u_specular_scale * t.y * u_mat_specular * u_light_specular[i];
#endif
    }
#endif
#ifdef HAS_REFLECTION
    // Sections 2-6: R = I - 2 (N.I) N with I = -V; the lookup starts at the capture centre.
    int room = 0; // 1: the lookup reads the room probe (pick_depth_hit)
#ifdef PER_VERTEX_REFLECTION
    vec3 d = v_reflect;
#elif defined(BOX_REFLECTION)
    // The common case in a variant of its own: llvmpipe runs every side of a uniform branch,
    // so the other corrections, the "depth" search and (opaque) the refraction below would
    // cost every pixel.
    vec3 d = correct_box(v_world, reflect(-V, N), u_proxy_min, u_proxy_max, u_probe_centre);
#else
    vec3 r = reflect(-V, N);
    vec3 d = u_correction == 2   ? correct_box(v_world, r, u_proxy_min, u_proxy_max, u_probe_centre)
             : u_correction == 3 ? correct_sphere(v_world, r, u_probe_centre, u_proxy_radius)
             : u_correction == 4 && u_room_active == 1 ? pick_depth_hit(v_world, r, room)
             : u_correction == 4 ? correct_depth(u_probe_distance, v_world, r, u_proxy_min, u_proxy_max,
                                                 u_probe_centre)
                                 : r;
#endif
#ifdef SPHERE_MAP
    vec3 refl = textureLod(u_sphere_map, sphere_map_st(u_view_rot * d), u_lod).rgb;
#elif defined(PLANAR_REFLECTION)
    // A flat mirror: every reflected ray comes from the eye's image, whose view through the
    // mirror shows what the ray from this point sees, at this point's own projection.
    vec4 pc = u_planar_view_proj * vec4(v_world, 1.0);
    vec3 refl = pc.w > 0.0 ? textureLod(u_planar, pc.xy / pc.w * 0.5 + 0.5, 0.0).rgb : vec3(0.0);
#else
    vec3 refl = room == 1 ? textureLod(u_room_probe, world_to_cmcs(d), u_room_lod).rgb
                          : textureLod(u_probe, world_to_cmcs(d), u_lod).rgb;
#endif
#ifndef BOX_REFLECTION
    if (u_surface_highlights == 1)
        refl += room == 1
                    ? reflected_highlight(u_room_surface, u_room_distance, u_room_centre, d, v_world)
                    : reflected_highlight(u_probe_surface, u_probe_distance, u_probe_centre, d,
                                          v_world);
#endif
#ifndef PLANAR_REFLECTION
    // What the probe left out, where the reflected ray meets it before the surface a "depth"
    // lookup found (what the ray meets first, by its search): the product's own parts
    // (self_trace.c), then a lamp (emitters.c), each hiding what lies behind it.
    vec3 r_seen = reflect(-V, N);
    float t_max = 1e30;
#if !defined(BOX_REFLECTION) && !defined(PER_VERTEX_REFLECTION)
    vec3 centre = room == 1 ? u_room_centre : u_probe_centre;
    if (u_correction == 4) // a small margin: the search places its hits to about 2 %
        t_max = 1.02 * dot(centre + d - v_world, r) + 0.01;
#endif
#ifdef SELF_TRACE
    // A blurred lookup traces one direction of its lobe a sample: the supersamples of a pixel
    // average them, and where a sample's ray misses the parts, the probe's blurred value.
    {
        int rays = u_lobe_exponent > 0.0 ? u_self_rays : 1;
        vec3 sum = vec3(0.0);
        float t_first = t_max;
        for (int k = 0; k < rays; k++) {
            vec3 own;
            float t_k = t_max;
            bool hit = self_reflection(v_world, lobe_direction(r_seen, u_lobe_exponent, k, rays), t_k, own);
            sum += hit ? own : refl;
            if (k == 0 && hit)
                t_first = t_k;
        }
        refl = sum / float(rays);
        t_max = t_first;
    }
#endif
#ifndef NO_LAMP_LOOKUPS
    // A fixed-light program of an object whose probe kept its lamps has no lookup: llvmpipe
    // would run its shading for every pixel behind the uniform branch.
    if (u_emitter_count > 0) {
        vec3 lamp;
        if (emitter_reflection(v_world, r_seen, t_max, lamp))
            refl = lamp;
    }
#endif
#endif
#if !defined(BOX_REFLECTION) || defined(BOX_GLASS)
    if (u_transparency > 0.0) {
        // Seed 003: refraction with an IOR, total internal reflection, optional dispersion
        // (one IOR per channel). A thin sheet displaces the ray but does not turn it.
        vec3 refr;
        for (int ch = 0; ch < 3; ch++) {
            float ior = u_ior + (float(ch) - 1.0) * 0.5 * u_dispersion;
            vec3 t = u_thin == 1 ? -V : refract(-V, N, 1.0 / ior);
#ifdef BOX_GLASS
            vec3 dt = dot(t, t) == 0.0 ? d // total internal reflection
                                       : correct_box(v_world, t, u_proxy_min, u_proxy_max, u_probe_centre);
#else
            vec3 dt = dot(t, t) == 0.0 ? d // total internal reflection
                      : u_correction == 2 ? correct_box(v_world, t, u_proxy_min, u_proxy_max, u_probe_centre)
                      : u_correction == 3 ? correct_sphere(v_world, t, u_probe_centre, u_proxy_radius)
                      : u_correction == 4 ? correct_depth(u_probe_distance, v_world, t, u_proxy_min,
                                                          u_proxy_max, u_probe_centre)
                                          : t;
#endif
            vec3 seen = textureLod(u_probe, world_to_cmcs(dt), u_lod).rgb, lamp;
            vec3 ray = dot(t, t) == 0.0 ? reflect(-V, N) : t;
            float t_seen = 1e30;
#ifdef SELF_TRACE
            vec3 own; // the parts the pane's probe leaves out, seen through it
            if (self_reflection(v_world, ray, t_seen, own))
                seen = own;
#endif
#ifndef NO_LAMP_LOOKUPS
            if (u_emitter_count > 0 && emitter_reflection(v_world, ray, t_seen, lamp))
                seen = lamp; // a lamp seen through the pane, as in the reflection above
#endif
            refr[ch] = seen[ch];
            if (u_dispersion <= 0.0) {
                refr = seen;
                break;
            }
        }
        if (u_pane_over == 1)
            refr = vec3(0.0);
        lit = mix(lit, refr, u_transparency);
    }
#endif
    lit = blend_reflection(u_blend, u_kr, u_mat_specular, lit, refl, dot(N, V));
#endif
#ifdef GLAZE
    // Glaze is glass: Schlick's Fresnel (Schlick 1994, "An Inexpensive BRDF Model for
    // Physically-based Rendering") with f0 = ((n - 1) / (n + 1))^2 = 0.04 for n = 1.5, blended
    // as section 6's fresnel mode: C = (1 - F) C_lit + F C_refl.
    {
        vec3 d = correct_box(v_world, reflect(-V, N), u_proxy_min, u_proxy_max, u_room_centre);
        vec3 room_seen = textureLod(u_room_probe, world_to_cmcs(d), u_room_lod).rgb;
        float f = fresnel_schlick(0.04, dot(N, V));
        lit = (1.0 - f) * lit + f * room_seen;
    }
#endif
    // A probe capture keeps the distance to what it saw for the "depth" lookup (reflect.glsl).
    frag_color = vec4(max(u_mat_emissive, lit),
                      u_store_distance > 0.0 ? length(v_world - u_eye) : 1.0); // eq. 7
#ifdef HAS_REFLECTION
    // The blend is linear in what the pane shows through it: that colour's weight.
    if (u_pane_over == 1)
        frag_color.a = dot(blend_reflection(u_blend, u_kr, u_mat_specular, vec3(u_transparency),
                                            vec3(0.0), dot(N, V)),
                           vec3(1.0 / 3.0));
#endif
    // Emissive surfaces keep no highlight: the max of eq. 7 mostly hides it.
    frag_surface = vec4(oct_encode(N),
                        any(greaterThan(u_mat_emissive, vec3(0.0))) ? 0.0
                                                                     : dot(u_mat_specular, vec3(1.0 / 3.0)),
                        min(u_mat_shininess, 65000.0));
}
