// A procedural wood grain as a scale on the albedo, from the object-space position (no UVs):
// growth rings along the object's x axis with a noise-perturbed radius, pores and streaks, and
// a broad figure, each with mean 0 around 1 so the material keeps its own mean colour. The CPU
// twin is render/src/wood_grain_ref.c (rd_ref_wood_grain), with the same constants
// (render/shade_ref.h); docs/rendering.md "Wood grain".
#ifdef WOOD_GRAIN
float wood_lattice(int x, int y, int z)
{
    uint h = uint(x) * 0x8da6b343u ^ uint(y) * 0xd8163841u ^ uint(z) * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) * (2.0 / 16777216.0) - 1.0;
}

float wood_noise(vec3 q)
{
    vec3 fl = floor(q);
    ivec3 i = ivec3(fl);
    vec3 t = q - fl;
    t = t * t * (3.0 - 2.0 * t);
    float c00 = mix(wood_lattice(i.x, i.y, i.z), wood_lattice(i.x + 1, i.y, i.z), t.x);
    float c01 = mix(wood_lattice(i.x, i.y, i.z + 1), wood_lattice(i.x + 1, i.y, i.z + 1), t.x);
    float c10 = mix(wood_lattice(i.x, i.y + 1, i.z), wood_lattice(i.x + 1, i.y + 1, i.z), t.x);
    float c11 = mix(wood_lattice(i.x, i.y + 1, i.z + 1), wood_lattice(i.x + 1, i.y + 1, i.z + 1), t.x);
    return mix(mix(c00, c10, t.y), mix(c01, c11, t.y), t.z);
}

float wood_grain(vec3 p, float footprint)
{
    float dy = p.y - WOOD_AXIS_Y, dz = p.z - WOOD_AXIS_Z;
    float wobble = WOOD_WOBBLE * wood_noise(vec3(p.x * 2.0, p.y * 7.0, p.z * 7.0)) +
                   0.3 * WOOD_WOBBLE * wood_noise(vec3(p.x * 5.0, p.y * 23.0, p.z * 23.0));
    float r = sqrt(dy * dy + dz * dz) + wobble;
    float f = fract(r / WOOD_RING_SPACING);
    float late = f * f * f * f - 0.2;
    float bands = wood_noise(vec3(p.x * 1.5, r * 60.0, 0.5));
    float pores = wood_noise(vec3(p.x * 12.0, p.y * 900.0, p.z * 900.0));
    float figure = wood_noise(vec3(p.x * 3.0, p.y * 11.0, p.z * 11.0));
    float fade_rings = clamp(2.0 - 4.0 * footprint / WOOD_RING_SPACING, 0.0, 1.0);
    float fade_pores = clamp(2.0 - footprint * 1800.0, 0.0, 1.0);
    float fade_bands = clamp(2.0 - footprint * 240.0, 0.0, 1.0);
    return 1.0 - WOOD_RING_CONTRAST * fade_rings * late + WOOD_BAND_CONTRAST * fade_bands * bands +
           WOOD_PORE_CONTRAST * fade_pores * pores +
           WOOD_FIGURE_CONTRAST * figure;
}
#endif
