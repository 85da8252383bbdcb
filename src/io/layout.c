/* summary.json's "layout" (layout.h) */
#include "io/layout.h"

#include <math.h>

#include "base/constants.h"
#include "base/json_util.h"
#include "model/path.h"
#include "parts/parts.h"

/* arcs are drawn as polygons of at most this angle per side, rad, and
 * lines in pieces of at most this fraction of the loop (so that a region
 * of s, loaded or lifted, can be drawn over them) */
#define ARC_STEP (2.0 * BD_PI / 180.0)
#define LINE_STEP (1.0 / 600.0)

static void add_point(cJSON *s, cJSON *x, cJSON *y, const bd_path *path, double at)
{
    double p[2], t[2];
    bd_path_point(path, at, p, t);
    cJSON_AddItemToArray(s, cJSON_CreateNumber(at));
    cJSON_AddItemToArray(x, cJSON_CreateNumber(p[0]));
    cJSON_AddItemToArray(y, cJSON_CreateNumber(p[1]));
}

/* a stretch [s0, s0 + len] of the path that is a line (sweep 0) or an arc
 * of the given sweep: its end, and its inner points if it is an arc */
static void add_stretch(cJSON *s, cJSON *x, cJSON *y, const bd_path *path, double s0, double len,
                        double sweep)
{
    int n = (int)ceil(len / (LINE_STEP * path->length));
    if (sweep != 0.0 && ceil(fabs(sweep) / ARC_STEP) > n)
        n = (int)ceil(fabs(sweep) / ARC_STEP);
    if (n < 1)
        n = 1;
    for (int k = 1; k <= n; k++)
        add_point(s, x, y, path, s0 + len * k / n);
}

/* the belt path from s = 0 round to the loop's end */
static void add_path(cJSON *layout, const bd_path *path)
{
    cJSON *o = cJSON_AddObjectToObject(layout, "path");
    cJSON *s = cJSON_AddArrayToObject(o, "s_m");
    cJSON *x = cJSON_AddArrayToObject(o, "x_m");
    cJSON *y = cJSON_AddArrayToObject(o, "y_m");
    add_point(s, x, y, path, 0.0);
    for (int g = 0; g < path->segment_count; g++) {
        const bd_path_segment *seg = &path->segments[g];
        if (seg->kind == BD_SEGMENT_ARC) {
            add_stretch(s, x, y, path, seg->s0, seg->length, seg->sweep);
        } else if (seg->piece_count == 0) {
            add_stretch(s, x, y, path, seg->s0, seg->length, 0.0);
        } else {
            for (int k = 0; k < seg->piece_count; k++) {
                const bd_path_piece *pc = &path->pieces[seg->piece_first + k];
                add_stretch(s, x, y, path, pc->s0, pc->length, pc->is_arc ? pc->sweep : 0.0);
            }
        }
    }
}

/* a drive's rating at the pulley shaft: the motor's rated torque through
 * gear_ratio (motor over pulley speed, a transmission's sheaves included:
 * model-format.md), N·m; 0 without a motor */
static double rated_torque(const bd_drive_def *d)
{
    if (d->control != BD_CONTROL_MOTOR || d->motor.rated_speed_rpm <= 0.0)
        return 0.0;
    return bd_motor_rated_torque(&d->motor) * d->motor.gear_ratio;
}

static void add_pulleys(cJSON *layout, const bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    const bd_path *path = &sim->model->path;
    cJSON *a = cJSON_AddArrayToObject(layout, "pulleys");
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *pd = &def->pulleys[i];
        const bd_path_segment *arc = bd_path_arc(path, i);
        cJSON *p = cJSON_CreateObject();
        cJSON_AddStringToObject(p, "name", pd->name);
        /* the centre the belt was laid round: a takeup's may stand off the
         * file's, moved along its axis until the belt's stretched length
         * closes the loop (belt/lumped/layout.c) */
        bd_json_add_number(p, "x_m", arc->centre[0]);
        bd_json_add_number(p, "y_m", arc->centre[1]);
        bd_json_add_number(p, "radius_m", pd->radius);
        /* the wrap on s: where the belt arrives and where it leaves */
        bd_json_add_number(p, "s_start_m", arc->s0);
        bd_json_add_number(p, "s_end_m", fmod(arc->s0 + arc->length, path->length));
        bd_json_add_number(p, "wrap_deg", bd_path_wrap_angle(path, i) * 180.0 / BD_PI);
        bd_json_add_number(p, "friction_static", pd->friction.mu_static);
        cJSON_AddBoolToObject(p, "drive", pd->has_drive);
        if (pd->has_drive) {
            double T = rated_torque(&pd->drive);
            if (T > 0.0)
                bd_json_add_number(p, "rated_torque_Nm", T);
            if (isfinite(pd->drive.max_torque))
                bd_json_add_number(p, "max_torque_Nm", pd->drive.max_torque);
        }
        cJSON_AddBoolToObject(p, "takeup", pd->has_takeup);
        if (pd->has_takeup) {
            cJSON *ax = cJSON_AddArrayToObject(p, "takeup_axis");
            cJSON_AddItemToArray(ax, cJSON_CreateNumber(pd->takeup.axis[0]));
            cJSON_AddItemToArray(ax, cJSON_CreateNumber(pd->takeup.axis[1]));
            bd_json_add_number(p, "takeup_shift_m",
                               (arc->centre[0] - pd->x) * pd->takeup.axis[0]
                                   + (arc->centre[1] - pd->y) * pd->takeup.axis[1]);
        }
        cJSON_AddItemToArray(a, p);
    }
}

void bd_layout_to_json(cJSON *root, const bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    const bd_path *path = &sim->model->path;
    cJSON *layout = cJSON_AddObjectToObject(root, "layout");
    bd_json_add_number(layout, "belt_length_m", path->length);
    add_pulleys(layout, sim);
    if (def->material.present) {
        double s_feed, len;
        bd_path_loaded_region(path, &def->material, &s_feed, &len);
        cJSON *m = cJSON_AddObjectToObject(layout, "loaded");
        bd_json_add_number(m, "feed_s_m", s_feed);
        bd_json_add_number(m, "length_m", len);
    }
    add_path(layout, path);
}
