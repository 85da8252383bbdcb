/* Writers of a run's outputs (cli.md `run` outputs): history.csv and
 * tension.csv row by row at output intervals, envelope.csv and summary.json
 * at the end. Beside the contract: parts.csv (the drives' tight and slack
 * side tensions and the takeups' pull, at history's rows) and summary.json's
 * "layout" (io/layout.c), which the report draws. Every file is written under a temporary name and renamed when
 * complete; an interrupted or failed run still renames its CSVs, which are
 * valid up to the last complete row. */
#include "io/outputs.h"
#include "io/checks.h"
#include "io/layout.h"
#include "base/file.h"
#include "base/json_util.h"

#include <cjson/cJSON.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "beltdyn/standards.h"
#include "io/hdf5_out.h"
#include "parts/parts.h"
#include "sensors/sensors.h"
#include "sim/timestep.h"

int bd_outputs_make_dir(const char *dir, char *err, size_t errlen)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        mkdir(buf, 0777);
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "cannot create output directory '%s': %s", dir, strerror(errno));
        return 1;
    }
    return 0;
}

static FILE *open_part(bd_outputs *o, int which, const char *name, char *err, size_t errlen)
{
    char dir[sizeof o->dir];
    memcpy(dir, o->dir, sizeof dir);
    snprintf(o->final_path[which], sizeof o->final_path[which], "%s/%s", dir, name);
    snprintf(o->part_path[which], sizeof o->part_path[which], "%s/.%s.part", dir, name);
    FILE *f = fopen(o->part_path[which], "w");
    if (!f)
        snprintf(err, errlen, "cannot write '%s': %s", o->part_path[which], strerror(errno));
    return f;
}

static int finish_part(bd_outputs *o, int which, FILE **f)
{
    if (!*f)
        return 0;
    int bad = fclose(*f) != 0;
    *f = NULL;
    if (!bad)
        bad = rename(o->part_path[which], o->final_path[which]) != 0;
    return bad;
}

/* a failed open: the CSVs opened so far closed and removed, the
 * envelope's bins freed (the caller closes nothing after a failed open) */
static void drop_parts(bd_outputs *o)
{
    free(o->env_max);
    free(o->env_min);
    o->env_max = o->env_min = NULL;
    FILE **f[] = {&o->history, &o->tension, &o->parts};
    int which[] = {BD_OUT_HISTORY, BD_OUT_TENSION, BD_OUT_PARTS};
    for (int k = 0; k < 3; k++)
        if (*f[k]) {
            fclose(*f[k]);
            *f[k] = NULL;
            remove(o->part_path[which[k]]);
        }
}

/* a header's pulley columns: two per drive, then one per takeup (the
 * order history.csv and parts.csv write their cells in) */
static void pulley_columns(FILE *f, const bd_model_def *def, int count, const char *drive_a,
                           const char *drive_b, const char *takeup)
{
    for (int i = 0; i < count; i++)
        if (def->pulleys[i].has_drive)
            fprintf(f, ",%s.%s,%s.%s", def->pulleys[i].name, drive_a, def->pulleys[i].name,
                    drive_b);
    for (int i = 0; i < count; i++)
        if (def->pulleys[i].has_takeup)
            fprintf(f, ",%s.%s", def->pulleys[i].name, takeup);
}

int bd_outputs_open(bd_outputs *o, const bd_sim *sim, const char *dir, int hdf5, char *err,
                    size_t errlen)
{
    memset(o, 0, sizeof *o);
    /* the files' paths (dir/.tension.h5.part the longest) fit with a dir
     * that fits; a longer one is refused, not cut short */
    if (snprintf(o->dir, sizeof o->dir, "%s", dir) >= (int)sizeof o->dir) {
        snprintf(err, errlen, "%.200s...: output directory path too long (at most %d bytes)",
                 dir, (int)sizeof o->dir - 1);
        return 1;
    }
    if (bd_outputs_make_dir(dir, err, errlen))
        return 1;
    /* the envelope's bins, before any file is opened */
    o->bins = sim->model->n;
    o->env_max = malloc((size_t)o->bins * sizeof *o->env_max);
    o->env_min = malloc((size_t)o->bins * sizeof *o->env_min);
    if (!o->env_max || !o->env_min) {
        free(o->env_max);
        free(o->env_min);
        o->env_max = o->env_min = NULL;
        snprintf(err, errlen, "out of memory for the tension envelope (%d bins)", o->bins);
        return 1;
    }
    const bd_model_def *def = sim->model->def;
    int parts = 0;
    for (int i = 0; i < sim->model->pulley_count; i++)
        parts += def->pulleys[i].has_drive || def->pulleys[i].has_takeup;
    o->history = open_part(o, BD_OUT_HISTORY, "history.csv", err, errlen);
    o->tension = o->history ? open_part(o, BD_OUT_TENSION, "tension.csv", err, errlen) : NULL;
    o->parts = o->tension && parts ? open_part(o, BD_OUT_PARTS, "parts.csv", err, errlen) : NULL;
    if (!o->history || !o->tension || (parts && !o->parts)) {
        drop_parts(o);
        return 1;
    }
    if (hdf5) {
        char d[sizeof o->dir];
        memcpy(d, o->dir, sizeof d);
        snprintf(o->final_path[BD_OUT_HDF5], sizeof o->final_path[BD_OUT_HDF5], "%s/tension.h5", d);
        snprintf(o->part_path[BD_OUT_HDF5], sizeof o->part_path[BD_OUT_HDF5], "%s/.tension.h5.part",
                 d);
        o->h5 = bd_h5_open(o->part_path[BD_OUT_HDF5], sim->model->def->name, sim->model->n,
                           sim->model->path.length, err, errlen);
        if (!o->h5) {
            drop_parts(o);
            remove(o->part_path[BD_OUT_HDF5]);
            return 1;
        }
    }
    o->history_buf = malloc(1 << 16);
    o->tension_buf = malloc(1 << 20);
    if (o->history_buf)
        setvbuf(o->history, o->history_buf, _IOFBF, 1 << 16);
    if (o->tension_buf)
        setvbuf(o->tension, o->tension_buf, _IOFBF, 1 << 20);
    bd_outputs_records_restart(o, 0.0);
    /* tension.csv's spacing: every k-th element, k the spacing over the
     * mean element length (at least 1) */
    o->field_stride = bd_tension_stride(&def->simulation, sim->model->path.length, sim->model->n);
    o->next_tension = 0.0;
    /* history header */
    fprintf(o->history, "t_s");
    for (int i = 0; i < sim->model->probe_count; i++)
        fprintf(o->history, ",%s.tension_N,%s.speed_mps", def->simulation.probes[i].name,
                def->simulation.probes[i].name);
    pulley_columns(o->history, def, sim->model->pulley_count, "omega_rad_s", "torque_Nm",
                   "travel_m");
    fprintf(o->history, ",kinetic_J,potential_J,dissipated_J,input_J");
    /* a belt whose topology varies: its degrees of freedom (belt.h) */
    if (sim->model->belt->topology)
        fprintf(o->history, ",belt_dof");
    fputc('\n', o->history);
    fprintf(o->tension, "t_s,s_m,x_m,y_m,tension_N,speed_mps\n");
    if (o->parts) {
        fprintf(o->parts, "t_s");
        pulley_columns(o->parts, def, sim->model->pulley_count, "tight_N", "slack_N", "pull_N");
        fputc('\n', o->parts);
    }
    return 0;
}

/* parts.csv's row: a drive's tension arriving at its wrap and leaving it
 * (its monitor's points, sensors/monitor.c), a takeup's pull: the belt's
 * force on the carriage along its axis, taken positive as it pulls against
 * the takeup */
static void parts_row(bd_outputs *o, bd_sim *sim, double t)
{
    const bd_model_def *def = sim->model->def;
    fprintf(o->parts, "%.6f", t);
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (def->pulleys[i].has_drive) {
            /* read now, as probes are: at t = 0 no step has updated them */
            bd_belt_sample in, out;
            bd_monitor_sides(sim, &sim->pulleys[i].mon, &in, &out);
            fprintf(o->parts, ",%.6g,%.6g", in.tension, out.tension);
        }
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (def->pulleys[i].has_takeup)
            fprintf(o->parts, ",%.6g", -sim->pulleys[i].f_axis);
    fputc('\n', o->parts);
}

void bd_outputs_row(bd_outputs *o, bd_sim *sim, double t)
{
    const bd_model_def *def = sim->model->def;
    FILE *h = o->history;
    fprintf(h, "%.6f", t);
    for (int i = 0; i < sim->model->probe_count; i++) {
        bd_probe *pr = &sim->probes[i];
        bd_probe_read(sim, pr);
        fprintf(h, ",%.6g,%.6g", pr->tension, pr->speed);
    }
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (def->pulleys[i].has_drive)
            fprintf(h, ",%.6g,%.6g", sim->pulleys[i].omega, sim->pulleys[i].drive_torque);
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (def->pulleys[i].has_takeup)
            fprintf(h, ",%.6g", sim->pulleys[i].q);
    const bd_energy *en = &sim->energy;
    double dissipated, input;
    bd_energy_at_t(en, &dissipated, &input);
    fprintf(h, ",%.9g,%.9g,%.9g,%.9g", en->kinetic, en->potential, dissipated, input);
    if (sim->model->belt->topology) {
        bd_belt_topology top;
        sim->model->belt->topology(sim, &top);
        fprintf(h, ",%d", top.dof_now);
    }
    fputc('\n', h);
    if (o->parts)
        parts_row(o, sim, t);

    /* tension along the belt (at its own interval and spacing,
     * model-format.md `tension_interval`, `tension_spacing`), and the
     * Eulerian envelope (every history row, every element) */
    const bd_simulation_def *sd = &def->simulation;
    /* due as history rows are (io/run.c): within half a step */
    double half_step = 0.5 * sim->model->dt;
    int write_field = sd->tension_interval <= 0.0 || t >= o->next_tension - half_step;
    if (write_field && sd->tension_interval > 0.0)
        while (o->next_tension <= t + half_step)
            o->next_tension += sd->tension_interval;
    FILE *f = o->tension;
    double L = sim->model->path.length;
    double *h5s = o->h5 && write_field ? bd_h5_s(o->h5) : NULL;
    double *h5T = h5s ? bd_h5_tension(o->h5) : NULL;
    double *h5v = h5s ? bd_h5_speed(o->h5) : NULL;
    for (int e = 0; e < sim->model->n; e++) {
        double s = bd_element_s(sim, e);
        double T = sim->tension[e];
        if (write_field && (h5s || e % o->field_stride == 0)) {
            int j = e + 1 == sim->model->n ? 0 : e + 1;
            double v = bd_element_speed(sim, e);
            if (e % o->field_stride == 0)
                fprintf(f, "%.6f,%.4f,%.4f,%.4f,%.6g,%.5g\n", t, s, 0.5 * (sim->x[e] + sim->x[j]),
                        0.5 * (sim->y[e] + sim->y[j]), T, v);
            if (h5s) {
                h5s[e] = s;
                h5T[e] = T;
                h5v[e] = v;
            }
        }
        int b = (int)(s / L * o->bins);
        if (b >= o->bins)
            b = o->bins - 1;
        if (b < 0)
            b = 0;
        if (T > o->env_max[b])
            o->env_max[b] = T;
        if (T < o->env_min[b])
            o->env_min[b] = T;
    }
    if (h5s && bd_h5_row(o->h5, t, o->err, sizeof o->err) != 0) {
        /* stop writing it; bd_outputs_close reports the failure */
        bd_h5_close(o->h5);
        o->h5 = NULL;
        o->h5_failed = 1;
    }
    o->rows++;
}

void bd_outputs_flush(bd_outputs *o)
{
    if (o->history)
        fflush(o->history);
    if (o->tension)
        fflush(o->tension);
    if (o->parts)
        fflush(o->parts);
    bd_h5_flush(o->h5);
}

static int write_envelope(bd_outputs *o, const bd_sim *sim)
{
    FILE *f = open_part(o, BD_OUT_ENVELOPE, "envelope.csv", o->err, sizeof o->err);
    if (!f)
        return 1;
    fprintf(f, "s_m,tension_max_N,tension_min_N\n");
    double L = sim->model->path.length;
    for (int b = 0; b < o->bins; b++) {
        /* a bin no element centre fell in takes its nearest filled one */
        int k = b;
        for (int d = 0; d < o->bins && o->env_max[k] == -INFINITY; d++) {
            k = (b + d) % o->bins;
            if (o->env_max[k] != -INFINITY)
                break;
            k = (b - d + o->bins) % o->bins;
        }
        if (o->env_max[k] == -INFINITY)
            continue;
        fprintf(f, "%.4f,%.6g,%.6g\n", (b + 0.5) * L / o->bins, o->env_max[k], o->env_min[k]);
    }
    return finish_part(o, BD_OUT_ENVELOPE, &f);
}

/* summary.json's "checks": the pass/fail table (io/checks.c) */
static void add_checks(cJSON *root, const bd_sim *sim, const bd_static_result *st)
{
    int max = bd_run_checks_max(sim);
    bd_check *checks = malloc((size_t)max * sizeof *checks);
    int n = checks ? bd_run_checks(sim, st, checks, max) : 0, failed = 0;
    cJSON *a = cJSON_AddArrayToObject(root, "checks");
    for (int i = 0; i < n; i++) {
        cJSON *c = cJSON_CreateObject();
        cJSON_AddStringToObject(c, "check", checks[i].name);
        bd_json_add_number(c, "value", checks[i].value);
        bd_json_add_number(c, "limit", checks[i].limit);
        cJSON_AddStringToObject(c, "unit", checks[i].unit);
        cJSON_AddStringToObject(c, "limit_is", bd_check_rule_name(checks[i].rule));
        cJSON_AddBoolToObject(c, "pass", checks[i].pass);
        cJSON_AddItemToArray(a, c);
        failed += !checks[i].pass;
    }
    cJSON_AddNumberToObject(root, "checks_failed", failed);
    free(checks);
}

/* the model's design-standard calculation (cli.md `static --json`) as
 * "static", with its T_min_sag_N also at the top level, and the checks
 * that use it; a warning instead when it cannot be computed */
static int add_static(cJSON *root, cJSON *warnings, const bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    int count = 1;   /* the failure's message, unless it computes */
    bd_diag diag;
    bd_diag_init(&diag);
    bd_static_result res;
    cJSON *st = NULL;
    int computed = bd_static_compute(def, &res, &diag) == 0;
    add_checks(root, sim, computed ? &res : NULL);
    if (computed) {
        char *text = bd_static_to_json(&res, def);
        st = text ? cJSON_Parse(text) : NULL;
        free(text);
        if (st) {
            bd_json_add_number(root, "T_min_sag_N", res.T_min_sag_N);
            count = res.warning_count;
        }
        bd_static_free(&res);
    }
    if (st) {
        cJSON_AddItemToObject(root, "static", st);
    } else {
        char msg[1200];
        snprintf(msg, sizeof msg, "the static design calculation failed%s%s",
                 diag.count > 0 ? ": " : "", diag.count > 0 ? diag.lines[0] : "");
        cJSON_AddItemToArray(warnings, cJSON_CreateString(msg));
    }
    bd_diag_free(&diag);
    return count;
}

void bd_outputs_records_restart(bd_outputs *o, double t)
{
    o->records_from = t;
    for (int i = 0; i < o->bins; i++) {
        o->env_max[i] = -INFINITY;
        o->env_min[i] = INFINITY;
    }
}

static int write_summary(bd_outputs *o, const bd_sim *sim, double wall, const char *status)
{
    const bd_model_def *def = sim->model->def;
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "model", def->name);
    bd_json_add_number(root, "duration_s", sim->t);
    bd_json_add_number(root, "time_step_s", sim->model->dt);
    bd_json_add_number(root, "steps", (double)sim->steps);
    bd_json_add_number(root, "nodes", sim->model->n);
    bd_json_add_number(root, "belt_length_m", sim->model->path.length);
    bd_json_add_number(root, "wall_time_s", wall);
    cJSON_AddStringToObject(root, "status", status);
    if (o->records_from > 0.0)
        bd_json_add_number(root, "records_from_s", o->records_from);
    bd_json_add_number(root, "time_step_limit_s", sim->model->dt_limit);
    cJSON_AddStringToObject(root, "time_step_limited_by",
                            bd_time_step_limit_name(sim->model->limit_kind));
    if (def->belt.rated_tension > 0.0)
        bd_json_add_number(root, "rated_tension_N", def->belt.rated_tension);
    /* design.safety_factor; the run's peak is judged by the starting one */
    bd_json_add_number(root, "safety_factor_running", def->design.safety_factor.running);
    bd_json_add_number(root, "safety_factor_starting", def->design.safety_factor.starting);
    if (def->belt.rated_tension > 0.0 && sim->tension_max > 0.0)
        bd_json_add_number(root, "peak_safety_factor", def->belt.rated_tension / sim->tension_max);
    cJSON *ten = cJSON_AddObjectToObject(root, "tension");
    bd_json_add_number(ten, "max_N", sim->tension_max);
    bd_json_add_number(ten, "max_time_s", sim->tension_max_t);
    bd_json_add_number(ten, "max_s_m", sim->tension_max_s);
    bd_json_add_number(ten, "min_N", sim->tension_min);
    bd_json_add_number(ten, "min_time_s", sim->tension_min_t);
    bd_json_add_number(ten, "min_s_m", sim->tension_min_s);
    /* the belt off its idlers: where, when, how long (sensors/lift_off.c) */
    const bd_lift_off *lift = &sim->lift;
    cJSON *lo = cJSON_AddObjectToObject(root, "lift_off");
    /* the axial belt has no idler contact to lose: not checked */
    cJSON_AddBoolToObject(lo, "checked", sim->model->belt->records_lift_off);
    if (sim->model->belt->records_lift_off)
        cJSON_AddBoolToObject(lo, "occurred", lift->first_t >= 0.0);
    if (lift->first_t >= 0.0) {
        bd_json_add_number(lo, "first_time_s", lift->first_t);
        bd_json_add_number(lo, "first_s_m", lift->first_s);
        bd_json_add_number(lo, "from_s_m", lift->s_min);
        bd_json_add_number(lo, "to_s_m", lift->s_max);
        bd_json_add_number(lo, "total_s", lift->total);
        bd_json_add_number(lo, "longest_s", lift->longest);
        cJSON_AddNumberToObject(lo, "max_stations", lift->max_stations);
    }
    cJSON *probes = cJSON_AddObjectToObject(root, "probes");
    for (int i = 0; i < sim->model->probe_count; i++) {
        const bd_probe *pr = &sim->probes[i];
        cJSON *p = cJSON_AddObjectToObject(probes, def->simulation.probes[i].name);
        bd_json_add_number(p, "tension_max_N", pr->tension_max);
        bd_json_add_number(p, "tension_min_N", pr->tension_min);
        bd_json_add_number(p, "tension_final_N", pr->tension);
        bd_json_add_number(p, "speed_final_mps", pr->speed);
    }
    cJSON *pulleys = cJSON_AddObjectToObject(root, "pulleys");
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *pb = &sim->pulleys[i];
        cJSON *p = cJSON_AddObjectToObject(pulleys, def->pulleys[i].name);
        bd_json_add_number(p, "omega_final_rad_s", pb->omega);
        if (def->pulleys[i].has_drive) {
            const bd_drive_monitor *m = &pb->mon;
            bd_json_add_number(p, "radius_m", def->pulleys[i].radius);
            bd_json_add_number(p, "torque_max_Nm", pb->torque_max_abs);
            bd_json_add_number(p, "tight_tension_max_N", m->tight_max);
            bd_json_add_number(p, "tight_tension_max_time_s", m->tight_max_t);
            bd_json_add_number(p, "slack_tension_min_N", m->slack_min);
            bd_json_add_number(p, "tight_tension_swing_N", bd_monitor_swing(m));
            bd_json_add_number(p, "belt_accel_max_mps2", m->accel_max);
            bd_json_add_number(p, "slip_longest_s", m->slip_longest);
            cJSON_AddBoolToObject(p, "slipped", m->slip_first_t >= 0.0);
            bd_json_add_number(p, "friction_used_max_pct", 100.0 * m->friction_used_max);
            bd_json_add_number(p, "friction_used_max_time_s", m->friction_used_max_t);
        }
        const bd_part *dp = bd_pulley_drive_part(sim, pb);
        if (dp && dp->type == BD_PART_TRANSMISSION) {
            double w_m, slip_m, slip_p;
            bd_transmission_state(dp, pb, &w_m, &slip_m, &slip_p);
            bd_json_add_number(p, "motor_sheave_omega_final_rad_s", w_m);
            bd_json_add_number(p, "transmission_slip_max_mps", bd_transmission_slip_max(dp));
        }
        if (def->pulleys[i].has_takeup) {
            bd_json_add_number(p, "travel_min_m", pb->travel_min);
            bd_json_add_number(p, "travel_max_m", pb->travel_max);
        }
    }
    cJSON *en = cJSON_AddObjectToObject(root, "energy");
    bd_json_add_number(en, "kinetic_final_J", sim->energy.kinetic);
    bd_json_add_number(en, "balance_error_rel", sim->energy.balance_error_rel);
    bd_json_add_number(en, "dissipation_fall_rel", sim->energy.dissipation_fall_rel);
    /* long sections (belt.h bd_belt_topology) */
    if (sim->model->belt->topology) {
        bd_belt_topology top;
        sim->model->belt->topology(sim, &top);
        cJSON *vt = cJSON_AddObjectToObject(root, "variable_topology");
        cJSON_AddBoolToObject(vt, "enabled", def->belt.group_sections);
        cJSON_AddNumberToObject(vt, "windows", top.windows);
        bd_json_add_number(vt, "window_length_m", top.window_length);
        cJSON_AddNumberToObject(vt, "belt_dof_min", top.dof_min);
        cJSON_AddNumberToObject(vt, "belt_dof_max", top.dof_max);
        cJSON_AddNumberToObject(vt, "belt_dof_final", top.dof_now);
        cJSON_AddNumberToObject(vt, "elements_joined", (double)top.joined);
        cJSON_AddNumberToObject(vt, "elements_left", (double)top.left);
        bd_json_add_number(vt, "energy_booked_dissipated_J", top.lost_J);
        bd_json_add_number(vt, "energy_booked_input_J", top.gained_J);
        bd_json_add_number(vt, "end_kink_share", top.kink_share);
        cJSON_AddNumberToObject(vt, "spans_left_free", top.kink_free_spans);
    }
    /* steady running against the model's own law (sensors/running.c) */
    bd_running_check rc;
    bd_sim_running_check(sim, &rc);
    cJSON *rf = cJSON_AddObjectToObject(root, "running_force");
    cJSON_AddBoolToObject(rf, "checked", rc.checked);
    if (rc.checked) {
        cJSON_AddBoolToObject(rf, "pass", rc.pass);
        bd_json_add_number(rf, "from_s", rc.from_s);
        bd_json_add_number(rf, "to_s", rc.to_s);
        bd_json_add_number(rf, "speed_mps", rc.speed_mps);
        bd_json_add_number(rf, "force_N", rc.force_N);
        bd_json_add_number(rf, "law_N", rc.law_N);
        bd_json_add_number(rf, "law_scale_N", rc.scale_N);
        bd_json_add_number(rf, "error_rel", rc.error_rel);
        bd_json_add_number(rf, "tolerance_rel", rc.tolerance_rel);
    } else {
        cJSON_AddStringToObject(rf, "why", rc.why);
    }
    if (def->simulation.stabilize) {
        cJSON *st = cJSON_AddObjectToObject(root, "stabilize");
        bd_json_add_number(st, "steps", (double)sim->stabilize_iterations);
        bd_json_add_number(st, "resets", sim->stabilize_resets);
        cJSON_AddBoolToObject(st, "converged", sim->stabilize_converged);
        bd_json_add_number(st, "kinetic_final_J", sim->stabilize_final_kinetic);
    }
    if (sim->settle_steps > 0) {
        /* the rfe belt let go where the layout lays it (sim/stabilize.c) */
        cJSON *st = cJSON_AddObjectToObject(root, "settle");
        bd_json_add_number(st, "steps", (double)sim->settle_steps);
        bd_json_add_number(st, "resets", sim->settle_resets);
        bd_json_add_number(st, "released_J", sim->settle_released);
    }
    bd_layout_to_json(root, sim);
    cJSON *w = cJSON_AddArrayToObject(root, "warnings");
    for (int i = 0; i < sim->warning_count; i++)
        cJSON_AddItemToArray(w, cJSON_CreateString(sim->warnings[i]));
    if (def->design.present)
        o->static_warnings = add_static(root, w, sim);
    else
        add_checks(root, sim, NULL);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    FILE *f = open_part(o, BD_OUT_SUMMARY, "summary.json", o->err, sizeof o->err);
    if (!f) {
        free(text);
        return 1;
    }
    fputs(text, f);
    fputc('\n', f);
    free(text);
    return finish_part(o, BD_OUT_SUMMARY, &f);
}

int bd_outputs_close(bd_outputs *o, const bd_sim *sim, double wall, const char *status)
{
    int bad = finish_part(o, BD_OUT_HISTORY, &o->history);
    bad |= finish_part(o, BD_OUT_TENSION, &o->tension);
    bad |= finish_part(o, BD_OUT_PARTS, &o->parts);
    free(o->history_buf);
    free(o->tension_buf);
    o->history_buf = o->tension_buf = NULL;
    if (o->h5) {
        int h5bad = bd_h5_close(o->h5);
        o->h5 = NULL;
        if (!h5bad)
            h5bad = rename(o->part_path[BD_OUT_HDF5], o->final_path[BD_OUT_HDF5]) != 0;
        bad |= h5bad;
    }
    if (o->h5_failed) {
        remove(o->part_path[BD_OUT_HDF5]);
        bad = 1;
    }
    if (o->rows > 0)
        bad |= write_envelope(o, sim);
    bad |= write_summary(o, sim, wall, status);
    free(o->env_max);
    free(o->env_min);
    o->env_max = o->env_min = NULL;
    return bad;
}

/* ---- the run's directory (cli.md) ---- */

/* the files a run writes: a directory holding one holds a run */
static const char *const run_files[] = {"summary.json", "history.csv", "tension.csv",
                                        "envelope.csv"};

/* dir/name removed, never a name cut short */
static void remove_in(const char *dir, const char *name)
{
    char path[2048];
    if (bd_path_join(path, sizeof path, dir, name) == 0)
        remove(path);
}

int bd_run_dir_prepare(const char *dir, int force, char *err, size_t errlen)
{
    err[0] = '\0';
    int state = bd_dir_state(dir, run_files, (int)(sizeof run_files / sizeof run_files[0]));
    if (state == BD_DIR_BAD) {
        snprintf(err, errlen, "'%s' is not a directory that can be read", dir);
        return BD_RUN_BAD_INPUT;
    }
    if (state == BD_DIR_OTHER && !force) {
        snprintf(err, errlen, "'%s' is not empty and holds no run (no summary.json, history.csv, "
                 "tension.csv or envelope.csv): give another -o DIR, or --force to write into it",
                 dir);
        return BD_RUN_BAD_INPUT;
    }
    if (state != BD_DIR_MARKED)
        return BD_RUN_OK;   /* with --force a foreign DIR keeps its files */
    remove_in(dir, "report.html");
    remove_in(dir, "tension.h5");
    remove_in(dir, "parts.csv");
    char plots[2048];
    DIR *d = bd_path_join(plots, sizeof plots, dir, "plots") == 0 ? opendir(plots) : NULL;
    if (!d)
        return BD_RUN_OK;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len > 4 && (strcmp(e->d_name + len - 4, ".png") == 0
                        || strcmp(e->d_name + len - 4, ".svg") == 0))
            remove_in(plots, e->d_name);
    }
    closedir(d);
    rmdir(plots);   /* only if nothing else is in it */
    return BD_RUN_OK;
}
