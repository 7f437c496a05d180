// Transforms a mesh into the world and the clip space; lighting happens per pixel in lit.frag.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat3 u_normal_matrix; // inverse transpose of u_model's 3x3, so non-uniform scale is right
uniform mat4 u_view_proj;

// The depth prepass (depth_only.frag) and the shaded pass must reach the same depths to the
// bit for GL_LEQUAL: invariance across programs is what GLSL promises for this (4.4.6).
invariant gl_Position;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
#ifdef WOOD_GRAIN
// The grain is fixed to the object (wood.glsl): its own axes, in metres (the model matrix's
// scale taken out of the rotation), whatever the model's units or a primitive's size.
out vec3 v_object;
uniform vec2 u_wood_grain_dir; // the grain's direction in the x-z plane (rd_ref_wood_grain_dir)
#endif

#ifdef BAKED_LIGHT
layout(location = 3) in vec4 a_baked;       // I (rgb), occlusion: per-vertex bake
layout(location = 4) in vec2 a_lightmap_uv; // or where the surface lies in the lightmap
out vec4 v_baked;
out vec2 v_lightmap_uv;
#endif

#ifdef PER_VERTEX_REFLECTION
// Seed 003's per-vertex reflection: the corrected direction at the vertices, interpolated.
uniform vec3 u_eye;
uniform vec3 u_probe_centre;
uniform int u_correction;
uniform vec3 u_proxy_min, u_proxy_max;
uniform float u_proxy_radius;
out vec3 v_reflect;
#endif

void main()
{
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_uv = a_uv;
#ifdef WOOD_GRAIN
    // Turned about y so that the grain's direction lies along x (rd_ref_wood_grain_point).
    vec3 object = a_position * vec3(length(u_model[0].xyz), length(u_model[1].xyz), length(u_model[2].xyz));
    v_object = vec3(u_wood_grain_dir.x * object.x + u_wood_grain_dir.y * object.z, object.y,
                    -u_wood_grain_dir.y * object.x + u_wood_grain_dir.x * object.z);
#endif
#ifdef BAKED_LIGHT
    v_baked = a_baked;
    v_lightmap_uv = a_lightmap_uv;
#endif
    gl_Position = u_view_proj * world;
#ifdef PER_VERTEX_REFLECTION
    vec3 n = normalize(v_normal);
    vec3 r = reflect(normalize(world.xyz - u_eye), n);
    // Per vertex, "depth" (4) has no stored distances to search: the box proxy.
    v_reflect = u_correction == 2 || u_correction == 4 ? correct_box(world.xyz, r, u_proxy_min, u_proxy_max, u_probe_centre)
                : u_correction == 3 ? correct_sphere(world.xyz, r, u_probe_centre, u_proxy_radius)
                                    : r;
#endif
}
