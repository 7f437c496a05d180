/* Labels beside the points of a plot, none over another label or over a point: greedy
 * placement (the candidate-position method of cartographic point labelling, Christensen,
 * Marks and Shieber 1995, "An empirical study of algorithms for point-feature label
 * placement", in its greedy form). No drawing here: the plot (sweep_plot.c) measures the
 * labels, places them and draws them. */
#ifndef APP_LABEL_PLACE_H
#define APP_LABEL_PLACE_H

/* A rectangle: left, top (y grows downwards, as on an image), width, height. */
typedef struct app_label_box {
    double x, y, w, h;
} app_label_box;

typedef struct app_label {
    double px, py; /* the point's centre */
    double w, h;   /* the label's extent */
    /* Results of app_labels_place: */
    app_label_box box; /* where the label goes */
    int placed;        /* 1: placed; 0: no free room within reach (left out) */
    int moved;         /* 1: placed away from its point, to be joined to it by a leader line */
} app_label;

/* 1 when a and b share interior (touching edges do not count). */
int app_label_boxes_overlap(const app_label_box *a, const app_label_box *b);

/* Places labels[0..n) in that order (earlier labels get the nearer places): each at the first
 * candidate around its point -- right, left, above, below, the diagonals, then rings further out
 * -- that lies inside `area`, overlaps no label placed before it and no point (a square of
 * side 2 * point_radius around each centre). */
void app_labels_place(app_label *labels, int n, double point_radius, const app_label_box *area);

#endif
