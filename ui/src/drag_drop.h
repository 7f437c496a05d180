/* Dragging a product from the catalog browser into the plan or the 3D view:
 * press on a hit, drag it out of the panel, let go over a view; it is placed there as one undo
 * step. The geometry (the floor point under the pointer) is pure and tested without a window. */
#ifndef UI_DRAG_DROP_H
#define UI_DRAG_DROP_H

typedef struct ui_drag_drop {
    int active;      /* a product is being dragged */
    int hit;         /* the browser's hit being dragged */
    double x, y;     /* the pointer, window pixels */
    char label[200]; /* shown beside the pointer */
} ui_drag_drop;

/* The point (mm) where the ray through window pixel (sx, sy) meets the floor z = 0, for a
 * perspective camera at eye looking at target (mm, z up) with a vertical field of view
 * fov_y_deg over a width x height window. Returns 1 and writes out_mm[2], or 0 when the ray
 * does not go down to the floor (above the horizon) or the input is degenerate. */
int ui_floor_point(const double eye[3], const double target[3], double fov_y_deg, int width,
                   int height, double sx, double sy, double out_mm[2]);

#endif
