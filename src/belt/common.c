/* What the belt formulations' builds share (belt.h), and the choice of a
 * formulation from the model. */
#include "belt/belt.h"

#include <math.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "base/alloc.h"
#include "laws/rolling.h"
#include "laws/secondary_resistance.h"
#include "model/secondary.h"

const bd_belt_ops *bd_belt_ops_for(bd_formulation f)
{
    switch (f) {
    case BD_FORMULATION_DISCRETE: return &bd_lumped_ops;
    case BD_FORMULATION_AXIAL: return &bd_axial_ops;
    case BD_FORMULATION_MOVING_NODE: return &bd_moving_node_ops;
    case BD_FORMULATION_RFE: return &bd_rfe_ops;
    }
    return NULL;
}

void bd_setup_probes_and_feed(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    const bd_simulation_def *sd = &def->simulation;
    sim->own->probe_count = sd->probe_count;
    sim->probes = bd_xcalloc((size_t)sd->probe_count, sizeof *sim->probes);
    for (int i = 0; i < sd->probe_count; i++) {
        bd_probe *pr = &sim->probes[i];
        sim->model->belt->point_init(
            sim, &pr->tr, bd_path_span_s(&sim->model->path, sd->probes[i].span, sd->probes[i].at));
        pr->tension_max = -INFINITY;
        pr->tension_min = INFINITY;
    }
    if (def->material.present) {
        sim->own->material_mpl = def->material.mass_per_length;
        sim->own->discharge_pulley = def->material.discharge;
        sim->has_feed = def->material.feeding;
        sim->own->feed_individual = bd_secondary_individual(def);
        sim->model->belt->point_init(
            sim, &sim->feed,
            bd_path_span_s(&sim->model->path, def->material.feed_span, def->material.feed_at));
    }
}

double bd_feed_force(const bd_sim *sim, double v, double m, int landing, int loaded)
{
    const bd_model_def *def = sim->model->def;
    const int individual = sim->model->feed_individual;
    double F = 0.0;
    /* the material landing is accelerated to belt speed: the momentum flux
     * ṁ·(v − v0) with ṁ = m'_L·v (ISO 5048's F_bA; physics.md §11); a
     * belt slower than the material takes nothing from it (its push is
     * left out) */
    if (landing && sim->has_feed && v > 0.0) {
        double v0 = bd_landing_speed(def, individual, v);
        if (v > v0)
            F -= bd_res_loading_inertia(sim->model->material_mpl, v, v0);
    }
    if (!individual)
        return F;
    /* the skirts: in the acceleration zone while material lands (F_f), over
     * their length while material lies there (F_gl), at the present speed;
     * a Coulomb force faded near rest, the fade no steeper than a quarter
     * of what the explicit step bears on a node of mass m */
    bd_feed_resistance fr;
    bd_secondary_feed(def, fabs(v), &fr);
    double skirts = (sim->has_feed ? fr.loading_skirts : 0.0) + (loaded ? fr.skirts : 0.0);
    if (skirts > 0.0) {
        F -= skirts * bd_coulomb_share(v, bd_coulomb_fade(skirts, 1.0, sim->model->dt, m));
    }
    return F;
}

int bd_span_vertical(const bd_path *path, int span)
{
    return fabs(bd_path_span(path, span)->dir[0]) < 1e-6;
}

int bd_idler_count(const bd_model_def *def, const bd_path *path, int k, double *spacing)
{
    const bd_idler_set_def *set = &def->idler_sets[k];
    const bd_path_segment *sp = bd_path_span(path, set->span);
    *spacing = set->spacing;
    if (bd_span_vertical(path, set->span))
        return 0;
    /* the closest spacing to the given one that fits the span evenly
     * (documented in docs/model-format.md) */
    int count = (int)lround(sp->length / set->spacing) - 1;
    if (count < 0)
        count = 0;
    *spacing = sp->length / (count + 1);
    return count;
}

int bd_idler_set_layout(bd_sim *sim, int k, double *spacing)
{
    const bd_model_def *def = sim->model->def;
    int count = bd_idler_count(def, &sim->model->path, k, spacing);
    sim->own->idlers_per_set[k] = count;
    if (bd_span_vertical(&sim->model->path, def->idler_sets[k].span))
        bd_sim_warn(sim, "idlers on span '%s': the span is vertical; no idlers placed",
                    def->pulleys[def->idler_sets[k].span].name);
    return count;
}

double bd_belt_point_tension(const bd_sim *sim, const bd_tracker *tr)
{
    int n = sim->model->n, e = tr->element;
    double g = tr->gamma;
    if (g >= 0.5) {
        int j = e + 1 == n ? 0 : e + 1;
        return sim->tension[e] + (g - 0.5) * (sim->tension[j] - sim->tension[e]);
    }
    int b = e == 0 ? n - 1 : e - 1;
    return sim->tension[b] + (g + 0.5) * (sim->tension[e] - sim->tension[b]);
}

void bd_belt_point_place(const bd_sim *sim, bd_tracker *tr, double s)
{
    double L = sim->model->path.length;
    s = fmod(s, L);
    if (s < 0.0)
        s += L;
    tr->s = s;
    bd_path_point(&sim->model->path, s, tr->p, tr->dir);
    /* the node with the largest initial s not beyond the point */
    int lo = 0, hi = sim->model->n - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (sim->model->s_node0[mid] <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    tr->element = lo;
}

/* The largest and the smallest tension, and whether any is NaN (a NaN
 * compares false, so it is flagged on its own). Which element holds an
 * extreme is looked up only when it is needed (bd_tension_element).
 * With SSE2, two elements to a register: maxpd and minpd keep the running
 * value (their second operand) when the tension is NaN or equal to it, as
 * x > m ? x : m does, and cmpunordpd flags the NaN: the same extremes to
 * the bit. The scalar loop it replaced (eight running maxima, maxsd, and
 * a NaN test and flag per element) took 5.3 % of bench_long_conveyor's
 * instructions. */
#define LANES 8
void bd_tension_extremes(bd_sim *sim)
{
    const int n = sim->model->n;
    const double *restrict T = sim->tension;
    double mx[LANES], mn[LANES];
    int nan = 0;
    for (int k = 0; k < LANES; k++) {
        mx[k] = -INFINITY;
        mn[k] = INFINITY;
    }
    int e = 0;
#if defined(__SSE2__)
    __m128d hi0 = _mm_set1_pd(-INFINITY), hi1 = hi0, lo0 = _mm_set1_pd(INFINITY), lo1 = lo0;
    __m128d un = _mm_setzero_pd();
    for (; e + 4 <= n; e += 4) {
        __m128d a = _mm_loadu_pd(T + e), b = _mm_loadu_pd(T + e + 2);
        hi0 = _mm_max_pd(a, hi0);
        lo0 = _mm_min_pd(a, lo0);
        hi1 = _mm_max_pd(b, hi1);
        lo1 = _mm_min_pd(b, lo1);
        un = _mm_or_pd(un, _mm_cmpunord_pd(a, b));
    }
    _mm_storeu_pd(mx, hi0);
    _mm_storeu_pd(mx + 2, hi1);
    _mm_storeu_pd(mn, lo0);
    _mm_storeu_pd(mn + 2, lo1);
    nan = _mm_movemask_pd(un) != 0;
#else
    for (; e + LANES <= n; e += LANES)
        for (int k = 0; k < LANES; k++) {
            double t = T[e + k];
            nan |= !(t == t);
            mx[k] = t > mx[k] ? t : mx[k];
            mn[k] = t < mn[k] ? t : mn[k];
        }
#endif
    for (; e < n; e++) {
        double t = T[e];
        nan |= !(t == t);
        mx[0] = t > mx[0] ? t : mx[0];
        mn[0] = t < mn[0] ? t : mn[0];
    }
    double hi = mx[0], lo = mn[0];
    for (int k = 1; k < LANES; k++) {
        hi = mx[k] > hi ? mx[k] : hi;
        lo = mn[k] < lo ? mn[k] : lo;
    }
    sim->step_tension_max = hi;
    sim->step_tension_min = lo;
    sim->step_tension_nan = nan;
}

int bd_tension_element(const bd_sim *sim, double value)
{
    const int n = sim->model->n;
    int e = 0;
    while (e < n - 1 && !(sim->tension[e] == value))
        e++;
    return e;
}

void bd_belt_point_position(const bd_sim *sim, const bd_tracker *tr, double *x, double *y)
{
    int e = tr->element, j = e + 1 == sim->model->n ? 0 : e + 1;
    double g = tr->gamma;
    *x = sim->x[e] + g * (sim->x[j] - sim->x[e]);
    *y = sim->y[e] + g * (sim->y[j] - sim->y[e]);
}

/* ---- belts whose nodes are stations fixed on the path (axial,
 * moving_node): what their sensors read ---- */

void bd_station_point_init(const bd_sim *sim, bd_tracker *tr, double s, const double *len)
{
    bd_belt_point_place(sim, tr, s);
    int lo = tr->element;
    double rel = tr->s - sim->model->s_node0[lo];
    if (rel < 0.0) {
        tr->element = sim->model->n - 1;
        rel = tr->s + sim->model->path.length - sim->model->s_node0[sim->model->n - 1];
    }
    tr->gamma = rel / len[tr->element];
}

void bd_station_point_update(const bd_sim *sim, bd_tracker *tr)
{
    (void)sim;
    (void)tr;
}

void bd_station_sample(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out)
{
    int e = tr->element, j = e + 1 == sim->model->n ? 0 : e + 1;
    double g = tr->gamma;
    bd_belt_point_position(sim, tr, &out->x, &out->y);
    out->tension = bd_belt_point_tension(sim, tr);
    out->speed = (1.0 - g) * sim->vx[e] + g * sim->vx[j];
}

double bd_station_element_s(const bd_sim *sim, int e, const double *len)
{
    double s = sim->model->s_node0[e] + 0.5 * len[e];
    return s < sim->model->path.length ? s : s - sim->model->path.length;
}

double bd_station_element_speed(const bd_sim *sim, int e)
{
    int j = e + 1 == sim->model->n ? 0 : e + 1;
    return 0.5 * (sim->vx[e] + sim->vx[j]);
}

double bd_station_node_speed(const bd_sim *sim, int i)
{
    return sim->vx[i];
}

double bd_station_wrap_energy(const bd_sim *sim, const bd_pulley_body *p)
{
    (void)sim;
    (void)p;
    return 0.0;
}

double bd_station_support_inertia(const bd_sim *sim, double R, double J)
{
    (void)sim;
    (void)R;
    return J;
}
