/* The lit draw of a scene's objects, shared by the main view and the probe faces. */
#include "draw.h"
#include "glaze.h"
#include "emitters.h"
#include "self_trace.h"
#include "gl_funcs.h"
#include "probe.h"
#include "shadow.h"

#include "render/reflect_ref.h"
#include "render/shade_ref.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdlib.h>

/* Texture units of the lit program: 0-2 its own, 3-4 the probe's distances and surface, 5 the
 * shadow atlas (shadow.c), 6-8 the room probe, 9-14 the self-reflection trace (self_trace.c);
 * the planar capture takes the last unit GL 3.3 guarantees. A unit shared with the atlas would
 * leave the capture bound where every later object reads its shadows. */
#define PLANAR_UNIT 15

/* lit.frag's light type of a rectangle light in the main loop as a point light of its power
 * (rd_pass.rect_lights_as_points): its own loop, the clipped form factor, is left out. It joins
 * the point and spot lights' loop with the attenuation of a point of its power (rect_as_point). */
#define LIGHT_RECT_AS_POINT 4

/* A rectangle light's attenuation as a point light of its power: the solid angle of area A at
 * distance d is A cos / d^2, so its irradiance factor over pi is A / (pi d^2) before lit.frag's
 * local_light_towards applies the cosine. A rectangle of no area lights nothing. */
static void rect_as_point_attenuation(const rd_light *l, float att[3])
{
    float uu = l->half_width[0] * l->half_width[0] + l->half_width[1] * l->half_width[1] +
               l->half_width[2] * l->half_width[2];
    float vv = l->half_height[0] * l->half_height[0] + l->half_height[1] * l->half_height[1] +
               l->half_height[2] * l->half_height[2];
    float area = 4.0f * sqrtf(uu * vv);
    att[0] = area > 0.0f ? 0.0f : 1e30f;
    att[1] = 0.0f;
    att[2] = area > 0.0f ? (float)GLM_PI / area : 0.0f;
}

/* Which of lit.frag's light lists takes light l: the point and spot lights' (0), the
 * rectangle lights' (1), or the rest (2, directional lights). */
static int light_list(const rd_light *l, int rect_as_points)
{
    if (l->type == RD_LIGHT_POINT || l->type == RD_LIGHT_SPOT ||
        (l->type == RD_LIGHT_RECT && rect_as_points))
        return 0;
    return l->type == RD_LIGHT_RECT ? 1 : 2;
}

/* The lights of `mask` (bit i: scene light i), packed in scene order: the light loop of
 * lit.frag runs over exactly these, and the rectangle loop over the rectangle lights, or
 * none of them when rect_as_points gives them to the light loop. */
static void set_light_uniforms(const rd_program *p, const rd_scene *s, unsigned mask,
                               int rect_as_points)
{
    int type[RD_MAX_LIGHTS];
    float pos[RD_MAX_LIGHTS][3], dir[RD_MAX_LIGHTS][3], dif[RD_MAX_LIGHTS][3],
        spec[RD_MAX_LIGHTS][3], att[RD_MAX_LIGHTS][3], spot[RD_MAX_LIGHTS][2],
        half_w[RD_MAX_LIGHTS][3], half_h[RD_MAX_LIGHTS][3];
    int n = 0, rects = 0, rect_index[RD_MAX_LIGHTS], locals = 0, local_index[RD_MAX_LIGHTS],
        others = 0, other_index[RD_MAX_LIGHTS];
    for (int i = 0; i < s->light_count; i++) {
        if (!(mask & (1u << i)))
            continue;
        const rd_light *l = &s->lights[i];
        type[n] = (int)l->type;
        memcpy(pos[n], l->position, sizeof pos[n]);
        memcpy(dir[n], l->direction, sizeof dir[n]);
        memcpy(dif[n], l->diffuse, sizeof dif[n]);
        memcpy(spec[n], l->specular, sizeof spec[n]);
        memcpy(att[n], l->attenuation, sizeof att[n]);
        spot[n][0] = l->spot_inner_cos;
        spot[n][1] = l->spot_outer_cos;
        memcpy(half_w[n], l->half_width, sizeof half_w[n]);
        memcpy(half_h[n], l->half_height, sizeof half_h[n]);
        if (l->type == RD_LIGHT_RECT && rect_as_points) {
            type[n] = LIGHT_RECT_AS_POINT;
            rect_as_point_attenuation(l, att[n]);
        }
        int list = light_list(l, rect_as_points);
        if (list == 0)
            local_index[locals++] = n;
        else if (list == 1)
            rect_index[rects++] = n;
        else
            other_index[others++] = n;
        n++;
    }
    glUniform1i(p->u_light_count, n);
    glUniform1i(p->u_local_count, locals);
    glUniform1i(p->u_other_count, others);
    if (locals > 0)
        glUniform1iv(p->u_local_index, locals, local_index);
    if (others > 0)
        glUniform1iv(p->u_other_index, others, other_index);
    if (p->u_rect_count >= 0) { /* the AREA_LIGHTS variant only */
        glUniform1i(p->u_rect_count, rects);
        if (rects > 0)
            glUniform1iv(p->u_rect_index, rects, rect_index);
    }
    if (n > 0) {
        glUniform1iv(p->u_light_type, n, type);
        glUniform3fv(p->u_light_position, n, &pos[0][0]);
        glUniform3fv(p->u_light_direction, n, &dir[0][0]);
        glUniform3fv(p->u_light_diffuse, n, &dif[0][0]);
        glUniform3fv(p->u_light_specular, n, &spec[0][0]);
        glUniform3fv(p->u_light_attenuation, n, &att[0][0]);
        glUniform2fv(p->u_light_spot, n, &spot[0][0]);
        if (p->u_light_half_width >= 0) { /* the AREA_LIGHTS variant only */
            glUniform3fv(p->u_light_half_width, n, &half_w[0][0]);
            glUniform3fv(p->u_light_half_height, n, &half_h[0][0]);
        }
    }
}

static unsigned all_lights(const rd_scene *s)
{
    return s->light_count >= 32 ? ~0u : (1u << s->light_count) - 1u;
}

/* The lengths of lit.frag's point-and-spot and directional lists for all of a scene's lights,
 * rectangles as points: what a fixed-light program (rd_lit_program_fixed) is made for. */
static void fixed_list_lengths(const rd_scene *s, int *locals, int *others)
{
    *locals = *others = 0;
    for (int i = 0; i < s->light_count; i++) {
        int list = light_list(&s->lights[i], 1);
        *locals += list == 0;
        *others += list == 2;
    }
}

/* The lights that can reach a bounding sphere (centre, radius): a spot light whose cone
 * misses the sphere adds exactly zero everywhere on it (lit.frag's spot_factor is 0 at and
 * beyond the outer cosine), so leaving it out changes no pixel. Point and directional lights
 * always stay: their attenuation never reaches zero (RENDERING.md section 1). */
static unsigned lights_reaching(const rd_scene *s, const float sphere[4])
{
    unsigned mask = all_lights(s);
    for (int i = 0; i < s->light_count; i++) {
        const rd_light *l = &s->lights[i];
        if (l->type != RD_LIGHT_SPOT || !(l->spot_outer_cos > -1.0f))
            continue;
        float d[3], dist2 = 0.0f;
        for (int k = 0; k < 3; k++) {
            d[k] = sphere[k] - l->position[k];
            dist2 += d[k] * d[k];
        }
        float dist = sqrtf(dist2), r = sphere[3] * 1.01f + 1e-4f; /* a margin for rounding */
        if (!(dist > r))
            continue; /* the light is inside the sphere */
        float axis =
            (d[0] * l->direction[0] + d[1] * l->direction[1] + d[2] * l->direction[2]) / dist;
        float to_centre = acosf(fminf(fmaxf(axis, -1.0f), 1.0f));
        float outer = acosf(fminf(fmaxf(l->spot_outer_cos, -1.0f), 1.0f));
        if (to_centre - asinf(r / dist) > outer + 1e-3f)
            mask &= ~(1u << i);
    }
    return mask;
}

void rd_set_frame_uniforms(const rd_program *p, const rd_scene *s, const float vp[16],
                           const float eye[3])
{
    glUseProgram(p->id);
    glUniformMatrix4fv(p->u_view_proj, 1, GL_FALSE, vp);
    glUniform3fv(p->u_eye, 1, eye);
    glUniform3fv(p->u_ambient_light, 1, s->ambient);
    set_light_uniforms(p, s, all_lights(s), 0);
    glUniform1i(p->u_diffuse_texture, 0);
    glUniform1f(p->u_specular_scale, 1.0f);
    glUniform1f(p->u_store_distance, 0.0f);
    if (s->reflection.ambient == RD_AMBIENT_SH9)
        glUniform3fv(p->u_sh, 9, &s->sh9[0][0]);
}

void rd_set_object_uniforms(const rd_program *p, const float model[16], const rd_material *m)
{
    mat3 normal;
    glm_mat4_pick3((vec4 *)model, normal);
    glm_mat3_inv(normal, normal);
    glm_mat3_transpose(normal);
    glUniformMatrix4fv(p->u_model, 1, GL_FALSE, model);
    glUniformMatrix3fv(p->u_normal_matrix, 1, GL_FALSE, &normal[0][0]);
    glUniform3fv(p->u_mat_ambient, 1, m->ambient);
    glUniform3fv(p->u_mat_diffuse, 1, m->diffuse);
    glUniform3fv(p->u_mat_specular, 1, m->specular);
    glUniform3fv(p->u_mat_emissive, 1, m->emissive);
    glUniform1f(p->u_mat_shininess, m->shininess);
    if (p->u_uv_scale >= 0)
        glUniform2f(p->u_uv_scale, m->uv_scale[0] > 0.0f ? m->uv_scale[0] : 1.0f,
                    m->uv_scale[1] > 0.0f ? m->uv_scale[1] : 1.0f);
    if (p->u_joint_width >= 0) {
        glUniform2f(p->u_joint_width, fmaxf(m->joint_width[0], 0.0f),
                    fmaxf(m->joint_width[1], 0.0f));
        glUniform3fv(p->u_joint_color, 1, m->joint_color);
    }
    if (p->u_wood_grain_dir >= 0) {
        float dir[2];
        rd_ref_wood_grain_dir(m->grain_angle_deg, dir);
        glUniform2fv(p->u_wood_grain_dir, 1, dir);
    }
}

static float determinant3(const float m[16])
{
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[4] * (m[1] * m[10] - m[2] * m[9]) +
           m[8] * (m[1] * m[6] - m[2] * m[5]);
}

typedef struct draw_item {
    int index;
    int background;
    float near;     /* distance from the eye to the object's world bounding box (0 inside) */
    float distance; /* to the box's centre: breaks ties (the eye inside several boxes) */
} draw_item;

static int compare_items(const void *a, const void *b)
{
    const draw_item *x = a, *y = b;
    if (x->background != y->background)
        return x->background - y->background;
    if (x->near != y->near)
        return (x->near > y->near) - (x->near < y->near);
    return (x->distance > y->distance) - (x->distance < y->distance);
}

/* Front to back, enclosing surfaces last: llvmpipe's early depth test then shades each
 * pixel about once, which is what keeps a frame near one full-screen pass. The order is by
 * the nearest point of each object's world box, not its centre: a wall's tiles
 * and the grout surface behind them share a centre to the millimetre, and the tiles, a few
 * millimetres nearer the room, then mostly come first. The main view does not depend on it
 * (its depth prepass shades each pixel once); probe faces, drawn without one, do. */
static draw_item *sorted_draw_list(rd_context *ctx, const rd_scene *s, const float eye[3])
{
    draw_item *items = malloc((size_t)(s->object_count ? s->object_count : 1) * sizeof *items);
    if (!items)
        return NULL;
    for (int i = 0; i < s->object_count; i++) {
        const rd_object_desc *o = &s->objects[i];
        float lo[3], hi[3], near2 = 0.0f, centre2 = 0.0f;
        rd_object_world_bounds(ctx, o, lo, hi);
        for (int k = 0; k < 3; k++) {
            if (!(lo[k] <= hi[k])) { /* no mesh: its origin */
                lo[k] = hi[k] = o->transform[12 + k];
            }
            float gap = eye[k] < lo[k] ? lo[k] - eye[k] : eye[k] > hi[k] ? eye[k] - hi[k] : 0.0f;
            float c = 0.5f * (lo[k] + hi[k]) - eye[k];
            near2 += gap * gap;
            centre2 += c * c;
        }
        items[i] = (draw_item){i, o->background, sqrtf(near2), sqrtf(centre2)};
    }
    qsort(items, (size_t)s->object_count, sizeof *items, compare_items);
    return items;
}

/* The reflection inputs of one object (RENDERING.md sections 3-6). */
static void set_reflection_uniforms(const rd_program *p, const rd_scene *s, const rd_probe *probe,
                                    const rd_object_desc *o)
{
    const rd_material *m = &o->material;
    glUniform1f(p->u_transparency, fminf(fmaxf(m->transparency, 0.0f), 1.0f));
    glUniform1f(p->u_ior, m->ior > 0.0f ? m->ior : 1.5f);
    glUniform1f(p->u_dispersion, fmaxf(m->dispersion, 0.0f));
    glUniform1i(p->u_thin, o->double_sided ? 1 : 0);
    float bmin[3], bmax[3];
    rd_effective_proxy(s, bmin, bmax);
    rd_correction c = rd_effective_correction(s, m);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, probe->planar ? 0 : rd_probe_texture(s, probe));
    if (probe->planar) {
        glActiveTexture(GL_TEXTURE0 + PLANAR_UNIT);
        glBindTexture(GL_TEXTURE_2D, probe->planar_texture);
        glUniform1i(p->u_planar, PLANAR_UNIT);
        glUniformMatrix4fv(p->u_planar_view_proj, 1, GL_FALSE, probe->planar_view_proj);
        glActiveTexture(GL_TEXTURE1);
    }
    glUniform1i(p->u_probe, 1);
    glUniform3fv(p->u_probe_centre, 1, probe->centre);
    glUniform1i(p->u_correction, (int)c);
    /* "depth" searches the capture's stored distances (alpha); a prepared map has none. */
    if (c == RD_CORRECTION_DEPTH &&
        (!probe->capture || s->objects[probe->owner].probe.update == RD_PROBE_STATIC))
        glUniform1i(p->u_correction, (int)RD_CORRECTION_BOX);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_CUBE_MAP, probe->capture);
    glUniform1i(p->u_probe_distance, 3);
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_CUBE_MAP, probe->surface);
    glUniform1i(p->u_probe_surface, 4);
    glUniform1i(p->u_surface_highlights, probe->surface ? 1 : 0);
    glUniform1f(p->u_lobe_exponent,
                m->glossiness < 1.0f ? rd_ref_gloss_exponent(m->glossiness) : 0.0f);
    glUniform1i(p->u_depth_steps, rd_depth_search_steps(m->glossiness));
    /* The room probe beside the own for "depth" lookups (probe.c, lit.frag's pick_depth_hit). */
    const rd_probe *room = &s->room_probe;
    int room_ready = c == RD_CORRECTION_DEPTH && s->reflection.room_probe != RD_SWITCH_OFF &&
                     room->faces_valid == 0x3f &&
                     (room->gloss_min >= 1.0f || room->filtered_level >= 0 ||
                      rd_effective_blur(s) != RD_BLUR_PREFILTERED);
    glUniform1i(p->u_room_active, room_ready ? 1 : 0);
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_CUBE_MAP, room_ready && room->gloss_min < 1.0f &&
                                               rd_effective_blur(s) == RD_BLUR_PREFILTERED
                                           ? room->filtered
                                           : room->capture);
    glUniform1i(p->u_room_probe, 6);
    glActiveTexture(GL_TEXTURE7);
    glBindTexture(GL_TEXTURE_CUBE_MAP, room->capture);
    glUniform1i(p->u_room_distance, 7);
    glActiveTexture(GL_TEXTURE8);
    glBindTexture(GL_TEXTURE_CUBE_MAP, room->surface);
    glUniform1i(p->u_room_surface, 8);
    glUniform3fv(p->u_room_centre, 1, room->centre);
    float glo[3], ghi[3];
    for (int k = 0; k < 3; k++) {
        glo[k] = probe->box_min[k] - 1e-3f; /* hits are placed to about a millimetre */
        ghi[k] = probe->box_max[k] + 1e-3f;
    }
    glUniform3fv(p->u_group_min, 1, glo);
    glUniform3fv(p->u_group_max, 1, ghi);
    glUniform1f(p->u_room_lod, room_ready ? rd_probe_lod(room, m->glossiness) : 0.0f);
    glActiveTexture(GL_TEXTURE1);
    glUniform3fv(p->u_proxy_min, 1, bmin);
    glUniform3fv(p->u_proxy_max, 1, bmax);
    const rd_probe_desc *pd = &s->objects[probe->owner].probe;
    glUniform1f(p->u_proxy_radius,
                pd->proxy_radius_m > 0.0f ? pd->proxy_radius_m : 4.0f * probe->radius);
    glUniform1f(p->u_kr, fminf(fmaxf(m->reflectivity, 0.0f), 1.0f));
    glUniform1f(p->u_lod, rd_probe_lod(probe, m->glossiness));
    glUniform1i(p->u_blend, (int)m->blend);
    rd_set_emitter_uniforms(p, s, probe->leaves_emitters);
    glActiveTexture(GL_TEXTURE0);
}

/* The lean program variant of an object whose reflection takes the box correction and shows
 * no re-lit highlights (set_reflection_uniforms): RD_LIT_BOX_OPAQUE, or RD_LIT_BOX_GLASS with
 * its refraction through the same box; 0 for the full path. */
static int box_variant(const rd_scene *s, const rd_probe *probe, const rd_object_desc *o)
{
    rd_correction c = rd_effective_correction(s, &o->material);
    if (c == RD_CORRECTION_DEPTH &&
        (!probe->capture || s->objects[probe->owner].probe.update == RD_PROBE_STATIC))
        c = RD_CORRECTION_BOX;
    if (c != RD_CORRECTION_BOX || probe->surface)
        return 0;
    return o->material.transparency > 0.0f ? RD_LIT_BOX_GLASS : RD_LIT_BOX_OPAQUE;
}

/* The room probe's texture as its readers of glossiness below 1 see it (blurred), or 0 while
 * it is not complete. */
static unsigned room_probe_blurred(const rd_scene *s)
{
    const rd_probe *room = &s->room_probe;
    if (room->faces_valid != 0x3f)
        return 0;
    if (rd_effective_blur(s) != RD_BLUR_PREFILTERED || !(room->gloss_min < 1.0f))
        return room->capture;
    return room->filtered_level >= 0 ? room->filtered : 0;
}

/* Whether object o is drawn as a glaze (glaze.h) in this pass: a lit pass (captures draw it
 * plain: the room probe never sees itself), the scene's switch on, the room probe ready. */
static int drawn_as_glaze(const rd_scene *s, const rd_pass *pass, const rd_object_desc *o)
{
    return pass->reflections && !pass->specular_off && s->reflection.glaze == RD_SWITCH_ON &&
           rd_material_glazed(&o->material) && room_probe_blurred(s) != 0;
}

/* The glaze's inputs (lit.frag, GLAZE): the room probe, the box it is corrected to, the level
 * of the highlight's lobe. */
static void set_glaze_uniforms(const rd_program *p, const rd_scene *s, const rd_material *m)
{
    const rd_probe *room = &s->room_probe;
    float bmin[3], bmax[3];
    rd_effective_proxy(s, bmin, bmax);
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_CUBE_MAP, room_probe_blurred(s));
    glUniform1i(p->u_room_probe, 6);
    glUniform3fv(p->u_room_centre, 1, room->centre);
    glUniform3fv(p->u_proxy_min, 1, bmin);
    glUniform3fv(p->u_proxy_max, 1, bmax);
    glUniform1f(p->u_room_lod, rd_probe_lod(room, rd_glaze_glossiness(m->shininess)));
    glActiveTexture(GL_TEXTURE0);
}

/* Whether a bounding sphere (centre, radius) lies outside one of the frustum's planes. */
static int outside_frustum(vec4 planes[6], const float sphere[4])
{
    for (int i = 0; i < 6; i++)
        if (glm_vec3_dot(planes[i], (float *)sphere) + planes[i][3] < -sphere[3])
            return 1;
    return 0;
}

/* Whether object o is a thin pane (a double-sided sheet of glass: light passes straight
 * through) that the pass blends over what lies behind it. From the eye of a planar mirror's
 * capture the view behind a thin pane is the capture's own, drawn from the ray's true origin:
 * the pane's probe, centred elsewhere, shows what lies far behind it through an opening (the
 * window's exterior through the window) from the wrong place. */
static int pane_over(const rd_pass *pass, const rd_object_desc *o)
{
    return pass->panes_over && pass->reflections && o->material.transparency > 0.0f &&
           o->double_sided;
}

/* Builds program p's code for this draw state without drawing: one triangle of mesh m under an
 * empty scissor box, since llvmpipe builds a program's code at its first draw. */
static rd_result prebuild(const rd_program *p, const rd_mesh_slot *m)
{
    if (!p)
        return RD_ERR_SHADER;
    GLint box[4], scissor = 0;
    glGetIntegerv(GL_SCISSOR_TEST, &scissor);
    glGetIntegerv(GL_SCISSOR_BOX, box);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 0, 0);
    glUseProgram(p->id);
    glBindVertexArray(m->vao);
    glDrawElements(GL_TRIANGLES, m->index_count < 3 ? m->index_count : 3, GL_UNSIGNED_INT, 0);
    glScissor(box[0], box[1], box[2], box[3]);
    if (!scissor)
        glDisable(GL_SCISSOR_TEST);
    return RD_OK;
}

/* One walk over the sorted objects. depth_only: the depth prepass, the same programs and
 * the same culling with colour writes off, so the shaded walk's depths match exactly.
 * panes: the walk over the panes of pane_over alone, back to front; the other walks leave
 * them out. */
static rd_result draw_list(rd_context *ctx, rd_scene *scene, const rd_pass *pass,
                           const draw_item *items, vec4 planes[6], unsigned *frame_uniforms_set,
                           unsigned *light_masks, int depth_only, int fast_paths, int panes)
{
    int shadows = pass->shadows && rd_shadows_active(scene);
    int fixed_locals, fixed_others;
    fixed_list_lengths(scene, &fixed_locals, &fixed_others);
    for (int n = 0; n < scene->object_count; n++) {
        int i = panes ? scene->object_count - 1 - n : n;
        int index = items[i].index;
        const rd_object_desc *o = &scene->objects[index];
        if (pane_over(pass, o) != panes)
            continue;
        if (pass->exclude_key && rd_object_key(scene, index) == pass->exclude_key)
            continue;
        if (pass->exclude_traced && rd_self_bvh_holds(pass->exclude_traced, index))
            continue;
        if (!pass->all_objects && scene->object_spheres &&
            outside_frustum(planes, scene->object_spheres[index]))
            continue;
        /* A probe skips what would cover less than about a texel of its faces. */
        if (pass->min_solid_radius > 0.0f && scene->object_spheres) {
            const float *sp = scene->object_spheres[index];
            float d = glm_vec3_distance((float *)sp, (float *)pass->eye);
            if (sp[3] < pass->min_solid_radius * d)
                continue;
        }
        /* Probes see no glass: drawn plain it would be an opaque dark sheet, and what a clear
         * pane shows is what lies behind it, which the probe sees anyway. */
        if (!pass->reflections && o->material.transparency > 0.0f)
            continue;
        /* A sharp probe's lookups intersect the lamps themselves (emitters.c). */
        if (pass->exclude_emitters && scene->object_emitter && scene->object_emitter[index])
            continue;
        const rd_mesh_slot *m = rd_mesh_lookup(ctx, o->mesh);
        if (!pass->reflections && !pass->full_meshes && o->probe_mesh.id) {
            const rd_mesh_slot *coarse = rd_mesh_lookup(ctx, o->probe_mesh);
            if (coarse)
                m = coarse;
        }
        const rd_texture_slot *t = rd_texture_lookup(ctx, o->material.diffuse_texture);
        if (!m)
            continue; /* destroyed after it was added: nothing to draw */
        const rd_probe *probe = NULL;
        if (pass->reflections && scene->object_probe && scene->object_probe[index] >= 0) {
            probe = &scene->probes[scene->object_probe[index]];
            /* Nothing captured yet (drawn plain this frame), or a planar mirror in another
             * mirror's capture (rd_pass.planar_off). */
            if (!rd_probe_texture(scene, probe) || (probe->planar && pass->planar_off))
                probe = NULL;
        }
        /* A mirror's capture without the pane's probe leaves the pane out, as a probe does. */
        if (pass->planar_off && !probe && o->material.transparency > 0.0f)
            continue;
        int variant = (t ? RD_LIT_TEXTURED : 0) | (probe ? RD_LIT_REFLECTING : 0) |
                      (scene->reflection.ambient == RD_AMBIENT_SH9 ? RD_LIT_SH9 : 0) |
                      (probe && (o->material.per_vertex_reflection || scene->reflection.per_vertex)
                           ? RD_LIT_PER_VERTEX
                           : 0) |
                      (probe && o->material.sphere_map && probe->sphere_map && pass->view_rot
                           ? RD_LIT_SPHERE_MAP
                           : 0) |
                      (shadows ? RD_LIT_SHADOWS : 0) |
                      (rd_scene_has_area_lights(scene) ? RD_LIT_AREA_LIGHTS : 0);
        if (o->material.pattern == RD_PATTERN_WOOD && !depth_only)
            variant |= RD_LIT_WOOD;
        if (m->bake && !depth_only && (m->bake == 1 || scene->lightmap))
            variant |= RD_LIT_BAKED; /* the ambient from the bake's vertices or lightmap */
        if (!probe && !depth_only && drawn_as_glaze(scene, pass, o))
            variant |= RD_LIT_GLAZE;
        /* In a mirror's capture a fixture reads its probe alone: tracing its own parts for every
         * texel of the capture would cost more than the rest of it, for what is a small
         * reflection of a reflection. Glass still traces: its probe leaves out the neighbours
         * seen through it, and a pane is a sharp lookup, one ray a texel each way. */
        int self_traced = probe && !(variant & (RD_LIT_PER_VERTEX | RD_LIT_SPHERE_MAP)) &&
                          !probe->planar &&
                          (!pass->planar_off || (o->material.transparency > 0.0f && !panes)) &&
                          rd_self_traced(scene, probe);
        if (self_traced)
            variant |= RD_LIT_SELF_TRACE; /* the full path's lookup, with its own parts */
        else if (probe && fast_paths)
            variant |= box_variant(scene, probe, o);
        if (probe && probe->planar)
            variant |= RD_LIT_PLANAR; /* its own lookup (probe_planar.c) */
        if (pass->specular_off)
            variant |= RD_LIT_NO_SPECULAR;
        if (depth_only)
            variant = RD_LIT_DEPTH_ONLY;
        /* The shadow lookups know a rectangle light only as a rectangle. */
        int rect_as_points = pass->rect_lights_as_points && !(variant & RD_LIT_SHADOWS);
        /* A live frame's programs run all the scene's lights in unrolled loops: cheaper than
         * leaving the lights out of an object's list that cannot reach it (lights_reaching),
         * and the same picture, as those add exactly zero. */
        int fixed = fast_paths && rect_as_points && !depth_only;
        int lamps = probe && probe->leaves_emitters && scene->emitter_count > 0;
        /* A still view that compiles a variant anew (the bake's light arriving, a new material)
         * in a context that also draws moving frames makes that variant's fixed-light program
         * too, and draws one triangle with it under an empty scissor box: llvmpipe builds a
         * program's code for the pipeline state at its first draw, so the next move finds it
         * built instead of stopping on it. That joins the compile this frame does anyway.
         * Renders that never move compile nothing more. */
        if (ctx->drew_live && !fixed && !depth_only && pass->view_rot && !rect_as_points &&
            !(variant & RD_LIT_SHADOWS) && !(ctx->lit[variant] && ctx->lit[variant]->id)) {
            if (prebuild(rd_lit_program_fixed(ctx, variant, fixed_locals, fixed_others, lamps),
                         m) != RD_OK)
                return RD_ERR_SHADER;
            frame_uniforms_set[variant] = 0; /* the variant's program is bound again below */
        }
        /* A primed pass (the shader warm-up's, rd_view.all_objects) builds too the variant an
         * object with a probe takes while its probe is not captured: drawn plain, as every
         * reflecting object is in the frames after a change of preset remakes the probes. */
        int plain =
            variant & ~(RD_LIT_REFLECTING | RD_LIT_PER_VERTEX | RD_LIT_SPHERE_MAP |
                        RD_LIT_BOX_OPAQUE | RD_LIT_BOX_GLASS | RD_LIT_PLANAR | RD_LIT_SELF_TRACE);
        if (pass->all_objects && probe && !depth_only && pass->view_rot) {
            const rd_program *q =
                fixed ? rd_lit_program_fixed(ctx, plain, fixed_locals, fixed_others, 0)
                      : rd_lit_program(ctx, plain);
            if (prebuild(q, m) != RD_OK)
                return RD_ERR_SHADER;
            frame_uniforms_set[variant] = 0;
        }
        const rd_program *p =
            fixed ? rd_lit_program_fixed(ctx, variant, fixed_locals, fixed_others, lamps)
                  : rd_lit_program(ctx, variant);
        if (!p)
            return RD_ERR_SHADER;
        /* By program name: a fixed-light program may have been made anew in its slot. */
        if (frame_uniforms_set[variant] != p->id) {
            rd_set_frame_uniforms(p, scene, pass->view_proj, pass->eye);
            if (rect_as_points && !depth_only)
                set_light_uniforms(p, scene, all_lights(scene), 1);
            light_masks[variant] = all_lights(scene);
            /* A highlight depends on where it is seen from; a probe sees from its centre, not
             * from the reflecting surface, so it may leave highlights out (section 8). */
            if (pass->specular_off)
                glUniform1f(p->u_specular_scale, 0.0f);
            if (pass->store_distance)
                glUniform1f(p->u_store_distance, 1.0f);
            if (variant & RD_LIT_SHADOWS)
                rd_shadow_set_uniforms(p, scene);
            frame_uniforms_set[variant] = p->id;
        } else {
            glUseProgram(p->id);
        }
        /* Per-object light culling (exact, lights_reaching). Shadowed programs index their
         * shadow maps by light, and "depth" probes re-light what they saw with every light,
         * as the lookups of lamps left out of a probe light those lamps: all keep the
         * scene's list. */
        if (!depth_only && fast_paths && !fixed && scene->object_spheres &&
            !(variant & RD_LIT_SHADOWS) && !(probe && (probe->surface || probe->leaves_emitters))) {
            unsigned mask = lights_reaching(scene, scene->object_spheres[index]);
            if (mask != light_masks[variant]) {
                set_light_uniforms(p, scene, mask, rect_as_points);
                light_masks[variant] = mask;
            }
        } else if (!depth_only && light_masks[variant] != all_lights(scene)) {
            set_light_uniforms(p, scene, all_lights(scene), rect_as_points);
            light_masks[variant] = all_lights(scene);
        }
        if (!depth_only) {
            if (t) {
                glActiveTexture(GL_TEXTURE0);
                glBindTexture(GL_TEXTURE_2D, t->name);
            }
            if (probe) {
                set_reflection_uniforms(p, scene, probe, o);
                glUniform1i(p->u_pane_over, panes);
            }
            if (variant & RD_LIT_GLAZE)
                set_glaze_uniforms(p, scene, &o->material);
            if (variant & RD_LIT_SELF_TRACE)
                rd_set_self_trace_uniforms(ctx, p, scene, probe, index,
                                           pass->sample_grid > 1 ? pass->sample_grid : 1);
            if (variant & RD_LIT_BAKED) {
                glActiveTexture(GL_TEXTURE12);
                glBindTexture(GL_TEXTURE_2D, scene->lightmap);
                glUniform1i(p->u_lightmap, 12);
                glUniform1i(p->u_bake_from_lightmap, m->bake == 2);
                glActiveTexture(GL_TEXTURE0);
            }
            if (variant & RD_LIT_SPHERE_MAP) {
                glActiveTexture(GL_TEXTURE2);
                glBindTexture(GL_TEXTURE_2D, probe->sphere_map);
                glUniform1i(p->u_sphere_map, 2);
                glUniformMatrix3fv(p->u_view_rot, 1, GL_FALSE, pass->view_rot);
                glActiveTexture(GL_TEXTURE0);
            }
        }
        /* Back faces of closed meshes are never seen: culling them saves shading fragments
         * that early depth testing cannot reject when they happen to be drawn first. */
        if (o->double_sided)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        /* A mirroring transform turns counter-clockwise triangles clockwise on screen. */
        glFrontFace(determinant3(o->transform) < 0.0f ? GL_CW : GL_CCW);
        rd_set_object_uniforms(p, o->transform, &o->material);
        glBindVertexArray(m->vao);
        glDrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT, 0);
    }
    return RD_OK;
}

rd_result rd_draw_objects(rd_context *ctx, rd_scene *scene, const rd_pass *pass)
{
    draw_item *items = sorted_draw_list(ctx, scene, pass->eye);
    if (!items)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "rd_render: out of memory");
    if (pass->rect_lights_as_points)
        ctx->drew_live = 1;
    /* Only what the view can see is drawn: a probe face sees a sixth of the room. */
    mat4 vp;
    vec4 planes[6];
    memcpy(vp, pass->view_proj, sizeof vp);
    glm_frustum_planes(vp, planes);
    /* By variant: the program set up this pass, and the lights it holds now (zero pages until
     * written: a pass uses a few variants). */
    unsigned *frame_uniforms_set = calloc(2 * (size_t)RD_LIT_VARIANTS, sizeof *frame_uniforms_set);
    if (!frame_uniforms_set) {
        free(items);
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "rd_render: out of memory");
    }
    unsigned *light_masks = frame_uniforms_set + RD_LIT_VARIANTS;
    rd_result r = RD_OK;
    /* TESSERA_NO_FAST_PATHS=1 draws without the depth prepass and the lean variant: the
     * general path the fast ones must match (tests/render/test_frame_work.c). */
    const char *slow = getenv("TESSERA_NO_FAST_PATHS");
    int fast = !(slow && *slow && strcmp(slow, "0") != 0);
    /* Probe captures sample the diffuse textures without anisotropic filtering: llvmpipe
     * filters anisotropically by looping over the footprint, and a probe a centimetre from a
     * wall or floor sees it at grazing angles nearly everywhere, where one large face takes
     * seconds. The capture is blurred or read through
     * a cube map of 90-degree faces, where the sharpness along a grazing wall is not seen. */
    if (pass->isotropic_textures) {
        if (!ctx->isotropic_sampler) {
            glGenSamplers(1, &ctx->isotropic_sampler);
            glSamplerParameteri(ctx->isotropic_sampler, GL_TEXTURE_MIN_FILTER,
                                GL_LINEAR_MIPMAP_LINEAR);
            glSamplerParameteri(ctx->isotropic_sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glSamplerParameteri(ctx->isotropic_sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glSamplerParameteri(ctx->isotropic_sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
        }
        glBindSampler(0, ctx->isotropic_sampler);
    }
    if (pass->depth_prepass && fast) {
        /* A depth-only walk first, then the shaded walk with GL_LEQUAL and no depth
         * writes, so llvmpipe's early depth test shades every pixel exactly once whatever the
         * order (layered tiles, grout and wall; fixtures in front of each other). The
         * prepass costs the vertices twice and a rasterisation without shading. */
        static const GLenum none = GL_NONE, colour = GL_COLOR_ATTACHMENT0;
        glDrawBuffers(1, &none);
        r = draw_list(ctx, scene, pass, items, planes, frame_uniforms_set, light_masks, 1, fast, 0);
        glDrawBuffers(1, &colour);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
    }
    if (r == RD_OK)
        r = draw_list(ctx, scene, pass, items, planes, frame_uniforms_set, light_masks, 0, fast, 0);
    if (r == RD_OK && pass->panes_over && pass->reflections) {
        /* colour = pane + weight (alpha) x what is behind it (lit.frag, u_pane_over) */
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC_ALPHA);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        r = draw_list(ctx, scene, pass, items, planes, frame_uniforms_set, light_masks, 0, fast, 1);
        glDisable(GL_BLEND);
    }
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    if (pass->isotropic_textures)
        glBindSampler(0, 0);
    free(items);
    free(frame_uniforms_set);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glBindVertexArray(0);
    return r;
}

rd_result rd_draw_view(rd_context *ctx, rd_scene *scene, const float *view_proj,
                       const float *view_rot, const float *eye, int sample_grid, int live,
                       int all_objects)
{
    return rd_draw_objects(ctx, scene,
                           &(rd_pass){.view_proj = view_proj,
                                      .view_rot = view_rot,
                                      .eye = eye,
                                      .reflections = 1,
                                      .shadows = 1,
                                      .depth_prepass = 1,
                                      .isotropic_textures = live,
                                      .rect_lights_as_points = live,
                                      .all_objects = all_objects,
                                      .sample_grid = sample_grid});
}
