// Tile joints drawn from the tile layout (rd_material.joint_width; docs/rendering.md "Grout").
// Each unit cell of the texture coordinate is one tile's nominal cell (the tile and half a
// joint on every side); a band joint_width wide around the cell's edges is grout. Its share of
// the pixel is integrated analytically over the pixel's footprint (a box filter of fwidth per
// axis), so a 3 mm joint seen from across the room is a faint, even darkening instead of a
// line that breaks up, and it is never lighter than the grout or the tile beside it. The
// texture is read only inside the band and four of the footprint's mip texels clear of it, so
// the image's own border texels (the grout the image was drawn with) never bleed into the tile
// through bilinear or mip filtering. The CPU twin is render/src/grout_ref.c.
uniform vec2 u_joint_width; // per axis, UV units; 0 = no joints (a plain texture)
uniform vec3 u_joint_color; // the grout's ambient and diffuse colour

// The fraction of [x - f/2, x + f/2] inside the bands around the cell edges 0 and 1.
float joint_coverage_1d(float x, float w, float f)
{
    if (!(w > 0.0))
        return 0.0;
    if (f >= 1.0) // the footprint spans whole cells: their mean
        return min(w, 1.0);
    float c = fract(x);
    if (!(f > 0.0))
        return (c < 0.5 * w || c > 1.0 - 0.5 * w) ? 1.0 : 0.0;
    float a = c - 0.5 * f, b = c + 0.5 * f;
    float o = max(0.0, min(b, 0.5 * w) - max(a, -0.5 * w)) +
              max(0.0, min(b, 1.0 + 0.5 * w) - max(a, 1.0 - 0.5 * w));
    return clamp(o / f, 0.0, 1.0);
}

// The texture's colour at uv and, in *joint, the grout's share of the pixel.
vec3 tile_texture(sampler2D tex, vec2 uv, out float joint)
{
    joint = 0.0;
    if (!(u_joint_width.x > 0.0 || u_joint_width.y > 0.0))
        return texture(tex, uv).rgb;
    vec2 f = fwidth(uv);
    float ju = joint_coverage_1d(uv.x, u_joint_width.x, f.x);
    float jv = joint_coverage_1d(uv.y, u_joint_width.y, f.y);
    joint = ju + jv - ju * jv;
    vec2 size = vec2(textureSize(tex, 0));
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float rho = max(length(dx * size), length(dy * size)); // level-0 texels a mip texel spans
    vec2 lo = min(0.5 * u_joint_width + 4.0 * max(rho, 0.25) / size, vec2(0.5));
    vec2 st = floor(uv) + clamp(fract(uv), lo, 1.0 - lo);
    // An isotropic lookup at the footprint's larger axis: anisotropic probes may run past
    // the clamp along the larger axis and fetch the image's border.
    return textureLod(tex, st, log2(max(rho, 1e-6))).rgb;
}
