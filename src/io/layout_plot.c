/* layout_plot.h: the conveyor drawing and its marks on s axes */
#include "io/layout_plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/json_util.h"

/* the drawing's plot area is about this wide and at least this high, px */
#define DRAW_W 1100.0
#define DRAW_MIN_H 160.0

static const bd_rgb belt_rgb = {0.25, 0.25, 0.25};
static const bd_rgb loaded_rgb = {0.55, 0.35, 0.10};
static const bd_rgb lifted_rgb = {0.90, 0.50, 0.0};
static const bd_rgb pulley_rgb[3] = {{0.0, 0.0, 0.0}, {0.80, 0.15, 0.10}, {0.0, 0.45, 0.70}};

/* is s in the region of the loop [from, from + length] (it may wrap)? */
static int in_region(double s, double from, double length, double loop)
{
    double d = fmod(s - from + loop, loop);
    return d <= length + 1e-9;
}

static double *num_array(const cJSON *o, const char *key, size_t *n)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(o, key);
    int k = cJSON_IsArray(a) ? cJSON_GetArraySize(a) : 0;
    *n = (size_t)k;
    if (k == 0)
        return NULL;
    double *v = malloc((size_t)k * sizeof *v);
    if (!v)
        return NULL;
    int i = 0;
    const cJSON *e;
    cJSON_ArrayForEach(e, a) v[i++] = cJSON_IsNumber(e) ? e->valuedouble : NAN;
    return v;
}

/* the vertical exaggeration that gives a flat conveyor a readable height:
 * 1 when its true shape is already DRAW_MIN_H px high, else the next of
 * 2, 5, 10, 20, 50, ... that is */
static double exaggeration(double xspan, double yspan)
{
    if (!(xspan > 0.0) || !(yspan > 0.0))
        return 1.0;
    double h = DRAW_W * yspan / xspan;
    double e = 1.0;
    static const double steps[3] = {2.0, 5.0, 10.0};
    for (double decade = 1.0; h * e < DRAW_MIN_H && decade < 1e6; decade *= 10.0)
        for (int i = 0; i < 3 && h * e < DRAW_MIN_H; i++)
            e = steps[i] * decade;
    return e;
}

void bd_layout_drawing_free(bd_layout_drawing *d)
{
    free(d->x);
    free(d->y);
    free(d->loaded_y);
    free(d->lifted_y);
    memset(d, 0, sizeof *d);
}

int bd_layout_figure(const cJSON *summary, bd_plot_figure *f, bd_layout_drawing *d)
{
    memset(d, 0, sizeof *d);
    const cJSON *lay = cJSON_GetObjectItemCaseSensitive(summary, "layout");
    const cJSON *path = cJSON_GetObjectItemCaseSensitive(lay, "path");
    if (!cJSON_IsObject(lay) || !cJSON_IsObject(path))
        return 0;
    size_t ns, nx, ny;
    double *s = num_array(path, "s_m", &ns);
    d->x = num_array(path, "x_m", &nx);
    d->y = num_array(path, "y_m", &ny);
    d->n = nx < ny ? nx : ny;
    if (ns < d->n)
        d->n = ns;
    if (d->n < 2 || !s || !d->x || !d->y) {
        int rc = d->n < 2 ? 0 : -1;
        free(s);
        bd_layout_drawing_free(d);
        return rc;
    }
    double loop = bd_json_num(lay, "belt_length_m");
    /* the loaded stretch and where the belt lifted off, drawn over the belt */
    const cJSON *loaded = cJSON_GetObjectItemCaseSensitive(lay, "loaded");
    const cJSON *lift = cJSON_GetObjectItemCaseSensitive(summary, "lift_off");
    double lift_from = bd_json_num(lift, "from_s_m"), lift_to = bd_json_num(lift, "to_s_m");
    int lifted = isfinite(lift_from) && isfinite(lift_to);
    if (cJSON_IsObject(loaded))
        d->loaded_y = malloc(d->n * sizeof *d->loaded_y);
    if (lifted)
        d->lifted_y = malloc(d->n * sizeof *d->lifted_y);
    if ((cJSON_IsObject(loaded) && !d->loaded_y) || (lifted && !d->lifted_y)) {
        free(s);
        bd_layout_drawing_free(d);
        return -1;
    }
    double feed = bd_json_num(loaded, "feed_s_m"), len = bd_json_num(loaded, "length_m");
    for (size_t i = 0; i < d->n; i++) {
        if (d->loaded_y)
            d->loaded_y[i] = in_region(s[i], feed, len, loop) ? d->y[i] : NAN;
        if (d->lifted_y)
            d->lifted_y[i] = s[i] >= lift_from && s[i] <= lift_to ? d->y[i] : NAN;
    }
    free(s);

    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (size_t i = 0; i < d->n; i++) {
        xlo = fmin(xlo, d->x[i]);
        xhi = fmax(xhi, d->x[i]);
        ylo = fmin(ylo, d->y[i]);
        yhi = fmax(yhi, d->y[i]);
    }
    d->exaggeration = exaggeration(xhi - xlo, yhi - ylo);
    bd_plot_axes *a = &f->panel[0];
    a->xlabel = "x [m]";
    a->ylabel = "y [m]";
    a->aspect = d->exaggeration;
    int k = bd_plot_add_series(a, d->x, d->y, d->n, "belt", belt_rgb);
    if (d->loaded_y) {
        snprintf(d->loaded_label, sizeof d->loaded_label, "loaded, %.1f m from the feed", len);
        k = bd_plot_add_series(a, d->x, d->loaded_y, d->n, d->loaded_label, loaded_rgb);
        a->series[k].width = 5.0;
    }
    if (d->lifted_y) {
        snprintf(d->lifted_label, sizeof d->lifted_label,
                 "where the belt lifted off its idlers at times (s = %.1f … %.1f m)", lift_from,
                 lift_to);
        k = bd_plot_add_series(a, d->x, d->lifted_y, d->n, d->lifted_label, lifted_rgb);
        a->series[k].width = 2.5;
        a->series[k].dashed = 1;
    }
    /* the pulleys: dots by kind, each with its name */
    const cJSON *pulleys = cJSON_GetObjectItemCaseSensitive(lay, "pulleys"), *p;
    int named = 0;
    cJSON_ArrayForEach(p, pulleys) {
        int kind = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(p, "drive")) ? 1
                 : cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(p, "takeup")) ? 2 : 0;
        double px = bd_json_num(p, "x_m"), py = bd_json_num(p, "y_m");
        const char *name = bd_json_str(p, "name");
        if (!isfinite(px) || !isfinite(py) || named >= BD_PLOT_MAX_TEXTS)
            continue;
        d->px[kind][d->np[kind]] = px;
        d->py[kind][d->np[kind]++] = py;
        snprintf(d->names[named], sizeof d->names[named], "%s", name);
        bd_plot_add_text(a, px, py, d->names[named++]);
    }
    static const char *const kind_label[3] = {"pulley", "drive pulley", "takeup pulley"};
    for (int c = 0; c < 3; c++) {
        if (d->np[c] == 0)
            continue;
        k = bd_plot_add_series(a, d->px[c], d->py[c], (size_t)d->np[c], kind_label[c],
                               pulley_rgb[c]);
        a->series[k].points = 1;
    }
    if (d->exaggeration > 1.0)
        snprintf(d->subtitle, sizeof d->subtitle,
                 "pulley centres and the belt path as built; heights drawn %g× their scale",
                 d->exaggeration);
    else
        snprintf(d->subtitle, sizeof d->subtitle,
                 "pulley centres and the belt path as built, true to scale");
    f->subtitle = d->subtitle;
    return 1;
}

void bd_layout_mark_s_axis(const cJSON *summary, bd_plot_axes *a)
{
    const cJSON *lay = cJSON_GetObjectItemCaseSensitive(summary, "layout");
    if (!cJSON_IsObject(lay))
        return;
    const cJSON *p;
    cJSON_ArrayForEach(p, cJSON_GetObjectItemCaseSensitive(lay, "pulleys")) {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(p, "name");
        bd_plot_add_xmark(a, bd_json_num(p, "s_start_m"),
                          cJSON_IsString(name) ? name->valuestring : NULL);
    }
    const cJSON *loaded = cJSON_GetObjectItemCaseSensitive(lay, "loaded");
    double feed = bd_json_num(loaded, "feed_s_m"), len = bd_json_num(loaded, "length_m");
    double loop = bd_json_num(lay, "belt_length_m");
    if (!a->map && isfinite(feed) && isfinite(len) && isfinite(loop) && loop > 0.0) {
        a->has_xspan = 1;
        a->xspan = (bd_plot_xspan){feed, fmod(feed + len, loop), "loaded region (feed to discharge)",
                                   {0.55, 0.35, 0.10}, 0.10};
    }
}
