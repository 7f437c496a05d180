/* Greedy point-label placement (label_place.h): candidates in rings around each point, the
 * nearest ring first, and within a ring the positions readers expect first (right of the
 * point, then left, above, below, then the diagonals and the angles between). */
#include "app/measure/label_place.h"

#include <math.h>

#define PI 3.14159265358979323846

/* Gap between a point's disc and the nearest edge of its label, pixels. */
#define GAP 2.0
/* Rings: the first touches the point; each further one a label height out, up to RINGS. */
#define RINGS 24
/* Angles a ring tries beyond the first eight (right, left, above, below, the diagonals). */
#define RING_ANGLES 24

int app_label_boxes_overlap(const app_label_box *a, const app_label_box *b)
{
    return a->x < b->x + b->w && b->x < a->x + a->w && a->y < b->y + b->h && b->y < a->y + a->h;
}

static int inside(const app_label_box *b, const app_label_box *area)
{
    return b->x >= area->x && b->y >= area->y && b->x + b->w <= area->x + area->w &&
           b->y + b->h <= area->y + area->h;
}

/* The box of label l whose centre lies in direction `angle` (radians, y down) from the point,
 * its nearest edge `d` from the point's centre: the centre on an ellipse with the label's half
 * extents plus d as its axes, so that right/left/above/below sit flush beside the point. */
static app_label_box candidate(const app_label *l, double angle, double d)
{
    double c = cos(angle), s = sin(angle);
    /* Snap near-axis directions, so that "right" is exactly level with the point. */
    if (fabs(c) < 1e-9)
        c = 0.0;
    if (fabs(s) < 1e-9)
        s = 0.0;
    double cx = l->px + c * (l->w / 2 + d), cy = l->py + s * (l->h / 2 + d);
    return (app_label_box){cx - l->w / 2, cy - l->h / 2, l->w, l->h};
}

static int free_at(const app_label_box *b, const app_label *labels, int placed_before, int n,
                   double r, const app_label_box *area)
{
    if (!inside(b, area))
        return 0;
    for (int j = 0; j < placed_before; j++)
        if (labels[j].placed && app_label_boxes_overlap(b, &labels[j].box))
            return 0;
    for (int j = 0; j < n; j++) {
        app_label_box dot = {labels[j].px - r, labels[j].py - r, 2 * r, 2 * r};
        if (app_label_boxes_overlap(b, &dot))
            return 0;
    }
    return 1;
}

void app_labels_place(app_label *labels, int n, double point_radius, const app_label_box *area)
{
    static const double first[8] = {0.0,     PI,     -PI / 2,     PI / 2,
                                    -PI / 4, PI / 4, -3 * PI / 4, 3 * PI / 4};
    for (int i = 0; i < n; i++) {
        app_label *l = &labels[i];
        l->placed = l->moved = 0;
        double step = l->h > 1.0 ? l->h : 1.0;
        for (int ring = 0; ring < RINGS && !l->placed; ring++) {
            double d = point_radius + GAP + ring * step;
            for (int k = 0; k < 8 + RING_ANGLES && !l->placed; k++) {
                /* Beyond the first eight: every 11.25 degrees, the ones nearest "right" first. */
                double a = k < 8 ? first[k]
                                 : (double)((k - 8) / 2 + 1) * (2 * PI / (RING_ANGLES + 8)) *
                                       ((k - 8) % 2 ? -1.0 : 1.0);
                app_label_box b = candidate(l, a, d);
                if (free_at(&b, labels, i, n, point_radius, area)) {
                    l->box = b;
                    l->placed = 1;
                    l->moved = ring > 0;
                }
            }
        }
    }
}
