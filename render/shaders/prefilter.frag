// Convolution of a cube map with the normalised Phong lobe ((n + 1) / 2 pi) (R.l)^n
// (RENDERING.md section 5; seed 001 eq. 6), by importance sampling the lobe itself, so the
// estimate is a plain mean and brightness is conserved. Each sample reads the source's box
// mips at the level matching its share of the lobe's solid angle ("filtered importance
// sampling", one level finer: see below), which keeps 24 samples free of fireflies; samples
// are clamped first so a lamp does not turn into speckles. Directions are cube-map coordinates (CMCS) throughout, and
// sampling is by direction with seamless filtering, so face edges leave no seams.
uniform samplerCube u_source;
uniform int u_face;
uniform float u_size;        // texels per side of the level being written
uniform float u_exponent;    // n; 0 = copy (the mirror level)
uniform float u_clamp;       // HDR clamp
uniform float u_source_size; // texels per side of the source's level 0
uniform int u_samples;       // 1..MAX_SAMPLES: fewer where the lobe is only texels wide

out vec4 frag_color;

const int MAX_SAMPLES = 24;
const float PI = 3.14159265358979;

// The direction through (s, t) of a face: the inverse of GL's face selection table.
vec3 face_direction(int face, vec2 st)
{
    vec2 c = st * 2.0 - 1.0; // (sc, tc) / |ma|
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

vec2 hammersley(int i)
{
    uint b = uint(i);
    b = (b << 16u) | (b >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return vec2((float(i) + 0.5) / float(u_samples), float(b) * 2.3283064365386963e-10);
}

void main()
{
    vec3 d = normalize(face_direction(u_face, gl_FragCoord.xy / u_size));
    if (u_exponent <= 0.0) {
        frag_color = vec4(min(textureLod(u_source, d, 0.0).rgb, vec3(u_clamp)), 1.0);
        return;
    }
    vec3 up = abs(d.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t1 = normalize(cross(up, d));
    vec3 t2 = cross(d, t1);
    float texel_solid_angle = 4.0 * PI / (6.0 * u_source_size * u_source_size);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_samples; i++) {
        vec2 xi = hammersley(i);
        float cos_t = pow(xi.x, 1.0 / (u_exponent + 1.0));
        float sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
        float phi = 2.0 * PI * xi.y;
        vec3 l = t1 * (cos(phi) * sin_t) + t2 * (sin(phi) * sin_t) + d * cos_t;
        float pdf = (u_exponent + 1.0) / (2.0 * PI) * pow(cos_t, u_exponent);
        float sample_solid_angle = 1.0 / (float(u_samples) * max(pdf, 1e-8));
        // The level whose texels match the sample's share of the lobe, one finer: box mips
        // spread a bright source in squares wider than their texel, and GPU Gems 3's "+1"
        // (coarser, against noise) makes the lobe of a glossy tap before a window of radiance
        // 20 several times too wide (assets/projects/stress-taps.json); one finer fixes it
        // and costs the demo nothing (docs/accuracy.md, "Blur").
        float lod = max(0.5 * log2(sample_solid_angle / texel_solid_angle) - 1.0, 0.0);
        sum += min(textureLod(u_source, l, lod).rgb, vec3(u_clamp));
    }
    frag_color = vec4(sum / float(u_samples), 1.0);
}
