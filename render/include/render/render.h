/* Tessera renderer: the public API. No GL types cross this header (ARCHITECTURE.md).
 *
 * The shape follows Filament and sokol: a context owns every GPU object; a scene holds
 * meshes placed with materials plus lights; a view says where the camera is and what size
 * to render; rd_render draws a view of a scene into the context's float target, tone maps
 * it, and the result is read back with rd_read_rgba8 / rd_read_linear.
 * Units: metres, right-handed, Z up. Colours: linear RGB. */
#ifndef RENDER_RENDER_H
#define RENDER_RENDER_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rd_result {
    RD_OK = 0,
    RD_ERR_INVALID_ARGUMENT,
    RD_ERR_BACKEND_UNAVAILABLE,
    RD_ERR_GL,
    RD_ERR_SHADER,
    RD_ERR_OUT_OF_MEMORY,
    RD_ERR_TOO_LARGE,
    RD_ERR_STALE_HANDLE,
} rd_result;

/* The message of the last failure on this thread ("" if none). */
const char *rd_last_error(void);
const char *rd_result_name(rd_result r);

/* ---- context ---------------------------------------------------------------------------- */

typedef enum rd_backend {
    RD_BACKEND_DEFAULT = 0, /* TESSERA_GL if set, else EGL, else OSMesa */
    RD_BACKEND_EGL,         /* EGL on Mesa's surfaceless platform (or a device) */
    RD_BACKEND_OSMESA,      /* Mesa's off-screen library */
    RD_BACKEND_ADOPT,       /* the caller's current context (the GLFW window) */
} rd_backend;

/* "egl", "osmesa", "adopt" -> backend; returns RD_ERR_INVALID_ARGUMENT for anything else. */
rd_result rd_backend_parse(const char *name, rd_backend *out);
const char *rd_backend_name(rd_backend b);

typedef struct rd_context rd_context;

typedef struct rd_context_desc {
    rd_backend backend;
    /* RD_BACKEND_ADOPT only: the window library's loader (glfwGetProcAddress). */
    void *(*get_proc_address)(const char *name);
} rd_context_desc;

rd_result rd_context_create(const rd_context_desc *desc, rd_context **out);
void rd_context_destroy(rd_context *ctx);
rd_backend rd_context_backend(const rd_context *ctx);
/* GL_RENDERER and GL_VERSION as one line, e.g. "llvmpipe (LLVM 15.0.6, 256 bits); 4.5 (Core
 * Profile) Mesa 22.3.6". */
const char *rd_context_description(const rd_context *ctx);
/* The largest render target side this context can make (before supersampling). */
int rd_context_max_size(const rd_context *ctx);
/* Waits until all submitted GPU work has finished (for timing). */
void rd_finish(rd_context *ctx);

/* ---- GPU resources: handles with a generation, so a stale handle is detected ------------- */

typedef struct rd_mesh {
    uint32_t id;
} rd_mesh;
typedef struct rd_texture {
    uint32_t id;
} rd_texture;

typedef struct rd_mesh_desc {
    const float *positions; /* 3 per vertex */
    const float *normals;   /* 3 per vertex */
    const float *uvs;       /* 2 per vertex, may be NULL */
    const uint32_t *indices;
    int vertex_count;
    int index_count; /* a multiple of 3 */
    /* Baked indirect light (ref/ref_bake.h), used in place of the ambient I_a: per vertex
     * 4 floats (I rgb, occlusion), or per vertex 2 floats of coordinates in the scene's
     * lightmap (rd_scene_set_lightmap). NULL = not baked: the scene's ambient. */
    const float *baked_light;
    const float *lightmap_uvs;
} rd_mesh_desc;

rd_mesh rd_mesh_create(rd_context *ctx, const rd_mesh_desc *desc); /* id 0 on failure */
void rd_mesh_destroy(rd_context *ctx, rd_mesh mesh);

typedef struct rd_texture_desc {
    int width, height;
    const float *rgba; /* 4 floats per texel, top row first */
    int srgb_encoded;  /* 1: values are sRGB display values, decoded to linear on sampling */
} rd_texture_desc;

rd_texture rd_texture_create(rd_context *ctx, const rd_texture_desc *desc);
void rd_texture_destroy(rd_context *ctx, rd_texture tex);

/* ---- scene -------------------------------------------------------------------------------- */

/* How the reflection joins the lit colour (RENDERING.md section 6). */
typedef enum rd_reflection_blend {
    RD_REFLECT_MIX = 0, /* C = (1 - k_r) C_lit + k_r C_refl (seed 002) */
    RD_REFLECT_ADD,     /* C = C_lit + k_r C_s C_refl (seed 000 eq. 3) */
    RD_REFLECT_FRESNEL, /* F = Schlick(f0 = k_r, N.V); C = (1 - F) C_lit + F C_refl (seed 001) */
} rd_reflection_blend;

/* Where the reflected ray is assumed to end (RENDERING.md section 4). */
typedef enum rd_correction {
    RD_CORRECTION_DEFAULT = 0, /* the scene's choice (rd_scene_set_reflection_defaults) */
    RD_CORRECTION_NONE,        /* an infinitely far environment: look up R itself */
    RD_CORRECTION_BOX,         /* the scene's proxy box (the room's interior) */
    RD_CORRECTION_SPHERE,      /* a sphere of the probe's proxy radius around its centre */
    RD_CORRECTION_DEPTH,       /* the probe's stored distances (distance impostors), box beyond */
} rd_correction;

/* How a blurred reflection is looked up (RENDERING.md section 5). */
typedef enum rd_blur_method {
    RD_BLUR_DEFAULT = 0, /* the scene's choice */
    RD_BLUR_PREFILTERED, /* a mip chain convolved with the Phong lobe per level, on the GPU */
    RD_BLUR_BOX_MIPS,    /* plain box-filtered mips with a level-of-detail bias (seed 001) */
    RD_BLUR_REFERENCE,   /* brute-force convolution on the CPU (rd_ref_cube_convolve): slow,
                            the yardstick of the other two; sources above 32 are reduced first */
} rd_blur_method;

/* RENDERING.md section 1; the same struct feeds the CPU reference (shade_ref.h). */
typedef enum rd_pattern { RD_PATTERN_NONE = 0, RD_PATTERN_WOOD } rd_pattern;

typedef struct rd_material {
    float ambient[3];  /* C_a */
    float diffuse[3];  /* C_d, multiplied by the texture if any */
    float specular[3]; /* C_s */
    float emissive[3]; /* C_emissive, combined by per-channel max (seed 002 eq. 7) */
    float shininess;   /* n, 0 .. 1e6 */
    rd_texture diffuse_texture;
    float uv_scale[2]; /* texture repeats per unit of the mesh's UVs; 0 = 1 */
    /* Tile joints drawn from the layout (shaders/grout.glsl; rd_ref_joint_*): with
     * joint_width > 0, each unit cell of the scaled UVs is one tile's nominal cell, its
     * texture the tile with half a joint on every side, and a band joint_width wide (UV units,
     * per axis) around the cell's edges shows joint_color (ambient and diffuse) instead,
     * antialiased by its coverage of the pixel. The texture is read only inside the band, so
     * its edge texels never bleed into the tile. Needs diffuse_texture. */
    float joint_width[2];
    float joint_color[3];
    /* A procedural pattern on the albedo, from the object-space position (no UVs):
     * RD_PATTERN_WOOD is a wood grain along the object's x axis (or grain_angle_deg) whose
     * mean is 1, so the material keeps its colour (shaders/wood.glsl, rd_ref_wood_grain). It is
     * computed at the mesh position times the transform's scale per axis: in metres along the
     * object's own axes, whatever the mesh's units. */
    rd_pattern pattern;
    /* The grain's direction in the object's x-z plane (a catalog model's front), in degrees
     * from x towards z: 0 along x, 90 along z (upright). */
    float grain_angle_deg;

    /* Reflections (RENDERING.md sections 3-6). reflectivity k_r = 0: no probe, no reflection
     * code in the object's program, output bit for bit that of section 1. */
    float reflectivity; /* k_r in [0, 1] */
    float glossiness;   /* g in [0, 1]; 1 = mirror, no blur work at all */
    rd_reflection_blend blend;
    rd_correction correction;
    /* Glass (RENDERING.md section 9, seed 003): what lies behind is looked up in the probe
     * along the refracted ray (straight through for a double-sided sheet), mixed into the lit
     * colour by transparency, then the reflection is blended on top as above. */
    float transparency; /* 0 opaque .. 1 clear */
    float ior;          /* 0 = 1.5 */
    float dispersion;   /* IOR spread from red to blue; 0 = none */
    /* Seed 003: the reflection vector computed per vertex and interpolated (faster, worse on
     * coarse meshes) instead of per pixel. */
    int per_vertex_reflection;
    /* Seed 000 eqs. 2, 4, 5: 1 = look the reflection up in a sphere map made from the probe for
     * the current view (a view-dependent, legacy mode), 0 = in the cube map. */
    int sphere_map;
} rd_material;

typedef enum rd_light_type {
    RD_LIGHT_POINT = 0,
    RD_LIGHT_SPOT,
    RD_LIGHT_DIRECTIONAL,
    /* An emitting rectangle (a window pane, a mirror light, an LED strip, a ceiling panel):
     * Lambertian, radiance I_d (diffuse) and I_s (specular), lighting the side `direction`
     * points to; docs/rendering.md, "Area lights". */
    RD_LIGHT_RECT,
} rd_light_type;

typedef struct rd_light {
    rd_light_type type;
    float position[3];    /* point, spot */
    float direction[3];   /* spot, directional: the direction light travels (normalised here) */
    float diffuse[3];     /* I_d */
    float specular[3];    /* I_s */
    float attenuation[3]; /* constant, linear, quadratic: 1 / (c + l d + q d^2), d in metres */
    float spot_inner_cos; /* full intensity inside this cone (cosine of the half-angle) */
    float spot_outer_cos; /* zero outside; smoothstep in between */
    /* RD_LIGHT_RECT: the rectangle around `position`, as its two half edges (world vectors,
     * metres, square to each other and to `direction`). RD_LIGHT_DIRECTIONAL: when not zero, a
     * portal (a window opening) centred at `position`: the light reaches only the points whose
     * ray towards it passes through that rectangle (the wall around the opening shades the
     * rest). Zero for the other lights. */
    float half_width[3], half_height[3];
} rd_light;

#define RD_MAX_LIGHTS 16

typedef struct rd_scene rd_scene;

/* When a probe's cube map is captured again (RENDERING.md section 8). */
typedef enum rd_probe_update {
    RD_PROBE_DEFAULT = 0, /* the scene's choice */
    RD_PROBE_EVERY_FRAME, /* also "every N frames" with every_n > 1 */
    RD_PROBE_ONCE,        /* on the first frame only */
    RD_PROBE_ON_CHANGE,   /* when any other object moved or changed since the last capture */
    RD_PROBE_TIME_SLICED, /* one face per frame, round robin */
    RD_PROBE_STATIC,      /* a prepared map (rd_cubemap), never captured */
} rd_probe_update;

typedef struct rd_cubemap {
    uint32_t id;
} rd_cubemap;

typedef struct rd_probe_desc {
    rd_probe_update update;
    int every_n;           /* RD_PROBE_EVERY_FRAME: capture on every n-th frame; 0 or 1 = every */
    int resolution;        /* texels per face side; 0 = auto, from the object's size on screen */
    float proxy_radius_m;  /* RD_CORRECTION_SPHERE: 0 = the object's bounding radius x 4 */
    rd_cubemap static_map; /* RD_PROBE_STATIC */
} rd_probe_desc;

/* What an object's mesh is, when it is one of primitives.h's unit shapes (the transform maps
 * it into the world). A lamp of a known shape is reflected exactly in mirrors and glass
 * (docs/rendering.md, "Lamps in sharp reflections"); MESH: any other mesh. */
typedef enum rd_shape {
    RD_SHAPE_MESH = 0,
    RD_SHAPE_SPHERE,   /* radius 0.5 at the origin */
    RD_SHAPE_BOX,      /* [-0.5, 0.5]^3 */
    RD_SHAPE_PLANE,    /* the unit square at z = 0 */
    RD_SHAPE_CYLINDER, /* axis Z, radius 0.5, z in [-0.5, 0.5], capped */
} rd_shape;

typedef struct rd_object_desc {
    rd_mesh mesh;
    rd_shape shape; /* what `mesh` is (MESH when unknown) */
    rd_material material;
    float transform[16]; /* column-major model matrix; all zero = identity */
    int background;      /* 1 for large enclosing surfaces (room walls): drawn after the rest */
    int double_sided;    /* 1: draw back faces too (open sheets); 0: closed, back faces culled */
    /* Parts of one product (a model's meshes) share a group > 0: one probe at the centre of
     * their joint bounds, and none of them appears in it. 0 = the object stands alone. */
    int group;
    rd_probe_desc probe;
    /* Optional coarser mesh drawn in probe captures (RENDERING.md section 8: probes may draw
     * lower-detail geometry); id 0 = the mesh itself. Its bounds must match the mesh's. */
    rd_mesh probe_mesh;
} rd_object_desc;

rd_scene *rd_scene_create(rd_context *ctx);
void rd_scene_destroy(rd_scene *scene);
rd_result rd_scene_add_object(rd_scene *scene, const rd_object_desc *desc);
rd_result rd_scene_add_light(rd_scene *scene, const rd_light *light);
void rd_scene_set_ambient(rd_scene *scene, const float intensity[3]); /* I_a */
/* The baked lightmap atlas that meshes made with lightmap_uvs read their ambient intensity from:
 * 4 floats per texel (I rgb, occlusion), row 0 at v = 0; copied. NULL removes it. */
rd_result rd_scene_set_lightmap(rd_scene *scene, int width, int height, const float *rgba);
int rd_scene_object_count(const rd_scene *scene);
/* A copy of object `index`'s description as it stands (its transform after moves). */
rd_result rd_scene_object_desc(const rd_scene *scene, int index, rd_object_desc *out);

/* Moves object `index` (in the order added); probes that see it are captured again under
 * RD_PROBE_ON_CHANGE. */
rd_result rd_scene_set_transform(rd_scene *scene, int index, const float transform[16]);
/* Draws object `index` with another mesh of the same shape (the same geometry carrying newer
 * baked light); the caller keeps owning both meshes. Probes that see it are captured again. */
rd_result rd_scene_set_object_mesh(rd_scene *scene, int index, rd_mesh mesh);

/* The ambient term (RENDERING.md section 7): the constant I_a, or the irradiance of nine
 * spherical-harmonic coefficients projected from a probe at the centre of the box proxy (the
 * room), E(n) = n^T M n (Ramamoorthi and Hanrahan 2001), giving C_a E(N) / pi. */
typedef enum rd_ambient_model {
    RD_AMBIENT_CONSTANT = 0,
    RD_AMBIENT_SH9,
} rd_ambient_model;

/* Scene-wide reflection settings, used where a material or probe says DEFAULT. */
/* A setting that is on, off, or left to whoever decides next (a quality preset, then the
 * renderer's default): one name and one polarity from the command line to the renderer. */
typedef enum rd_switch {
    RD_SWITCH_UNSET = 0,
    RD_SWITCH_OFF,
    RD_SWITCH_ON,
} rd_switch;

typedef struct rd_reflection_defaults {
    rd_correction correction; /* DEFAULT = box */
    rd_blur_method blur;      /* DEFAULT = prefiltered */
    rd_probe_update update;   /* DEFAULT = every frame */
    int every_n;
    int resolution;           /* 0 = auto */
    int max_resolution;       /* cap for auto; 0 = 256 (stills raise it: print quality) */
    float hdr_clamp;          /* radiance clamp before blurring; 0 = 64 */
    rd_ambient_model ambient; /* RENDERING.md section 7 */
    int per_vertex;           /* 1: every reflective object per vertex (seed 003) */
    int probe_no_specular;    /* 1: captures leave highlights out (they are view-dependent) */
    float proxy_min[3], proxy_max[3]; /* the box proxy (metres); all zero = the scene's bounds */
    int max_faces_per_frame; /* refreshes of probes already complete: at most this many faces
                                a frame, probes taking turns; 0 = no limit */
    int split_captures;      /* 1: first captures keep to max_faces_per_frame too (one probe a
                                frame at least); probes held back are drawn unfinished and
                                counted in rd_frame_stats.probes_held, so the caller can wait
                                (the planner's still view). 0: a first capture is never held.
                                2: a first capture too is split, at most max_faces_per_frame
                                faces a frame in face order, blurred after its last face (the
                                map as one capture makes it, reached over frames) */
    /* Switches: RD_SWITCH_UNSET takes the renderer's default, named with each. */
    rd_switch planar_mirrors; /* ON: a flat mirror's probe is captured from the eye's mirror
                                 image, clipped at its plane, at the view's resolution (a planar
                                 reflection through the probe's cube map; docs/rendering.md).
                                 Default off */
    rd_switch mirror_bounce;  /* ON: a planar mirror's capture draws glass and reflective objects
                                 with their own probes (a second bounce: chrome in a mirror is
                                 chrome); OFF: plain, glass left out, as in every other capture
                                 and the direct-only tracer. Default on */
    rd_switch mirror_panes;   /* ON: a planar mirror's capture draws a thin pane (double-sided
                                 glass) last, blended over what it drew behind it: the view
                                 through the pane from the eye's image, exact (about 8 % more
                                 CPU for a 4K print of the designed demo); otherwise the pane
                                 shows what lies behind it from its own probe, centred on the
                                 pane. Default off */
    rd_switch room_probe;     /* ON: the "depth" lookup searches the room probe beside the
                                 object's own probe; OFF: its own probe only (docs/rendering.md,
                                 "The room probe"). Default on */
    rd_switch exact_lamps;    /* ON: lamps in the sharp reflections of mirrors and glass are
                                 intersected exactly, and those probes leave them out; OFF: they
                                 stay in the probes, reflected as the probe saw them (docs/
                                 rendering.md, "Lamps in sharp reflections"). Default on */
    rd_switch glaze;          /* ON: glazed surfaces without a probe of their own (glossy tiles:
                                 rd_material_glazed) reflect the room probe, weighted by
                                 Schlick's Fresnel for glass (docs/rendering.md, "Glazes").
                                 Default off */
    int self_reflections;     /* > 0: a fixture's lookups trace its own parts and the fixtures
                                 beside it (a tap's lever in its body, the basin by it), which its
                                 probe then leaves out; blurred lookups trace this many directions
                                 of their lobe a sample. 0: off (docs/rendering.md,
                                 "Self-reflections") */
} rd_reflection_defaults;
void rd_scene_set_reflection_defaults(rd_scene *scene, const rd_reflection_defaults *d);
rd_reflection_defaults rd_scene_reflection_defaults(const rd_scene *scene);
/* Changes only the capture budget (max_faces_per_frame and split_captures above) without the
 * new captures a change of defaults asks for: a live view sets it frame by frame. */
void rd_scene_set_capture_budget(rd_scene *scene, int max_faces_per_frame, int split_captures);
/* Also keeps a frame's probe captures within about `ms` milliseconds when split (split_captures
 * 2, or refreshes of a few faces): a face or a blur is made only when the time the frame's
 * captures took so far and its predicted cost fit, the first of a frame always, so captures
 * progress. The prediction scales the faces measured so far by texels (each face is waited
 * for, glFinish, to be measured). 0: no limit, nothing waited for. */
void rd_scene_set_capture_time(rd_scene *scene, float ms);

/* Shadows from every light (docs/rendering.md, "Shadows"): shadow maps in one depth atlas, a
 * cube (six faces) per point light, one face per spot and directional light. Objects with
 * `background` set (the room's walls, floor, ceiling), glass and emissive objects (a light's
 * own fixture) cast none: the room encloses its lights, and a window's directional light would
 * otherwise never get in. Probe captures draw
 * without shadows (a reflection of a shadow is a second-order detail). OFF compiles no shadow
 * code into any program. */
typedef enum rd_shadow_mode {
    RD_SHADOWS_OFF = 0,
    RD_SHADOWS_HARD, /* one bilinear depth comparison per light: a 1-texel edge */
    RD_SHADOWS_SOFT, /* PCF over a disk of `softness_m` at the receiver, `taps` per pixel */
} rd_shadow_mode;

typedef struct rd_shadow_settings {
    rd_shadow_mode mode;
    int map_size;     /* texels per face side; 0 = 1024 (clamped to fit the atlas) */
    int taps;         /* SOFT: comparisons per pixel on rotated Vogel disks, shared by its samples;
                         0 = 16, at most 256 */
    float softness_m; /* SOFT: the disk's radius at the receiver, metres; 0 = 0.03 */
} rd_shadow_settings;
void rd_scene_set_shadows(rd_scene *scene, const rd_shadow_settings *s);
/* The settings with their defaults filled in and limits applied (what a scene stores). */
rd_shadow_settings rd_shadow_settings_resolve(const rd_shadow_settings *s);
rd_shadow_settings rd_scene_shadows(const rd_scene *scene);
/* "off", "hard", "soft" <-> mode; parse returns RD_ERR_INVALID_ARGUMENT for anything else. */
rd_result rd_shadow_mode_parse(const char *name, rd_shadow_mode *out);
const char *rd_shadow_mode_name(rd_shadow_mode m);
/* The tap offsets both renderers use: tap i of n on the unit disk (Vogel 1979 spiral), the
 * spiral turned by `rotation` radians (a per-sample random angle, so that supersampling
 * averages differently placed taps). */
void rd_shadow_disk_tap(int i, int n, float rotation, float out[2]);
/* Soft taps per sample at s x s supersampling: the pixel's taps shared by its s^2 samples, at
 * least 2 (1 when hard). */
int rd_shadow_taps_per_sample(const rd_shadow_settings *s, int supersample);
/* Makes at most max_faces (at least 1) of the shadow-map faces the scene's lights and settings
 * still lack (a point light's cube counts six faces, a spot or directional light one), so that
 * a window can spread a change of settings over frames; *left gets the faces still to make (0:
 * the maps are ready). The next rd_render completes what is left; the maps come out the same
 * however the work was split. Waits for the GPU, so the work falls within the call. */
rd_result rd_scene_prepare_shadows(rd_context *ctx, rd_scene *scene, int max_faces, int *left);
/* Makes the SH9 ambient light (RENDERING.md section 7) if the scene's settings ask for it and
 * it is due, as the next rd_render would first: a window can give it a frame of its own. Waits
 * for the GPU, so the work falls within the call. */
rd_result rd_scene_prepare_ambient(rd_context *ctx, rd_scene *scene);

/* Probes the scene holds now (one per reflective object or group); for tests and stats. */
int rd_scene_probe_count(const rd_scene *scene);
/* Reads back one face (GL order) of one mip level of probe `index`'s cube map as the main
 * pass samples it (captured, box-mipped or prefiltered), RGBA float, CMCS; *size gets the
 * level's side. For tests and diagnostics. */
rd_result rd_scene_read_probe(rd_scene *scene, int index, int face, int level, float *rgba,
                              size_t count, int *size);
/* Frame statistics of the last rd_render (of rd_render_tiled: the whole image, each tile's work
 * summed): what each stage did, so a caller can tell which stages ran. */
typedef struct rd_frame_stats {
    int probes, faces_captured, prefiltered;
    int adaptive;             /* 1: the samples were taken adaptively (renderer_adaptive.c) */
    long long refined_pixels; /* adaptive supersampling: pixels given s x s samples */
    int planar_mirrors;       /* flat mirrors captured as planar reflections (probe_planar.c) */
    int room_probe;           /* 1: the room probe was captured ("depth" lookups, glazes) */
    int glazed;               /* objects in view drawn with the glaze's reflection */
    int emitters;             /* lamps reflected exactly in sharp reflections (emitters.c) */
    int emitter_probes;       /* probes captured without them (their readers are all sharp) */
    int self_traced_probes;   /* probes whose lookups trace their own parts (self_trace.c) */
    int self_triangles;       /* the triangles those traces hold */
    float exposure_ev;        /* the exposure the tone map used (auto_exposure: measured) */
    int probes_held;          /* probes in view whose capture waits for a later frame's budget */
} rd_frame_stats;
rd_frame_stats rd_last_frame_stats(const rd_context *ctx);

/* A prepared cube map for RD_PROBE_STATIC: six faces of RGBA floats in GL's order (+X, -X,
 * +Y, -Y, +Z, -Z), CMCS convention (RENDERING.md section 3), linear radiance. */
typedef struct rd_cubemap_desc {
    int size;
    const float *faces[6];
} rd_cubemap_desc;
rd_cubemap rd_cubemap_create(rd_context *ctx, const rd_cubemap_desc *desc);
void rd_cubemap_destroy(rd_context *ctx, rd_cubemap map);

/* ---- view and render ---------------------------------------------------------------------- */

typedef enum rd_tonemap {
    RD_TONEMAP_PHOTOGRAPHIC = 0, /* Reinhard et al. 2002, eq. 4, on luminance, with L_white */
    RD_TONEMAP_CLAMP,            /* exposure then clamp to [0, 1] */
    RD_TONEMAP_NEUTRAL,          /* Khronos PBR Neutral: true colours up to 0.76, then a
                                    soft shoulder (product renders) */
    RD_TONEMAP_AGX,              /* AgX (Sobotka), the minimal polynomial fit: filmic contrast,
                                    highlights desaturate to white */
} rd_tonemap;
/* "reinhard" (also "photographic"), "clamp", "neutral", "agx" <-> mode. */
rd_result rd_tonemap_parse(const char *name, rd_tonemap *out);
const char *rd_tonemap_name(rd_tonemap t);

/* The exposure a scene asks for (Reinhard et al. 2002, "Photographic tone reproduction for
 * digital images", eqs. 1-2): the log-average luminance L_avg = exp(mean(log(delta + L)))
 * mapped to the key a: EV = log2(a / L_avg) + compensation_ev. The key is that paper's
 * high-key value a = 0.36 (section 3: 0.18 is middle grey, 0.36 and 0.72 for high-key
 * scenes), as a photographer opens up a reflected-light reading by one stop for a white
 * scene: a tiled bathroom is mostly white glaze, and at 0.18 its white walls are shown grey.
 * sum_log is the sum of log(delta + L) over count samples; count 0 gives compensation_ev. */
#define RD_EXPOSURE_KEY 0.36f
#define RD_EXPOSURE_DELTA 1e-4f
float rd_auto_exposure_ev(double sum_log, long long count, float compensation_ev);

/* White balance: the 3 x 3 matrix (row-major, linear Rec. 709 RGB) that renders a light of
 * colour temperature kelvin as neutral white: a von Kries adaptation in the Bradford cone
 * space from the Planckian white of that temperature to D65. kelvin <= 0: identity; others
 * are clamped to the locus fit's 1667 to 25000 K. */
void rd_white_balance_matrix(float kelvin, float m[9]);

typedef struct rd_view {
    float eye[3], target[3], up[3]; /* up all zero = +Z */
    float fov_y_deg;                /* 0 = 60 */
    float near_m, far_m;            /* 0 = fitted to the scene */
    int width, height;              /* output pixels */
    int supersample;                /* 0 or 1 = none; 2..4 = s x s samples per pixel */
    float exposure_ev;              /* scale by 2^ev before the tone map (auto_exposure:
                                       the compensation added to the measured EV) */
    rd_tonemap tonemap;
    float white; /* L_white of the photographic operator; 0 = 4 */
    /* 1: the exposure is measured from this render's own radiance (rd_auto_exposure_ev over
     * a grid of at most 96 x 96 samples of the main pass); rd_last_frame_stats gives the EV
     * used. A tiled render measures a small render of the whole view first. */
    int auto_exposure;
    float white_balance_k; /* colour temperature rendered as white (rd_white_balance_matrix);
                              0 = none */
    int to_window;         /* RD_BACKEND_ADOPT: also draw the result into framebuffer 0 */
    /* A window of a larger image (tiled rendering): when full_width > 0, this render is the
     * width x height pixels at (crop_x, crop_y) (top-left origin) of a full_width x
     * full_height image of the same camera, with an off-centre projection. */
    int crop_x, crop_y, full_width, full_height;
    /* Adaptive supersampling (with supersample s > 1): shade once per pixel, then the s x s
     * samples of a full supersampled render only for the pixels that differ from a neighbour
     * by more than adaptive_threshold in a display channel (0..1; 0 = 4/255): edges, tile
     * joints, penumbrae, highlights. Elsewhere a pixel keeps its centre sample. 0 = every
     * pixel s x s. */
    int adaptive;
    float adaptive_threshold;
    /* Sub-pixel offset of the projection in output pixels (x right, y down), |jitter| < 1:
     * successive renders at different offsets, averaged, supersample the view over time
     * (temporal supersampling; the planner's still view). 0 = the pixel centres. */
    float jitter[2];
    /* 1: a frame of a moving live view (the planner while the camera or a fixture moves),
     * drawn cheaper where the difference does not show in motion: rectangle lights as point
     * lights of their power at their centres (what probe captures' lookups use) instead of
     * their clipped form factor, diffuse textures without anisotropic filtering, and probes
     * kept at the sizes they have (no new capture for a new size while the eye and the render
     * scale change; the still view sizes them again). A still view renders with 0, exactly. */
    int live;
    /* 1: the main pass draws every object, in view or not. llvmpipe compiles a program's
     * variant at its first draw with a given state, and an object out of view still draws
     * (nothing) through its variant: a small frame with this compiles what any later view of
     * the scene needs (the planner's shader warm-up). The picture is the same. */
    int all_objects;
    /* rd_measure_view_exposure only: 1 keeps the probes captured already at their sizes in its
     * small render, and after it (the planner's still view, measured again after each move:
     * the probes its strips use stay); 0 makes them anew at the next render's sizes, as a
     * single render of the view has them. */
    int keep_probes;
} rd_view;

rd_result rd_render(rd_context *ctx, rd_scene *scene, const rd_view *view);

/* The timing "floor" of the benchmark: one full-screen pass of the same lighting program,
 * with the scene's lights, into the same float target at the view's size. */
rd_result rd_render_floor(rd_context *ctx, rd_scene *scene, const rd_view *view);

/* The EV to draw a view with when it is drawn in parts (view->crop_*, full_width and
 * full_height describe one part, or none): with auto_exposure, measured once on a small render
 * of the whole view, so every part shares it (render each part with auto_exposure = 0 and this
 * exposure_ev); without, view->exposure_ev. The next render captures its probes again. */
rd_result rd_measure_view_exposure(rd_context *ctx, rd_scene *scene, const rd_view *view,
                                   float *ev);

/* Renders a view of any size (up to RD_IMAGE_MAX_SIDE per side) in tiles of at most
 * tile_max x tile_max output pixels (0 = as large as the context allows), each with an
 * off-centre projection, and stitches them into rgba8 (width*height*4 bytes, top row first) and,
 * if linear is not NULL, linear (width*height*4 floats). Probes and shadow maps are made on the
 * first tile and reused. progress(user, done, total) is called after each tile (may be NULL). */
rd_result rd_render_tiled(rd_context *ctx, rd_scene *scene, const rd_view *view, int tile_max,
                          uint8_t *rgba8, float *linear,
                          void (*progress)(void *user, int done, int total), void *user);
/* hold = 1: rd_render_tiled keeps the probes it has (captures only those never captured), also
 * from one call to the next -- a panorama's faces and a video's frames of a still scene see
 * the same probes (they are captured at the objects, not at the camera). 0 = the policies. */
void rd_scene_hold_probes(rd_scene *scene, int hold);

/* Read back the last rd_render: tone-mapped sRGB bytes (RGBA, top row first, width*height*4),
 * or linear radiance after exposure (RGBA float, width*height*4), both at output size. */
rd_result rd_read_rgba8(rd_context *ctx, uint8_t *out, size_t out_size);
rd_result rd_read_linear(rd_context *ctx, float *out, size_t out_count);

/* RD_BACKEND_ADOPT: draw the last render's tone-mapped image scaled to the caller's window
 * (framebuffer 0) with linear filtering, and read the window back (RGBA, top row first) for
 * screenshots that include the caller's own drawing on top. */
rd_result rd_present(rd_context *ctx, int window_width, int window_height);
/* The same into the rectangle (x, y, width, height) of the window, in window pixels from its
 * top-left corner (a pane beside the caller's panels); the rest of the window is cleared. */
rd_result rd_present_rect(rd_context *ctx, int window_width, int window_height, int x, int y,
                          int width, int height);
/* RD_BACKEND_ADOPT: the same for an image the caller composed (width x height RGBA8, top row
 * first; the planner's accumulated still view), unscaled at (x, y) of the window, in window
 * pixels from its top-left corner. */
rd_result rd_present_rgba8(rd_context *ctx, int width, int height, const uint8_t *rgba,
                           int window_width, int window_height, int x, int y);
rd_result rd_read_window_rgba8(rd_context *ctx, int width, int height, uint8_t *out,
                               size_t out_size);

#ifdef __cplusplus
}
#endif
#endif
