// Seed 000's sphere map, made from a probe's cube map for the current view (RENDERING.md
// section 9): every texel shows the cube map along the view-space direction of eqs. 2 and 5.
uniform samplerCube u_source;
uniform mat3 u_view_rot; // world to view; its transpose takes view directions to the world
uniform float u_size;

out vec4 frag_color;

void main()
{
    vec3 r_view = sphere_map_direction(gl_FragCoord.xy / u_size);
    vec3 r_world = transpose(u_view_rot) * r_view;
    frag_color = vec4(textureLod(u_source, world_to_cmcs(r_world), 0.0).rgb, 1.0);
}
