/* Building a simulation from a validated model: discretize the belt, place
 * the idlers, set up the pulley bodies, probes and feed point, choose the
 * time step. Everything allocated here; the step loop allocates nothing. */
#include "sim/system.h"
#include "sim/layout.h"
#include "sim/timestep.h"
#include "base/constants.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


void bd_sim_warn(bd_sim *sim, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    for (int i = 0; i < sim->warning_count; i++)
        if (strcmp(sim->warnings[i], buf) == 0)
            return;
    char **w = realloc(sim->warnings, (size_t)(sim->warning_count + 1) * sizeof *w);
    if (!w)
        return;
    sim->warnings = w;
    sim->warnings[sim->warning_count] = malloc(strlen(buf) + 1);
    if (sim->warnings[sim->warning_count]) {
        strcpy(sim->warnings[sim->warning_count], buf);
        sim->warning_count++;
    }
}

/* default target element length: chord of a 30° arc of the smallest pulley
 * (seed 001 §4.3.1, §6.1) */
static double default_element_length(const bd_model_def *def)
{
    double r = INFINITY;
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].radius < r)
            r = def->pulleys[i].radius;
    return 2.0 * r * sin(BD_PI / 12.0);
}

void *bd_xcalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p) {
        fprintf(stderr, "beltdyn: out of memory\n");
        exit(BD_RUN_FAILED);
    }
    return p;
}

/* what every formulation's pulley body takes from its definition */
void bd_pulley_body_init(bd_sim *sim, bd_pulley_body *p, const bd_pulley_def *pd)
{
    p->def = pd;
    p->radius = pd->radius;
    p->wrap = pd->wrap;
    p->mu_s = pd->friction.mu_static;
    p->mu_d = pd->friction.mu_dynamic;
    p->bearing_damping = pd->bearing_damping;
    p->inertia = pd->inertia + (pd->has_drive ? pd->drive.inertia : 0.0);
    /* a massless pulley would have an undefined speed when the belt
     * slips on it everywhere: floor its inertia at 1% of the inertia of
     * the belt wrapped on it (documented in docs/physics.md) */
    double floor_inertia = 0.01 * sim->belt_mpl * BD_PI * pd->radius * pd->radius * pd->radius;
    if (p->inertia < floor_inertia)
        p->inertia = floor_inertia;
    p->cx = pd->x;
    p->cy = pd->y;
    if (pd->has_takeup) {
        p->axis[0] = pd->takeup.axis[0];
        p->axis[1] = pd->takeup.axis[1];
        p->movable = pd->takeup.type != BD_TAKEUP_FIXED;
        p->carriage_mass = pd->mass + pd->takeup.mass;
        if (p->movable && p->carriage_mass <= 0.0)
            p->carriage_mass = 1e-3 * sim->belt_mpl * pd->radius;
        p->force_prev = bd_table_eval(&pd->takeup.force, 0.0);
    }
}

static void setup_pulleys(bd_sim *sim, const bd_layout *lay)
{
    const bd_model_def *def = sim->def;
    sim->pulley_count = def->pulley_count;
    sim->pulleys = bd_xcalloc((size_t)def->pulley_count, sizeof *sim->pulleys);
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *pd = &def->pulleys[i];
        bd_pulley_body *p = &sim->pulleys[i];
        bd_pulley_body_init(sim, p, pd);
        if (i == lay->takeup) {
            p->cx += lay->takeup_shift * p->axis[0];
            p->cy += lay->takeup_shift * p->axis[1];
        }
        /* contact: stiff and linearly implicit (pulley_contact.c) */
        p->k_contact = 100.0 * sim->k_axial;
        double wrap = bd_path_wrap_angle(&sim->path, i);
        p->win_max = (int)ceil((wrap + 0.5) * pd->radius / sim->l0) + 16;
        p->c_node = bd_xcalloc((size_t)p->win_max, sizeof *p->c_node);
        p->c_normal = bd_xcalloc((size_t)p->win_max, sizeof *p->c_normal);
        p->c_tx = bd_xcalloc((size_t)p->win_max, sizeof *p->c_tx);
        p->c_ty = bd_xcalloc((size_t)p->win_max, sizeof *p->c_ty);
        p->c_f = bd_xcalloc((size_t)p->win_max, sizeof *p->c_f);
        p->c_slip = bd_xcalloc((size_t)p->win_max, sizeof *p->c_slip);
        /* window: nodes lying on its arc */
        const bd_path_segment *arc = bd_path_arc(&sim->path, i);
        int first = -1, count = 0;
        for (int k = 0; k < sim->n; k++) {
            double rel = sim->s_node0[k] - arc->s0;
            if (rel >= -1e-9 * sim->path.length && rel <= arc->length + 1e-9) {
                if (first < 0)
                    first = k;
                count++;
            }
        }
        p->win_first = first < 0 ? 0 : first;
        p->win_count = count;
    }
}

int bd_idler_set_layout(bd_sim *sim, int k, double *spacing)
{
    const bd_model_def *def = sim->def;
    const bd_idler_set_def *set = &def->idler_sets[k];
    const bd_path_segment *sp = bd_path_span(&sim->path, set->span);
    sim->idlers_per_set[k] = 0;
    *spacing = set->spacing;
    if (fabs(sp->dir[0]) < 1e-6) {
        bd_sim_warn(sim, "idlers on span '%s': the span is vertical; no idlers placed",
                    def->pulleys[set->span].name);
        return 0;
    }
    /* the closest spacing to the given one that fits the span evenly
     * (documented in docs/model-format.md) */
    int count = (int)lround(sp->length / set->spacing) - 1;
    if (count < 0)
        count = 0;
    sim->idlers_per_set[k] = count;
    *spacing = sp->length / (count + 1);
    return count;
}

static void setup_idlers(bd_sim *sim)
{
    const bd_model_def *def = sim->def;
    int total = 0;
    sim->idlers_per_set = bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->idlers_per_set);
    sim->idler_spacing = bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->idler_spacing);
    for (int k = 0; k < def->idler_set_count; k++)
        total += bd_idler_set_layout(sim, k, &sim->idler_spacing[k]);
    sim->idler_count = total;
    sim->idlers = bd_xcalloc((size_t)total, sizeof *sim->idlers);
    int at = 0;
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_idler_set_def *set = &def->idler_sets[k];
        const bd_path_segment *sp = bd_path_span(&sim->path, set->span);
        /* the lower side of the belt: the normal pointing down */
        double nx = sp->dir[1], ny = -sp->dir[0];
        if (ny > 0.0) {
            nx = -nx;
            ny = -ny;
        }
        for (int j = 0; j < sim->idlers_per_set[k]; j++) {
            bd_idler *id = &sim->idlers[at++];
            double s = sp->s0 + (j + 1) * sim->idler_spacing[k];
            bd_tracker_init(sim, &id->tr, s);
            /* touch the belt as laid (not the ideal path): no initial kick */
            int e = id->tr.element, e1 = e + 1 == sim->n ? 0 : e + 1;
            double g = id->tr.gamma;
            id->tr.p[0] = sim->x[e] + g * (sim->x[e1] - sim->x[e]);
            id->tr.p[1] = sim->y[e] + g * (sim->y[e1] - sim->y[e]);
            id->radius = set->radius;
            id->centre[0] = id->tr.p[0] + nx * set->radius;
            id->centre[1] = id->tr.p[1] + ny * set->radius;
            id->inertia = set->inertia > 0.0 ? set->inertia : 1e-6;
            id->mu_s = set->friction.mu_static;
            id->mu_d = set->friction.mu_dynamic;
            id->rolling = set->rolling_resistance;
            /* stiff, linearly implicit contact (idler_contact.c) */
            id->k_contact = 100.0 * sim->k_axial;
            id->set = k;
        }
    }
}

/* the per-node and per-element arrays both belt formulations keep (zeroed;
 * s_node0 is each builder's own: the axial one sets it before it knows n) */
void bd_alloc_node_arrays(bd_sim *sim)
{
    size_t n = (size_t)sim->n;
    double **d[] = {&sim->x,    &sim->y,   &sim->vx,       &sim->vy,      &sim->fx,
                    &sim->fy,   &sim->fnx, &sim->fny,      &sim->mass,    &sim->material,
                    &sim->tension, &sim->ux, &sim->uy,     &sim->len};
    for (size_t i = 0; i < sizeof d / sizeof d[0]; i++)
        *d[i] = bd_xcalloc(n, sizeof(double));
    sim->seg_hint = bd_xcalloc(n, sizeof(int));
}

/* probes and the feed point: trackers fixed on the path (both belt
 * formulations) */
void bd_setup_probes_and_feed(bd_sim *sim)
{
    const bd_model_def *def = sim->def;
    const bd_simulation_def *sd = &def->simulation;
    sim->probe_count = sd->probe_count;
    sim->probes = bd_xcalloc((size_t)sd->probe_count, sizeof *sim->probes);
    for (int i = 0; i < sd->probe_count; i++) {
        bd_probe *pr = &sim->probes[i];
        bd_tracker_init(sim, &pr->tr, bd_path_span_s(&sim->path, sd->probes[i].span,
                                                     sd->probes[i].at));
        pr->tension_max = -INFINITY;
        pr->tension_min = INFINITY;
    }
    if (def->material.present) {
        sim->material_mpl = def->material.mass_per_length;
        sim->discharge_pulley = def->material.discharge;
        sim->has_feed = def->material.feeding;
        bd_tracker_init(sim, &sim->feed,
                        bd_path_span_s(&sim->path, def->material.feed_span, def->material.feed_at));
    }
}

/* A chain of straight elements cannot follow a wrap up to its tangent point
 * unless a node falls exactly there: the element that straddles the tangent
 * cuts the corner and kinks the first free node of the span, which then has
 * nothing to hold it. The chain's own equilibrium shape wraps the pulley
 * with nodes on the shell and leaves it from a node just past the tangent
 * point: put each span's end nodes (the ones next to a wrap) onto the shell
 * and lay the nodes between on the straight line joining them, at the same
 * fractions along the span. */
/* put node k onto pulley pb's shell at chord distance |x_k − x_ref| from
 * the wrap node ref, turning in the sense `sense` (±1) from ref: the
 * element between them keeps its length */
static void onto_shell(bd_sim *sim, const bd_pulley_body *pb, int ref, int k, double sense)
{
    double c = hypot(sim->x[k] - sim->x[ref], sim->y[k] - sim->y[ref]);
    if (c >= 2.0 * pb->radius)
        return;
    double a = atan2(sim->y[ref] - pb->cy, sim->x[ref] - pb->cx)
             + sense * 2.0 * asin(c / (2.0 * pb->radius));
    sim->x[k] = pb->cx + pb->radius * cos(a);
    sim->y[k] = pb->cy + pb->radius * sin(a);
}

static void straighten_spans(bd_sim *sim)
{
    const int n = sim->n;
    for (int i = 0; i < n; i++) {
        int prev = i == 0 ? n - 1 : i - 1;
        const bd_path_segment *g = &sim->path.segments[sim->seg_hint[i]];
        const bd_path_segment *gp = &sim->path.segments[sim->seg_hint[prev]];
        if (g->kind != BD_SEGMENT_SPAN || gp->kind != BD_SEGMENT_ARC)
            continue;
        /* i is the first node of a span after a wrap; find its last node */
        int last = i, count = 1;
        while (count < n && sim->seg_hint[(last + 1) % n] == sim->seg_hint[i]) {
            last = (last + 1) % n;
            count++;
        }
        const bd_path_segment *gn = &sim->path.segments[sim->seg_hint[(last + 1) % n]];
        if (gn->kind != BD_SEGMENT_ARC || count < 1)
            continue;
        /* the departure node: the span's first node if it is within half an
         * element of the tangent point (then on the shell), else the last
         * node of the wrap; likewise the arrival node */
        int a = prev, b = (last + 1) % n;
        if (sim->s_node0[i] - g->s0 < 0.5 * sim->l0) {
            onto_shell(sim, &sim->pulleys[gp->pulley], prev, i, sim->pulleys[gp->pulley].wrap);
            a = i;
        }
        if (g->s0 + g->length - sim->s_node0[last] < 0.5 * sim->l0 && last != a) {
            onto_shell(sim, &sim->pulleys[gn->pulley], (last + 1) % n, last,
                       -sim->pulleys[gn->pulley].wrap);
            b = last;
        }
        double ax = sim->x[a], ay = sim->y[a], bx = sim->x[b], by = sim->y[b];
        double sa = sim->s_node0[a], sb = sim->s_node0[b];
        if (sb < sa)
            sb += sim->path.length;
        for (int j = (a + 1) % n; j != b; j = (j + 1) % n) {
            double sj = sim->s_node0[j] < sa ? sim->s_node0[j] + sim->path.length
                                             : sim->s_node0[j];
            double f = (sj - sa) / (sb - sa);
            sim->x[j] = ax + f * (bx - ax);
            sim->y[j] = ay + f * (by - ay);
        }
    }
}

/* place nodes on the laid path. A node on or at the edge of a wrap is held
 * by its pulley against the pull of its two elements, |T_b·u_b − T_a·u_a|
 * (the kink force); push it into the pulley by the penetration that makes
 * the contact carry exactly that, so the initial state is in equilibrium */
static void place_nodes(bd_sim *sim, const bd_layout *lay)
{
    const int n = sim->n;
    for (int i = 0; i < n; i++) {
        double p[2], t[2];
        bd_path_point(&sim->path, lay->s[i], p, t);
        sim->x[i] = p[0];
        sim->y[i] = p[1];
        sim->s_node0[i] = lay->s[i];
        sim->seg_hint[i] = bd_path_segment_at(&sim->path, lay->s[i]);
        sim->mass[i] = sim->belt_mpl * sim->l0;
    }
    straighten_spans(sim);
    for (int i = 0; i < n; i++) {
        int b = i == 0 ? n - 1 : i - 1, a = i + 1 == n ? 0 : i + 1;
        double ubx = sim->x[i] - sim->x[b], uby = sim->y[i] - sim->y[b];
        double uax = sim->x[a] - sim->x[i], uay = sim->y[a] - sim->y[i];
        double lb = hypot(ubx, uby), la = hypot(uax, uay);
        double kx = lay->tension[i] * uax / la - lay->tension[b] * ubx / lb;
        double ky = lay->tension[i] * uay / la - lay->tension[b] * uby / lb;
        for (int k = 0; k < sim->pulley_count; k++) {
            const bd_pulley_body *pb = &sim->pulleys[k];
            double rx = sim->x[i] - pb->cx, ry = sim->y[i] - pb->cy;
            double r = hypot(rx, ry);
            if (r > pb->radius * (1.0 + 1e-9))
                continue;
            double inward = -(kx * rx + ky * ry) / r;   /* pull towards the centre */
            double depth = inward > 0.0 ? inward / pb->k_contact : 0.0;
            double target = pb->radius - depth;
            sim->x[i] = pb->cx + rx * target / r;
            sim->y[i] = pb->cy + ry * target / r;
        }
    }
}

/* initial material: nodes from the feed point to the discharge pulley */
static void load_material(bd_sim *sim)
{
    const bd_material_def *mat = &sim->def->material;
    if (!mat->present || !mat->initially_loaded)
        return;
    double L = sim->path.length;
    double s_feed = bd_path_span_s(&sim->path, mat->feed_span, mat->feed_at);
    double s_dis = bd_path_arc(&sim->path, mat->discharge)->s0;
    double len = fmod(s_dis - s_feed + 2.0 * L, L);
    for (int i = 0; i < sim->n; i++) {
        double rel = fmod(sim->s_node0[i] - s_feed + 2.0 * L, L);
        if (rel <= len) {
            sim->material[i] = mat->mass_per_length * sim->l0;
            sim->mass[i] += sim->material[i];
        }
    }
}

/* the inertia the speed controllers are tuned for: everything the belt
 * moves, reflected to each drive pulley, shared among the speed drives */
static void prepare_drives(bd_sim *sim)
{
    double belt_mass = 0.0;
    for (int i = 0; i < sim->n; i++)
        belt_mass += sim->mass[i];
    int speed_drives = 0;
    for (int i = 0; i < sim->pulley_count; i++)
        if (sim->pulleys[i].def->has_drive
            && sim->pulleys[i].def->drive.control == BD_CONTROL_SPEED)
            speed_drives++;
    for (int i = 0; i < sim->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        if (!p->def->has_drive)
            continue;
        double R = p->radius;
        double J = belt_mass * R * R;
        for (int k = 0; k < sim->pulley_count; k++) {
            double r = sim->pulleys[k].radius;
            J += sim->pulleys[k].inertia * (R / r) * (R / r);
        }
        for (int k = 0; k < sim->idler_count; k++) {
            double r = sim->idlers[k].radius;
            J += sim->idlers[k].inertia * (R / r) * (R / r);
        }
        bd_drive_prepare(sim, p, J / (speed_drives > 0 ? speed_drives : 1));
    }
}

/* every formulation: time step, drives (and transmissions), rest */
static int finish_create(bd_sim *sim, bd_sim **out, bd_diag *diag)
{
    if (bd_time_step_choose(sim, diag) || bd_transmissions_create(sim, diag)) {
        bd_sim_free(sim);
        return 1;
    }
    prepare_drives(sim);
    bd_transmissions_tune(sim);
    bd_sim_start_at_rest(sim);
    sim->tension_max = -INFINITY;
    sim->tension_min = INFINITY;
    for (int i = 0; i < sim->pulley_count; i++) {
        sim->pulleys[i].travel_min = 0.0;
        sim->pulleys[i].travel_max = 0.0;
    }
    *out = sim;
    return 0;
}

int bd_sim_create(const bd_model_def *def, bd_sim **out, bd_diag *diag)
{
    *out = NULL;
    if (def->belt.formulation == BD_FORMULATION_AXIAL) {
        bd_sim *sim = bd_xcalloc(1, sizeof *sim);
        sim->def = def;
        sim->axial = 1;
        sim->gravity = def->gravity;
        sim->EA = def->belt.axial_stiffness;
        sim->belt_mpl = def->belt.mass_per_length;
        if (bd_axial_build(sim, diag)) {
            bd_sim_free(sim);
            return 1;
        }
        return finish_create(sim, out, diag);
    }
    bd_path given;
    if (bd_path_build(def, &given, diag))
        return 1;
    bd_sim *sim = bd_xcalloc(1, sizeof *sim);
    sim->def = def;
    sim->gravity = def->gravity;
    sim->EA = def->belt.axial_stiffness;
    sim->EI = def->belt.bending_stiffness;
    sim->belt_mpl = def->belt.mass_per_length;

    double target = def->belt.element_length > 0.0 ? def->belt.element_length
                                                   : default_element_length(def);
    bd_layout lay;
    char err[512];
    bd_layout_request req = {&given, target};
    if (bd_layout_belt(def, &req, &lay, err, sizeof err)) {
        bd_diag_error(diag, def->source, def->belt.mark, "%s", err);
        bd_path_free(&given);
        free(sim);
        return 1;
    }
    bd_path_free(&given);
    sim->path = lay.path;
    lay.path.segments = NULL;
    sim->n = lay.n;
    sim->l0 = lay.l0;
    sim->k_axial = sim->EA / sim->l0;
    double m_el = sim->belt_mpl * sim->l0;
    /* seed 001 eq 4.3: c = 2·m·ζ·√(k/m) with m the element mass */
    sim->c_axial = 2.0 * def->belt.damping_ratio * sqrt(sim->k_axial * m_el);
    /* seed 001 eq 4.11: k_θ = EI/l */
    sim->k_bend = sim->EI / sim->l0;

    bd_alloc_node_arrays(sim);
    sim->s_node0 = bd_xcalloc((size_t)sim->n, sizeof *sim->s_node0);
    for (int i = 0; i < sim->n; i++)
        sim->s_node0[i] = lay.s[i];
    setup_pulleys(sim, &lay);
    place_nodes(sim, &lay);
    for (int i = 0; i < sim->n; i++)
        sim->tension[i] = lay.tension[i];
    bd_layout_free(&lay);
    load_material(sim);
    setup_idlers(sim);
    bd_setup_probes_and_feed(sim);
    for (int i = 0; i < sim->pulley_count; i++)
        if (sim->pulleys[i].def->has_drive)
            bd_monitor_init(sim, &sim->pulleys[i]);

    return finish_create(sim, out, diag);
}

void bd_sim_free(bd_sim *sim)
{
    if (!sim)
        return;
    free(sim->x);
    free(sim->y);
    free(sim->vx);
    free(sim->vy);
    free(sim->fx);
    free(sim->fy);
    free(sim->fnx);
    free(sim->fny);
    free(sim->mass);
    free(sim->material);
    free(sim->tension);
    free(sim->ux);
    free(sim->uy);
    free(sim->len);
    free(sim->s_node0);
    free(sim->seg_hint);
    bd_axial_free(sim);
    bd_transmissions_free(sim);
    for (int i = 0; i < sim->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        free(p->c_node);
        free(p->c_normal);
        free(p->c_tx);
        free(p->c_ty);
        free(p->c_f);
        free(p->c_slip);
    }
    free(sim->pulleys);
    free(sim->idlers);
    free(sim->idlers_per_set);
    free(sim->idler_spacing);
    free(sim->probes);
    for (int i = 0; i < sim->warning_count; i++)
        free(sim->warnings[i]);
    free(sim->warnings);
    bd_path_free(&sim->path);
    free(sim);
}

double bd_sim_time(const bd_sim *sim) { return sim->t; }
double bd_sim_time_step(const bd_sim *sim) { return sim->dt; }
int bd_sim_node_count(const bd_sim *sim) { return sim->n; }
