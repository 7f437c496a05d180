#ifndef RENDER_SCENE_INTERNAL_H
#define RENDER_SCENE_INTERNAL_H

#include "render/render.h"

/* The parts of a probe's product as a bounding-volume hierarchy its lookups trace
 * (self_trace.c): triangles in world space, in two buffer textures. */
#define RD_MAX_SELF_PARTS 16
#define RD_MAX_SELF_TEXTURES 4
typedef struct rd_self_bvh {
    unsigned node_buffer, node_texture, tri_buffer, tri_texture;
    int node_count, tri_count; /* tri_count 0: none (not wanted, or nothing to trace) */
    long long stamp;           /* the newest change counter of its objects at the build */
    int part_count;
    int part_object[RD_MAX_SELF_PARTS]; /* the scene's object index of each part */
    int part_base[RD_MAX_SELF_PARTS];   /* its first triangle in the probe's numbering */
} rd_self_bvh;

/* One reflection probe: a cube map captured at the centre of a reflective object (or of the
 * parts of one product), RENDERING.md section 3. GL names live in the scene's context. */
typedef struct rd_probe {
    int key;           /* the group (> 0), or -(index + 1) for a lone object */
    int owner;         /* the first object of the key: its material drives the probe */
    unsigned capture;  /* cube map as captured; box-filtered mips when a blur needs them */
    unsigned filtered; /* prefiltered chain (RD_BLUR_PREFILTERED, g < 1), else 0 */
    int size, levels;
    float centre[3], radius;
    float box_min[3], box_max[3]; /* its objects' joint world box (place_probe) */
    float detail_size;            /* metres: what its resolution follows (see place_probe) */
    /* The glossiness range of the objects that look it up (a product's parts share one probe
     * and may differ: a mirror and its frame): the blur covers all of them. */
    float gloss_min, gloss_max;
    long long captured_stamp; /* the scene's change counter at the last full capture */
    int captured_frame;       /* -1: never */
    int faces_valid;          /* bit f: face f holds a capture */
    int next_face;            /* time slicing: the face captured next */
    int faces_since_blur;     /* time slicing: faces captured since the last blur */
    int blur_waits; /* a split first capture (split_captures 2): its faces are in, its blur not */
    long long face_stamp[6]; /* the scene's change counter when face f was last captured */
    int filtered_level;      /* the lower prefiltered level that holds data; -1 none */
    int mips_valid;          /* box mips generated since the last capture */
    unsigned sphere_map;     /* material.sphere_map: the probe as a sphere map for this view */
    int sphere_size;
    /* "depth" correction: the captured surfaces' normals (octahedral), specular and shininess,
     * for highlights seen from the reflecting point (probe.c); 0 for the other modes. */
    unsigned surface;
    /* A flat mirror under rd_reflection_defaults.planar_mirrors (probe_planar.c): captured
     * from the eye's mirror image, of what lies in front of its plane only. */
    int planar;
    float plane[4];          /* world plane n.x + d = 0, n towards the eye */
    float quad[4][3];        /* the mirror's front face (world corners), a little enlarged */
    unsigned planar_texture; /* the capture: what the eye's image sees through the quad */
    int planar_width, planar_height;
    long long planar_frame;     /* the scene frame it was captured for; a stale one is not read */
    float planar_view_proj[16]; /* world -> the capture's clip space (column-major) */
    /* 1: captured without the scene's analytic emitters, which its lookups intersect exactly
     * instead (emitters.c); its readers are all sharp. */
    int leaves_emitters;
    /* Its lookups' own parts, traced (self_trace.c); empty when not. */
    rd_self_bvh self;
} rd_probe;

/* A lamp of a known shape, reflected exactly by sharp lookups (emitters.c). */
#define RD_MAX_EMITTERS 8
typedef struct rd_emitter {
    int object;
    rd_shape shape;
    int two_sided;      /* a plane lit from both sides */
    float to_local[16]; /* world -> the unit shape's space (column-major) */
    float sphere[4];    /* its world bounding sphere: centre, radius */
} rd_emitter;

struct rd_scene {
    rd_context *ctx;
    rd_object_desc *objects;
    long long *object_stamps; /* change counter value when each object last changed */
    int object_count, object_capacity;
    rd_light lights[RD_MAX_LIGHTS];
    int light_count;
    float ambient[3];
    unsigned lightmap; /* GL texture of rd_scene_set_lightmap, 0 = none */

    rd_reflection_defaults reflection;
    rd_probe *probes;
    int probe_count;
    int *object_probe;          /* per object: index into probes, -1 when it does not reflect */
    float (*object_spheres)[4]; /* per object, this frame: world bounding sphere centre, radius */
    int probes_dirty;           /* objects were added: the probe list must be rebuilt */
    long long change_counter;
    /* The ambient probe waits for a scene in motion to settle (ambient_sh.c): the change
     * counter it last saw and the frame it saw it change. */
    long long ambient_seen_change;
    int ambient_seen_frame;
    int frame;
    rd_probe ambient_probe; /* RD_AMBIENT_SH9: captured at the proxy's centre */
    float sh9[9][3];        /* its irradiance coefficients, world coordinates */
    /* The "depth" lookup's second probe (probe.c, room_probe_update): everything, seen from
     * the proxy's centre; key 0, which no object has, so nothing is left out. */
    rd_probe room_probe;
    /* This frame's analytic emitters (emitters.c) and, per object, whether it is one. */
    rd_emitter emitters[RD_MAX_EMITTERS];
    int emitter_count;
    unsigned char *object_emitter;

    rd_shadow_settings shadows;         /* rd_scene_set_shadows */
    struct rd_shadow_maps *shadow_maps; /* shadow.c; NULL until shadows are first drawn */
    int hold_probes;                    /* rd_scene_hold_probes (renderer_tiled.c) */
    int hold_probe_sizes; /* 1: captured probes keep their sizes (exposure_whole_view.c) */
    /* rd_scene_set_capture_time: a frame's captures within capture_ms (0: no limit), and the
     * learnt cost of a face in ms per million of its texels (capture_clock.c). */
    float capture_ms;
    float capture_ms_per_unit;
};

#endif
