/* The mesh check (beltdyn/sim.h bd_mesh_check; `beltdyn run --mesh-check`):
 * does the answer depend on the element length? The run is repeated on
 * elements half as long and the figures an engineer reads first are
 * compared: the peak belt tension, each drive's peak tight-side and
 * lowest slack-side tension and peak torque, the takeups' travel, and the
 * steady running force when both runs held it to the law
 * (sensors/running.c). Issue 10 asks that running force and peak
 * tight-side tension change by less than 2 % when the element halves;
 * every figure here is held to that. A lumped belt without bending
 * stiffness turned sharply over idlers at speed does not converge
 * (docs/physics.md §10); a peak carried by one node's landing need not
 * either: the check says which, with both values. */
#include "io/outputs.h"
#include "sim/engine.h"

#include <cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/constants.h"
#include "base/file.h"
#include "base/json_util.h"
#include "io/html.h"

#define MESH_TOLERANCE 0.02

void bd_mesh_refine(const bd_sim *coarse, bd_model_def *def, bd_mesh_check *mc)
{
    memset(mc, 0, sizeof *mc);
    mc->tolerance_rel = MESH_TOLERANCE;
    bd_belt_def *b = &def->belt;
    if (b->formulation == BD_FORMULATION_MOVING_NODE) {
        /* arcs: half the angle; spans: half the given length, or half the
         * shortest default (each span's idler spacing, 1 m without), so
         * that every span is at least halved */
        double arc = 0.5 * b->wrap_element_angle, span = b->span_element_length;
        if (!(span > 0.0)) {
            span = 1.0;
            for (int k = 0; k < def->idler_set_count; k++)
                if (def->idler_sets[k].spacing > 0.0)
                    span = fmin(span, def->idler_sets[k].spacing);
        }
        snprintf(mc->mesh, sizeof mc->mesh,
                 "wrap elements of %.3g° and span elements of %.4g m at most, against %.3g° "
                 "and %s", arc * 180.0 / BD_PI, 0.5 * span,
                 b->wrap_element_angle * 180.0 / BD_PI,
                 b->span_element_length > 0.0 ? "the given span elements"
                                              : "the idler spacing");
        b->wrap_element_angle = arc;
        b->span_element_length = 0.5 * span;
    } else {
        /* the element the run was built with (a default halved over
         * sharply turning idlers included), halved */
        double l0 = coarse->model->l0;
        snprintf(mc->mesh, sizeof mc->mesh, "elements of %.4g m against %.4g m", 0.5 * l0, l0);
        b->element_length = 0.5 * l0;
    }
    /* the finer run's tension field is not kept: its first and last rows */
    def->simulation.tension_interval = fmax(def->simulation.duration, def->simulation.output_interval);
}

/* a figure of both runs; its change over |coarse|, or over `scale` where
 * that is larger (a slack side near 0 N is judged against the tensions
 * in play, not against itself) */
static void quantity(bd_mesh_check *mc, const char *name, const char *unit, double coarse,
                     double fine, double scale)
{
    if (mc->count >= BD_MESH_QUANTITIES || !isfinite(coarse) || !isfinite(fine))
        return;
    bd_mesh_quantity *q = &mc->q[mc->count++];
    snprintf(q->name, sizeof q->name, "%s", name);
    snprintf(q->unit, sizeof q->unit, "%s", unit);
    q->coarse = coarse;
    q->fine = fine;
    q->change_rel = (fine - coarse) / fmax(fmax(fabs(coarse), scale), 1e-12);
    q->pass = fabs(q->change_rel) <= mc->tolerance_rel;
}

void bd_mesh_compare(const bd_sim *coarse, const bd_sim *fine, bd_mesh_check *mc)
{
    mc->count = 0;
    bd_run_result a, b;
    bd_sim_result(coarse, &a);
    bd_sim_result(fine, &b);
    /* tensions against a tenth of the peak at least */
    const double ts = 0.1 * fabs(a.tension_max_N);
    quantity(mc, "peak belt tension", "N", a.tension_max_N, b.tension_max_N, 0.0);
    if (a.drives > 0 && b.drives > 0) {
        quantity(mc, "peak tight-side tension", "N", a.tight_max_N, b.tight_max_N, ts);
        quantity(mc, "lowest slack-side tension", "N", a.slack_min_N, b.slack_min_N, ts);
        quantity(mc, "peak drive torque", "N·m", a.torque_max_Nm, b.torque_max_Nm, 0.0);
    }
    if (a.travel_range_m > 0.0)
        quantity(mc, "takeup travel range", "m", a.travel_range_m, b.travel_range_m, 0.0);
    /* the running force where both runs judged it, else why not */
    bd_running_check ra, rb;
    bd_sim_running_check(coarse, &ra);
    bd_sim_running_check(fine, &rb);
    mc->running_force_why[0] = '\0';
    if (ra.checked && rb.checked)
        quantity(mc, "steady running force", "N", ra.force_N, rb.force_N, 0.0);
    else
        snprintf(mc->running_force_why, sizeof mc->running_force_why, "%s run: %s",
                 ra.checked ? "the finer" : "the", ra.checked ? rb.why : ra.why);
    mc->converged = 1;
    for (int i = 0; i < mc->count; i++)
        mc->converged &= mc->q[i].pass;
}

int bd_mesh_check_write(const char *dir, const bd_mesh_check *mc, char *err, size_t errlen)
{
    char path[2048];
    if (bd_path_join(path, sizeof path, dir, "summary.json")) {
        snprintf(err, errlen, "'%s': path too long", dir);
        return 1;
    }
    char *text = NULL;
    size_t len = 0;
    if (bd_read_file(path, &text, &len) != BD_READ_OK) {
        snprintf(err, errlen, "cannot read '%s'", path);
        return 1;
    }
    cJSON *root = cJSON_ParseWithLength(text, len);
    free(text);
    if (!root) {
        snprintf(err, errlen, "'%s' is not JSON", path);
        return 1;
    }
    cJSON *m = cJSON_AddObjectToObject(root, "mesh_check");
    cJSON_AddStringToObject(m, "mesh", mc->mesh);
    bd_json_add_number(m, "tolerance_rel", mc->tolerance_rel);
    cJSON_AddBoolToObject(m, "converged", mc->converged);
    if (mc->running_force_why[0])
        cJSON_AddStringToObject(m, "running_force_not_compared", mc->running_force_why);
    bd_json_add_number(m, "fine_wall_time_s", mc->fine_wall_s);
    cJSON *qs = cJSON_AddArrayToObject(m, "quantities");
    char off[1024] = "";
    size_t used = 0;
    for (int i = 0; i < mc->count; i++) {
        const bd_mesh_quantity *q = &mc->q[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", q->name);
        cJSON_AddStringToObject(o, "unit", q->unit);
        bd_json_add_number(o, "value", q->coarse);
        bd_json_add_number(o, "fine_value", q->fine);
        bd_json_add_number(o, "change_rel", q->change_rel);
        cJSON_AddBoolToObject(o, "pass", q->pass);
        cJSON_AddItemToArray(qs, o);
        if (!q->pass && used < sizeof off) {
            int k = snprintf(off + used, sizeof off - used, "%s%s %+.1f %% (%.5g to %.5g %s)",
                             used ? ", " : "", q->name, 100.0 * q->change_rel, q->coarse,
                             q->fine, q->unit);
            used += k > 0 ? (size_t)k : 0;
        }
    }
    if (!mc->converged) {
        cJSON *w = cJSON_GetObjectItemCaseSensitive(root, "warnings");
        char line[1400];
        snprintf(line, sizeof line,
                 "mesh check: on %s the results moved by more than %.0f %%: %s. They are not "
                 "converged with the mesh: read them with that error, or run on the finer "
                 "mesh (docs/model-format.md, \"The mesh check\")",
                 mc->mesh, 100.0 * mc->tolerance_rel, off);
        if (cJSON_IsArray(w))
            cJSON_AddItemToArray(w, cJSON_CreateString(line));
    }
    /* written whole by a temporary name (io/html.c bd_html_write) */
    char *out = cJSON_Print(root);
    cJSON_Delete(root);
    if (!out) {
        snprintf(err, errlen, "%s: out of memory", path);
        return 1;
    }
    bd_strbuf b = {0};
    bd_sb_puts(&b, out);
    bd_sb_puts(&b, "\n");
    free(out);
    return bd_html_write(&b, path, err, errlen) != 0;
}
