/* The sweep plot's label placement (app/measure/label_place.h): in crowded plots every label
 * finds a place, no two placed labels share any area, none covers a point, all stay inside the
 * plot; an uncrowded label sits right beside its point with no leader line. */
#include "test_util.h"

#include "app/measure/label_place.h"

#include <math.h>

/* The invariants every placement must keep; returns how many labels were placed. */
static int check_placement(const app_label *l, int n, double r, const app_label_box *area)
{
    int placed = 0;
    for (int i = 0; i < n; i++) {
        if (!l[i].placed)
            continue;
        placed++;
        const app_label_box *b = &l[i].box;
        CHECK(b->w == l[i].w && b->h == l[i].h);
        CHECK(b->x >= area->x && b->y >= area->y && b->x + b->w <= area->x + area->w &&
              b->y + b->h <= area->y + area->h);
        for (int j = 0; j < n; j++) {
            if (j != i && l[j].placed && app_label_boxes_overlap(b, &l[j].box)) {
                fprintf(stderr, "labels %d and %d overlap\n", i, j);
                CHECK(0);
            }
            app_label_box dot = {l[j].px - r, l[j].py - r, 2 * r, 2 * r};
            if (app_label_boxes_overlap(b, &dot)) {
                fprintf(stderr, "label %d covers point %d\n", i, j);
                CHECK(0);
            }
        }
    }
    return placed;
}

int main(void)
{
    /* The overlap test itself: shared interior counts, touching edges do not. */
    app_label_box a = {0, 0, 10, 10}, b = {9, 9, 5, 5}, c = {10, 0, 5, 5}, d = {0, 10, 5, 5};
    CHECK(app_label_boxes_overlap(&a, &b) && app_label_boxes_overlap(&b, &a));
    CHECK(!app_label_boxes_overlap(&a, &c) && !app_label_boxes_overlap(&a, &d));

    const app_label_box area = {90, 60, 780, 570};
    const double r = 6.0;

    /* One label alone: right of its point, level with it, not moved. */
    app_label one = {.px = 400, .py = 300, .w = 50, .h = 12};
    app_labels_place(&one, 1, r, &area);
    CHECK(one.placed && !one.moved);
    CHECK(one.box.x > one.px + r && one.box.x < one.px + r + 5);
    CHECK(fabs(one.box.y + one.box.h / 2 - one.py) < 1e-9);

    /* A point at the plot's right edge: its label goes left. */
    app_label edge = {.px = 865, .py = 300, .w = 50, .h = 12};
    app_labels_place(&edge, 1, r, &area);
    CHECK(edge.placed && edge.box.x + edge.box.w <= edge.px - r);

    /* The fast end of a sweep: 28 points within 40 x 30 pixels, some on top of each other, with
     * labels as long as the sweep's ("depth, own probe only"). */
    enum { N = 28 };
    app_label crowd[N];
    for (int i = 0; i < N; i++) {
        crowd[i] = (app_label){
            .px = 120 + (i * 7) % 40, .py = 500 + (i * 13) % 30, .w = 30 + (i * 17) % 90, .h = 13};
    }
    crowd[5].px = crowd[4].px, crowd[5].py = crowd[4].py; /* identical points */
    app_labels_place(crowd, N, r, &area);
    CHECK(check_placement(crowd, N, r, &area) == N);
    int moved = 0;
    for (int i = 0; i < N; i++)
        moved += crowd[i].moved;
    CHECK(moved > 0); /* the crowd cannot all sit beside their points */

    /* The same crowd in a corner of the plot: room on two sides only. */
    for (int i = 0; i < N; i++) {
        crowd[i].px = area.x + 8 + (i * 7) % 40;
        crowd[i].py = area.y + area.h - 8 - (i * 13) % 30;
    }
    app_labels_place(crowd, N, r, &area);
    CHECK(check_placement(crowd, N, r, &area) == N);

    /* More labels than fit in a small plot: whatever is placed still never overlaps. */
    enum { M = 200 };
    static app_label many[M];
    const app_label_box small = {0, 0, 200, 120};
    for (int i = 0; i < M; i++)
        many[i] = (app_label){.px = 100 + (i % 7), .py = 60 + (i % 5), .w = 40, .h = 12};
    app_labels_place(many, M, r, &small);
    int placed = check_placement(many, M, r, &small);
    CHECK(placed > 10 && placed < M);
    return check_report("label_place");
}
