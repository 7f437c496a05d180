/* The fixtures' numbers, by position: clockwise along the walls seen from above (each fixture at
 * the point of its nearest wall), starting at the door (the first door of the plan, else its
 * first opening, else its first corner), so a customer standing in the door reads the plan and
 * the room in the same order. The same number marks the
 * fixture on the plan, on the elevations and in the part list (its quotation position is looked
 * up here too, so the legend and the quotation cannot disagree). */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct numbered {
    int fixture;
    double sweep;  /* clockwise distance along the walls from the door, mm */
    double bottom; /* stacked fixtures (basin, mixer, mirror): the lower first */
} numbered;

static int cmp_numbered(const void *a, const void *b)
{
    const numbered *p = a, *q = b;
    if (fabs(p->sweep - q->sweep) > 1e-9)
        return p->sweep < q->sweep ? -1 : 1;
    if (p->bottom != q->bottom)
        return p->bottom < q->bottom ? -1 : 1;
    return p->fixture - q->fixture;
}

/* Where the numbering starts: the middle of the first door, or of the first opening, on the
 * inside face of its wall; else corner 0. */
static app_point2 start_point(const app_room_plan *pl, const char **name)
{
    *name = "corner 1";
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < pl->opening_count; k++) {
            const app_opening *op = &pl->openings[k];
            if ((pass == 0 && op->type != APP_OPENING_DOOR) || op->wall < 0 ||
                op->wall >= pl->corner_count)
                continue;
            app_point2 a = pl->corners[op->wall],
                       b = pl->corners[(op->wall + 1) % pl->corner_count];
            double l = hypot(b.x - a.x, b.y - a.y), s = op->offset_mm + op->width_mm / 2;
            if (l <= 0)
                continue;
            *name = op->type == APP_OPENING_DOOR ? "the door" : "the window";
            return (app_point2){a.x + (b.x - a.x) * s / l, a.y + (b.y - a.y) * s / l};
        }
    return pl->corners[0];
}

/* The position of p along the room's outline: the arc length, counter-clockwise from corner 0,
 * of the point of the nearest wall nearest to p. */
static double outline_position(const app_room_plan *pl, app_point2 p)
{
    double best = 1e300, at = 0, run = 0;
    for (int i = 0; i < pl->corner_count; i++) {
        app_point2 a = pl->corners[i], b = pl->corners[(i + 1) % pl->corner_count];
        double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy, l = sqrt(l2);
        double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        double qx = a.x + dx * t - p.x, qy = a.y + dy * t - p.y, dist = qx * qx + qy * qy;
        if (dist < best - 1e-9) {
            best = dist;
            at = run + t * l;
        }
        run += l;
    }
    return at;
}

void pr_fixtures_number(pr_doc *d)
{
    const app_room_plan *pl = &d->plan;
    numbered *list = malloc((size_t)(d->fixture_count + 1) * sizeof *list);
    if (!list)
        return;
    double perimeter = 0;
    for (int i = 0; i < pl->corner_count; i++) {
        app_point2 a = pl->corners[i], b = pl->corners[(i + 1) % pl->corner_count];
        perimeter += hypot(b.x - a.x, b.y - a.y);
    }
    const char *name;
    double start = outline_position(pl, start_point(pl, &name));
    int n = 0;
    for (int i = 0; i < d->fixture_count; i++) {
        pr_fixture *f = &d->fixtures[i];
        f->number = 0;
        if (f->part_count == 0)
            continue;
        app_point2 c = {(f->min[0] + f->max[0]) / 2, (f->min[1] + f->max[1]) / 2};
        /* The plan's corners run counter-clockwise: clockwise is backwards along the outline. */
        double sweep =
            perimeter > 0 ? fmod(start - outline_position(pl, c) + 2 * perimeter, perimeter) : 0;
        list[n++] = (numbered){i, sweep, f->min[2]};
    }
    qsort(list, (size_t)n, sizeof *list, cmp_numbered);
    for (int k = 0; k < n; k++)
        d->fixtures[list[k].fixture].number = k + 1;
    free(list);
}

int pr_quotation_position(const pr_doc *d, const app_product_ref *ref)
{
    if (!d->have_bom || !ref)
        return 0;
    for (int i = 0; i < d->bom.line_count; i++)
        if (!d->bom.lines[i].is_tile && app_product_ref_equal(&d->bom.lines[i].product, ref))
            return i + 1;
    return 0;
}

int pr_fixture_numbers_text(const pr_doc *d, const app_product_ref *ref, char *out, size_t size)
{
    size_t used = 0;
    int count = 0;
    if (size)
        out[0] = 0;
    for (int number = 1; number <= d->fixture_count; number++)
        for (int i = 0; i < d->fixture_count; i++) {
            const pr_fixture *f = &d->fixtures[i];
            if (f->number != number || !f->has_product || !app_product_ref_equal(&f->ref, ref))
                continue;
            int w = snprintf(out + used, used < size ? size - used : 0, "%s%d", count ? ", " : "",
                             number);
            if (w > 0 && used + (size_t)w < size)
                used += (size_t)w;
            count++;
        }
    return count;
}

const char *pr_numbering_start(const pr_doc *d)
{
    const char *name;
    start_point(&d->plan, &name);
    return name;
}
