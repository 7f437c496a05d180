#ifndef RENDER_DEPTH_RANGE_H
#define RENDER_DEPTH_RANGE_H

#include "render/render.h"

/* How far outside the room's box an object may reach and still widen the depth range. */
#define RD_DEPTH_ROOM_MARGIN_M 1.0f

/* The box every depth range (the view's near and far, the shadow maps') is fitted to: the
 * bounds of the objects, but no farther than RD_DEPTH_ROOM_MARGIN_M outside the room's box
 * (the scene's box proxy) when the scene has one, so that one object moved kilometres away
 * cannot stretch the far plane and leave the room without depth precision. Objects beyond
 * the clamp fall behind the far plane and are not drawn. Without a room: the objects' bounds;
 * without objects either: the box [-1, 1]^3. */
void rd_scene_depth_bounds(const rd_scene *s, float lo[3], float hi[3]);

/* The near plane for a far plane `far_m` over the box [lo, hi]: far / 1000, but no more than
 * 1/250 of the box's smallest side, so a tall narrow room (a plan height of kilometres) does
 * not put its walls, a metre from the eye, in front of the near plane. */
float rd_depth_near(float far_m, const float lo[3], const float hi[3]);

#endif
