/* The boom's run (boom-format.md "Outputs of run"): settle under gravity
 * with time held at 0, then the step loop, writing history.csv and
 * beams.csv row by row and summary.json at the end. Files are written
 * under temporary names and renamed when complete; a failed or
 * interrupted run still renames its CSVs, valid up to their last row. */
#include "boom/boom_internal.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/clock.h"
#include "base/json_util.h"
#include "io/outputs.h"

enum { F_HISTORY = 0, F_BEAMS, F_SUMMARY, F_COUNT };
static const char *const file_names[F_COUNT] = {"history.csv", "beams.csv", "summary.json"};

typedef struct boom_out {
    char final[F_COUNT][1100];
    char part[F_COUNT][1100];
    FILE *f[F_COUNT];
} boom_out;

static int out_open(boom_out *o, const char *dir, int which, char *err, size_t errlen)
{
    snprintf(o->final[which], sizeof o->final[which], "%s/%s", dir, file_names[which]);
    snprintf(o->part[which], sizeof o->part[which], "%s/.%s.part", dir, file_names[which]);
    o->f[which] = fopen(o->part[which], "w");
    if (!o->f[which]) {
        snprintf(err, errlen, "cannot write '%s': %s", o->part[which], strerror(errno));
        return 1;
    }
    return 0;
}

static int out_finish(boom_out *o, int which)
{
    if (!o->f[which])
        return 0;
    int bad = fclose(o->f[which]) != 0;
    o->f[which] = NULL;
    return bad || rename(o->part[which], o->final[which]) != 0;
}

static void history_header(const bd_boom *b, FILE *f)
{
    fprintf(f, "t_s,stroke_m,tip.x_m,tip.y_m,tip.vx_mps,tip.vy_mps,tip.ax_mps2,tip.ay_mps2,"
            "telescopic_cylinder_N,luffing_N");
    for (int k = 1; k < b->ns; k++)
        fprintf(f, ",pad%d.inner_normal_N,pad%d.outer_normal_N,pad%d.friction_N", k, k, k);
    fprintf(f, ",kinetic_J,potential_J,dissipated_J,input_J");
    /* added columns: the rigid boom's tip, the distance from it, ropes */
    fprintf(f, ",tip_rigid.x_m,tip_rigid.y_m,tip.deflection_m");
    for (int j = 1; j + 1 < b->ns; j++)
        fprintf(f, ",rope%d.extend_N,rope%d.retract_N", j + 1, j + 1);
    fprintf(f, "\n");
}

static void history_row(const bd_boom *b, FILE *f, double ax, double ay)
{
    double x, y, vx, vy, rx, ry;
    boom_tip(b, &x, &y, &vx, &vy);
    boom_tip_rigid(b, &rx, &ry);
    fprintf(f, "%.6g,%.9g,%.9g,%.9g,%.6g,%.6g,%.6g,%.6g,%.7g,%.7g", b->t, b->stroke_ref, x, y, vx,
            vy, ax, ay, b->cyl_force, b->luff_force);
    for (int k = 1; k < b->ns; k++) {
        const boom_contact *ci = &b->c[2 * (k - 1)], *co = &b->c[2 * (k - 1) + 1];
        fprintf(f, ",%.7g,%.7g,%.7g", ci->normal, co->normal, ci->friction + co->friction);
    }
    fprintf(f, ",%.9g,%.9g,%.9g,%.9g", b->pend_kin, b->e_pot, b->e_diss, b->e_in);
    fprintf(f, ",%.9g,%.9g,%.6g", rx, ry, hypot(x - rx, y - ry));
    for (int j = 1; j + 1 < b->ns; j++)
        fprintf(f, ",%.7g,%.7g", b->rope_ext[j], b->rope_ret[j]);
    fprintf(f, "\n");
}

/* one row per node: the section's forces there (the mean of the two
 * elements that meet at an inner node) */
static void beams_rows(const bd_boom *b, FILE *f)
{
    for (int k = 0; k < b->ns; k++) {
        const boom_section *S = &b->sec[k];
        int last = S->first + S->n - 1;
        for (int i = S->first; i <= last; i++) {
            double N = 0.0, V = 0.0, M = 0.0;
            int n = 0;
            if (i > S->first) {
                N += b->eN[i - 1];
                V += b->eV[i - 1];
                M += b->eMb[i - 1];
                n++;
            }
            if (i < last) {
                N += b->eN[i];
                V += b->eV[i];
                M -= b->eMa[i];
                n++;
            }
            fprintf(f, "%.6g,%d,%.6g,%.9g,%.9g,%.7g,%.7g,%.7g\n", b->t, k + 1, b->s[i], b->x[i],
                    b->y[i], N / n, V / n, M / n);
        }
    }
}

static void record(bd_boom *b)
{
    double x, y, vx, vy, rx, ry;
    boom_tip(b, &x, &y, &vx, &vy);
    boom_tip_rigid(b, &rx, &ry);
    bd_boom_result *r = &b->res;
    if (b->steps_run == 0 || x > r->tip_x_max_m)
        r->tip_x_max_m = x;
    if (b->steps_run == 0 || y > r->tip_y_max_m)
        r->tip_y_max_m = y;
    r->tip_deflection_max_m = fmax(r->tip_deflection_max_m, hypot(x - rx, y - ry));
    r->telescopic_cylinder_force_max_N = fmax(r->telescopic_cylinder_force_max_N,
                                              fabs(b->cyl_force));
    r->luffing_force_max_N = fmax(r->luffing_force_max_N, fabs(b->luff_force));
    for (int j = 0; j < b->nc; j++)
        r->pad_normal_force_max_N = fmax(r->pad_normal_force_max_N, b->c[j].normal);
}

static int write_summary(const bd_boom *b, boom_out *o, const char *dir, double wall,
                         const char *status, const char *warning, double duration)
{
    char why[1200];
    if (out_open(o, dir, F_SUMMARY, why, sizeof why))
        return 1;
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "model", b->def.name);
    cJSON_AddStringToObject(root, "kind", "boom");
    bd_json_add_number(root, "duration_s", duration);
    bd_json_add_number(root, "time_step_s", b->dt);
    bd_json_add_number(root, "steps", (double)b->steps_run);
    bd_json_add_number(root, "settle_steps", (double)b->settle_steps);
    bd_json_add_number(root, "nodes", b->N);
    bd_json_add_number(root, "wall_time_s", wall);
    cJSON_AddStringToObject(root, "status", status);
    cJSON *w = cJSON_AddArrayToObject(root, "warnings");
    if (warning && warning[0])
        cJSON_AddItemToArray(w, cJSON_CreateString(warning));
    cJSON *en = cJSON_AddObjectToObject(root, "energy");
    bd_json_add_number(en, "kinetic_final_J", b->e_kin);
    bd_json_add_number(en, "balance_error_rel", b->balance_rel);
    bd_json_add_number(en, "dissipated_J", b->e_diss);
    bd_json_add_number(en, "input_J", b->e_in);
    cJSON *bm = cJSON_AddObjectToObject(root, "boom");
    const bd_boom_result *r = &b->res;
    bd_json_add_number(bm, "tip_x_max_m", r->tip_x_max_m);
    bd_json_add_number(bm, "tip_y_max_m", r->tip_y_max_m);
    bd_json_add_number(bm, "tip_deflection_max_m", r->tip_deflection_max_m);
    bd_json_add_number(bm, "telescopic_cylinder_force_max_N", r->telescopic_cylinder_force_max_N);
    bd_json_add_number(bm, "luffing_force_max_N", r->luffing_force_max_N);
    bd_json_add_number(bm, "pad_normal_force_max_N", r->pad_normal_force_max_N);
    bd_json_add_number(bm, "first_bending_hz_estimate", b->f1_hz);
    cJSON_AddStringToObject(bm, "luffing_unit", b->def.luffing_cylinder.present ? "N" : "N*m");
    cJSON_AddNumberToObject(bm, "sections", b->ns);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    int bad = !text || fprintf(o->f[F_SUMMARY], "%s\n", text) < 0;
    free(text);
    return out_finish(o, F_SUMMARY) || bad;
}

int bd_boom_run(bd_boom *b, const bd_run_options *opt, char *err, size_t errlen)
{
    const bd_boom_def *d = &b->def;
    double wall0 = bd_wall_seconds();
    double duration = d->simulation.duration > 0.0 ? d->simulation.duration
                                                   : bd_boom_stroke_end(&d->stroke) + 2.0;
    const char *dir = opt ? opt->out_dir : NULL;
    boom_out o;
    memset(&o, 0, sizeof o);
    err[0] = '\0';
    if (dir && bd_outputs_make_dir(dir, err, errlen))
        return BD_RUN_FAILED;
    if (dir && (out_open(&o, dir, F_HISTORY, err, errlen) || out_open(&o, dir, F_BEAMS, err,
                                                                         errlen))) {
        for (int k = 0; k < F_COUNT; k++)
            if (o.f[k]) {
                fclose(o.f[k]);
                remove(o.part[k]);
            }
        return BD_RUN_FAILED;
    }
    char warning[512] = "";
    int rc = BD_RUN_OK;
    long max_settle = opt && opt->stabilize_max_steps > 0 ? opt->stabilize_max_steps : 2000000;
    int s = boom_settle(b, max_settle, opt ? opt->interrupted : NULL, err, errlen);
    if (s == 1) {
        snprintf(warning, sizeof warning, "%s", err);
        if (opt && opt->message)
            opt->message(warning, opt->message_ctx);
        err[0] = '\0';
    } else if (s == -1) {
        rc = BD_RUN_FAILED;
    } else if (s == 2) {
        rc = BD_RUN_INTERRUPTED;
        snprintf(err, errlen, "interrupted while settling");
    }
    if (dir) {
        history_header(b, o.f[F_HISTORY]);
        fprintf(o.f[F_BEAMS], "t_s,section,s_m,x_m,y_m,axial_N,shear_N,moment_Nm\n");
    }
    b->t = 0.0;
    b->e_diss = b->e_in = b->e_0 = b->balance_rel = b->e_norm = 0.0;
    b->steps_run = 0;
    double interval = d->simulation.output_interval > 0.0 ? d->simulation.output_interval : 0.01;
    long next_row = 0;
    double last_progress = wall0;
    double ax = 0.0, ay = 0.0;
    while (rc == BD_RUN_OK) {
        boom_evaluate(b);
        record(b);
        if (b->t >= (double)next_row * interval - 0.5 * b->dt) {
            if (dir) {
                history_row(b, o.f[F_HISTORY], ax, ay);
                beams_rows(b, o.f[F_BEAMS]);
            }
            next_row++;
        }
        if (b->t >= duration - 0.5 * b->dt)
            break;
        if (opt && opt->interrupted && *opt->interrupted) {
            rc = BD_RUN_INTERRUPTED;
            snprintf(err, errlen, "interrupted at t = %.3f s", b->t);
            break;
        }
        int i_tip = b->N - 1;
        double tvx = b->vx[i_tip], tvy = b->vy[i_tip];
        if (boom_advance(b, 0, err, errlen)) {
            rc = BD_RUN_FAILED;
            break;
        }
        b->steps_run++;
        /* the tip's acceleration over this step (the next row's) */
        ax = (b->vx[i_tip] - tvx) / b->dt;
        ay = (b->vy[i_tip] - tvy) / b->dt;
        if (opt && opt->progress && (b->steps_run & 1023) == 0) {
            double now = bd_wall_seconds();
            if (now - last_progress > 0.25) {
                bd_run_progress p = {b->t, duration, now - wall0, 0, 0};
                opt->progress(&p, opt->progress_ctx);
                last_progress = now;
            }
        }
    }
    double wall = bd_wall_seconds() - wall0;
    if (opt && opt->progress) {
        bd_run_progress p = {b->t, duration, wall, 1, 0};
        opt->progress(&p, opt->progress_ctx);
    }
    if (dir) {
        int bad = out_finish(&o, F_HISTORY) | out_finish(&o, F_BEAMS);
        const char *status = rc == BD_RUN_OK ? "completed"
                           : rc == BD_RUN_INTERRUPTED ? "interrupted" : "failed";
        bad |= write_summary(b, &o, dir, wall, status, rc == BD_RUN_FAILED ? err : warning,
                             duration);
        if (bad && rc == BD_RUN_OK) {
            snprintf(err, errlen, "cannot write the outputs in '%s'", dir);
            rc = BD_RUN_FAILED;
        }
    }
    return rc;
}
