/* Compile a boom model: the nodes of each section, the contacts, the
 * damping, and the stable time step; what `check` prints. */
#include "boom/boom_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/constants.h"
#include "laws/stable_step.h"
#include "model/fields.h"
#include "sim/timestep.h"

/* state arrays: x y phi vx vy w s m J fx fy mz eN eMa eMb eV and the
 * seven remap scratch arrays */
#define BOOM_ARRAYS 23

static int copy_table(bd_table *dst, const bd_table *src)
{
    memset(dst, 0, sizeof *dst);
    if (src->n == 0)
        return 0;
    if (bd_fields_table_alloc(dst, src->n))
        return 1;
    memcpy(dst->t, src->t, (size_t)src->n * sizeof *dst->t);
    memcpy(dst->v, src->v, (size_t)src->n * sizeof *dst->v);
    return 0;
}

static int copy_def(bd_boom_def *dst, const bd_boom_def *src)
{
    *dst = *src;
    dst->sections = NULL;
    memset(&dst->luffing_angle, 0, sizeof dst->luffing_angle);
    memset(&dst->stroke.table, 0, sizeof dst->stroke.table);
    dst->sections = malloc((size_t)src->section_count * sizeof *dst->sections);
    if (!dst->sections)
        return 1;
    memcpy(dst->sections, src->sections, (size_t)src->section_count * sizeof *dst->sections);
    if (copy_table(&dst->luffing_angle, &src->luffing_angle)
        || copy_table(&dst->stroke.table, &src->stroke.table))
        return 1;
    return 0;
}

/* highest frequency of the beams alone (rad/s) at the present layout:
 * power iteration on M^-1/2 K M^-1/2, K by differences of the elastic
 * forces about the rigid state */
static double beam_omega_max(bd_boom *b)
{
    int N = b->N, n3 = 3 * N;
    double *z = calloc((size_t)n3, sizeof *z);
    double *f0 = calloc((size_t)n3, sizeof *f0);
    if (!z || !f0) {
        free(z);
        free(f0);
        return -1.0;
    }
    double saved_beta = b->beta, u, p;
    b->beta = 0.0;
    memcpy(b->tx, b->x, (size_t)N * sizeof(double));
    memcpy(b->ty, b->y, (size_t)N * sizeof(double));
    memcpy(b->tphi, b->phi, (size_t)N * sizeof(double));
    for (int i = 0; i < N; i++)
        b->vx[i] = b->vy[i] = b->w[i] = 0.0;
    memset(b->fx, 0, (size_t)N * sizeof(double));
    memset(b->fy, 0, (size_t)N * sizeof(double));
    memset(b->mz, 0, (size_t)N * sizeof(double));
    boom_beam_forces(b, &u, &p);
    for (int i = 0; i < N; i++) {
        f0[3 * i] = b->fx[i];
        f0[3 * i + 1] = b->fy[i];
        f0[3 * i + 2] = b->mz[i];
    }
    /* a fixed start with every component present */
    for (int j = 0; j < n3; j++)
        z[j] = 1.0 + 0.37 * sin(1.7 * j) + ((j & 1) ? 0.5 : -0.5);
    double lam = 0.0;
    const double disp = 1e-7;   /* m (and rad) of the largest perturbation */
    for (int it = 0; it < 200; it++) {
        double nz = 0.0;
        for (int j = 0; j < n3; j++)
            nz += z[j] * z[j];
        nz = sqrt(nz);
        if (!(nz > 0.0))
            break;
        double mmin = INFINITY;
        for (int i = 0; i < N; i++)
            mmin = fmin(mmin, fmin(b->m[i], b->J[i]));
        double h = disp * sqrt(mmin);
        for (int i = 0; i < N; i++) {
            b->x[i] = b->tx[i] + h * z[3 * i] / nz / sqrt(b->m[i]);
            b->y[i] = b->ty[i] + h * z[3 * i + 1] / nz / sqrt(b->m[i]);
            b->phi[i] = b->tphi[i] + h * z[3 * i + 2] / nz / sqrt(b->J[i]);
        }
        memset(b->fx, 0, (size_t)N * sizeof(double));
        memset(b->fy, 0, (size_t)N * sizeof(double));
        memset(b->mz, 0, (size_t)N * sizeof(double));
        boom_beam_forces(b, &u, &p);
        double na = 0.0;
        for (int i = 0; i < N; i++) {
            z[3 * i] = -(b->fx[i] - f0[3 * i]) / h / sqrt(b->m[i]);
            z[3 * i + 1] = -(b->fy[i] - f0[3 * i + 1]) / h / sqrt(b->m[i]);
            z[3 * i + 2] = -(b->mz[i] - f0[3 * i + 2]) / h / sqrt(b->J[i]);
            if (i == b->sec[0].first)
                z[3 * i] = z[3 * i + 1] = 0.0;   /* the pivot does not move */
        }
        for (int j = 0; j < n3; j++)
            na += z[j] * z[j];
        lam = sqrt(na);
    }
    memcpy(b->x, b->tx, (size_t)N * sizeof(double));
    memcpy(b->y, b->ty, (size_t)N * sizeof(double));
    memcpy(b->phi, b->tphi, (size_t)N * sizeof(double));
    b->beta = saved_beta;
    free(z);
    free(f0);
    return sqrt(lam);
}

/* the parts other than the beams, each on the lightest node it can touch
 * (an upper bound of their own frequencies) */
static double parts_omega2(const bd_boom *b)
{
    double mmin = INFINITY, Jmin = INFINITY;
    for (int i = 1; i < b->N; i++) {
        mmin = fmin(mmin, b->m[i]);
        Jmin = fmin(Jmin, b->J[i]);
    }
    const bd_boom_def *d = &b->def;
    double w = d->pads.width;
    /* both pads of a contact can press at once when gap = 0 */
    double pad = 2.0 * d->pads.stiffness * 2.0 / mmin;
    double pad_rot = 2.0 * d->pads.stiffness * w * w / 4.0 * 2.0 / Jmin;
    double cyl = d->telescopic_cylinder.stiffness * 2.0 / mmin;
    double rope = 0.0;
    for (int k = 0; k < b->ns; k++)
        rope = fmax(rope, 3.0 * d->ropes.axial_stiffness / (b->sec[k].L) * 2.0 / mmin);
    double rod = d->luffing_cylinder.present ? d->luffing_cylinder.stiffness / mmin : 0.0;
    return fmax(pad, pad_rot) + cyl + rope + rod;
}

/* the first bending frequency of the boom at its initial stroke, as a
 * cantilever stepped where the sections end (the outermost present at
 * each point carries the bending; the overlaps' extra stiffness is left
 * out), its tip stiffness 1 / int (L - x)^2 / EI dx, with the tip mass and
 * 0.24 of the beams' mass at the tip (Rayleigh's 33/140 for a uniform
 * cantilever, Blevins, Formulas for natural frequency, table 6-2): an
 * estimate, to place the mass-proportional damping (rad/s) */
static double first_bending(const bd_boom *b)
{
    double Ltot = boom_rigid_offset(b, b->ns - 1, b->def.stroke.initial) + b->sec[b->ns - 1].L;
    double flex = 0.0, mass = 0.0;
    const int n = 400;
    for (int i = 0; i < n; i++) {
        double x = (i + 0.5) * Ltot / n;
        double EI = 0.0;
        for (int k = 0; k < b->ns && EI == 0.0; k++) {
            double x0 = boom_rigid_offset(b, k, b->def.stroke.initial);
            if (x >= x0 && x <= x0 + b->sec[k].L)
                EI = b->sec[k].EI;
        }
        if (EI == 0.0)
            EI = b->sec[b->ns - 1].EI;
        flex += (Ltot - x) * (Ltot - x) / EI * Ltot / n;
    }
    for (int k = 0; k < b->ns; k++)
        mass += b->sec[k].rhoA * b->sec[k].L;
    return sqrt(1.0 / flex / (b->tip_mass + 0.24 * mass));
}

void bd_boom_free(bd_boom *b)
{
    if (!b)
        return;
    free(b->x);
    bd_boom_def_free(&b->def);
    free(b);
}

int bd_boom_create(const bd_boom_def *def, bd_boom **out, bd_diag *diag)
{
    *out = NULL;
    bd_boom *b = calloc(1, sizeof *b);
    if (!b || copy_def(&b->def, def)) {
        bd_diag_error(diag, def->source, def->mark, "out of memory building the boom");
        if (b)
            bd_boom_free(b);
        return 1;
    }
    const bd_boom_def *d = &b->def;
    b->ns = d->section_count;
    b->g = d->gravity;
    b->tip_mass = d->tip_mass;
    b->base_a = -d->pivot_offset[0];
    b->base_n = -d->pivot_offset[1];
    b->attach_n = d->luffing_cylinder.attach[1] - b->base_n;
    int p = d->elements_per_segment;
    int first = 0;
    for (int k = 0; k < b->ns; k++) {
        boom_section *S = &b->sec[k];
        const bd_boom_section_def *sd = &d->sections[k];
        S->L = sd->length;
        S->EA = sd->axial_stiffness;
        S->EI = sd->bending_stiffness;
        S->rhoA = sd->mass_per_length;
        S->h = sd->height;
        S->per_seg = p;
        if (k == 0) {
            S->key = BOOM_KEY_NONE;
            /* the attachment is given from the pivot; on the section it
             * stands base_a further back */
            double as = d->luffing_cylinder.attach[0] - b->base_a;
            if (d->luffing_cylinder.present && as < 0.999 * S->L) {
                S->key = BOOM_KEY_ATTACH;
                b->attach_s = as;
            }
        } else {
            S->key = BOOM_KEY_OUTER;
        }
        S->n = S->key == BOOM_KEY_NONE ? p + 1 : 2 * p + 1;
        S->first = first;
        first += S->n;
    }
    b->N = first;
    b->attach_node = b->sec[0].key == BOOM_KEY_ATTACH ? b->sec[0].first + p
                                                     : b->sec[0].first + b->sec[0].n - 1;
    if (b->sec[0].key != BOOM_KEY_ATTACH)
        b->attach_s = b->sec[0].L;
    double *blk = calloc((size_t)b->N * BOOM_ARRAYS, sizeof *blk);
    if (!blk) {
        bd_diag_error(diag, d->source, d->mark, "out of memory: %d nodes", b->N);
        bd_boom_free(b);
        return 1;
    }
    double **arr[BOOM_ARRAYS] = {&b->x, &b->y, &b->phi, &b->vx, &b->vy, &b->w, &b->s, &b->m,
                                 &b->J, &b->fx, &b->fy, &b->mz, &b->eN, &b->eMa, &b->eMb,
                                 &b->eV, &b->tx, &b->ty, &b->tphi, &b->tvx, &b->tvy, &b->tw,
                                 &b->ts};
    for (int i = 0; i < BOOM_ARRAYS; i++)
        *arr[i] = blk + (size_t)i * (size_t)b->N;
    /* contacts */
    b->nc = 2 * (b->ns - 1);
    for (int j = 0; j + 1 < b->ns; j++) {
        boom_contact *ci = &b->c[2 * j], *co = &b->c[2 * j + 1];
        const boom_section *in = &b->sec[j + 1], *ou = &b->sec[j];
        ci->inner_sec = co->inner_sec = j + 1;
        ci->outer_sec = co->outer_sec = j;
        ci->h = in->h;   /* the inner section's bottom pads */
        co->h = ou->h;   /* the outer section's top pads */
        ci->A = (boom_where){j + 1, in->first, 0.0};
        ci->B = (boom_where){j, ou->first, 0.0};
        co->A = (boom_where){j + 1, in->first + in->per_seg, 0.0};
        co->B = (boom_where){j, ou->first + ou->n - 2, 1.0};
        ci->surface_on_A = 0;
        co->surface_on_A = 1;
    }
    /* the stable step: the highest frequency over the layouts the stroke
     * passes through (element lengths are extreme at its ends) */
    double strokes[2] = {d->stroke.initial, 0.0}, a_;
    bd_boom_stroke_eval(&d->stroke, bd_boom_stroke_end(&d->stroke), &strokes[1], &a_, &a_);
    b->omega_max = 0.0;
    for (int q = 0; q < 2; q++) {
        boom_kinematics(b, 0.0);
        b->theta_dot = 0.0;
        b->stroke_ref = strokes[q];
        b->stroke_v = 0.0;
        boom_place_rigid(b);
        double wb = beam_omega_max(b);
        if (wb < 0.0) {
            bd_diag_error(diag, d->source, d->mark, "out of memory building the boom");
            bd_boom_free(b);
            return 1;
        }
        double wmax = sqrt(wb * wb + parts_omega2(b));
        if (wmax > b->omega_max)
            b->omega_max = wmax;
    }
    /* Rayleigh damping: beta gives the highest mode 5 % (it only cleans
     * numerical noise); alpha gives the first bending mode the model's
     * damping ratio */
    const double zeta_top = 0.05;
    b->beta = 2.0 * zeta_top / b->omega_max;
    double w1 = first_bending(b);
    b->f1_hz = w1 / BD_TWO_PI;
    b->alpha = 2.0 * d->damping_ratio * w1;
    double zeta_hi = zeta_top + d->pads.damping_ratio;
    double dt_stable = BD_TIME_STEP_SAFETY * bd_central_difference_limit(b->omega_max, zeta_hi);
    b->dt = dt_stable;
    if (d->simulation.time_step > 0.0) {
        if (d->simulation.time_step > dt_stable)
            bd_diag_error(diag, d->source, d->simulation.time_step_mark,
                          "simulation.time_step: %g s is above the stable step of this boom, "
                          "%.3g s (highest frequency %.0f Hz); use auto or at most that",
                          d->simulation.time_step, dt_stable, b->omega_max / BD_TWO_PI);
        b->dt = d->simulation.time_step;
    }
    if (d->luffing_cylinder.present) {
        /* a rod nearly through the pivot holds the boom only with a huge
         * force and a soft angle: say so where the rod is defined */
        double c = cos(b->theta), sn = sin(b->theta);
        const double *at = d->luffing_cylinder.attach, *base = d->luffing_cylinder.base;
        double px = d->pivot[0] + at[0] * c - at[1] * sn, py = d->pivot[1] + at[0] * sn + at[1] * c;
        double ux = px - base[0], uy = py - base[1], l = hypot(ux, uy);
        double lever = fabs((px - d->pivot[0]) * uy - (py - d->pivot[1]) * ux) / l;
        if (lever < 0.05 * at[0])
            bd_diag_warning(diag, d->source, d->luffing_cylinder.mark,
                            "boom.luffing_cylinder: its line passes %.3f m from the pivot "
                            "(%.1f %% of the attachment's distance): it needs %.0f N for every N·m "
                            "the boom's weight puts about the pivot",
                            lever, 100.0 * lever / at[0], 1.0 / lever);
    }
    if (diag->count > 0) {
        bd_boom_free(b);
        return 1;
    }
    /* the state at t = 0: the rigid boom at the initial stroke */
    b->t = 0.0;
    boom_kinematics(b, 0.0);
    boom_place_rigid(b);
    boom_actuators_init(b);
    *out = b;
    return 0;
}

double boom_static_cylinder_force(const bd_boom *b)
{
    /* rope statics (virtual work): section k's bottom moves k times the
     * stroke (synchronised), so F = g sin(theta) sum k m_k, the tip mass
     * with the last section */
    double th = bd_table_eval(&b->def.luffing_angle, 0.0), F = 0.0;
    for (int k = 1; k < b->ns; k++) {
        double r = b->def.synchronized ? k : 1.0;
        double mk = b->sec[k].rhoA * b->sec[k].L + (k == b->ns - 1 ? b->tip_mass : 0.0);
        F += r * mk;
    }
    return b->g * sin(th) * F;
}

double boom_static_luffing(const bd_boom *b, double stroke)
{
    /* the weight's moment about the pivot: each section's mass at its
     * centre, the tip mass at the tip, x - x_pivot = d cos - n sin in the
     * boom frame (d along from the pivot, n = base_n across) */
    const bd_boom_def *d = &b->def;
    double th = bd_table_eval(&d->luffing_angle, 0.0), c = cos(th), sn = sin(th), M = 0.0;
    for (int k = 0; k < b->ns; k++) {
        double at = b->base_a + boom_rigid_offset(b, k, stroke);
        double mk = b->sec[k].rhoA * b->sec[k].L;
        M += mk * ((at + 0.5 * b->sec[k].L) * c - b->base_n * sn);
        if (k == b->ns - 1)
            M += b->tip_mass * ((at + b->sec[k].L) * c - b->base_n * sn);
    }
    M *= b->g;
    if (!d->luffing_cylinder.present)
        return M;
    /* the rod's push F along u (base -> attachment) turns the boom by
     * F (r x u) about the pivot */
    const double *at = d->luffing_cylinder.attach, *base = d->luffing_cylinder.base;
    double rx = at[0] * c - at[1] * sn, ry = at[0] * sn + at[1] * c;
    double ux = d->pivot[0] + rx - base[0], uy = d->pivot[1] + ry - base[1], l = hypot(ux, uy);
    return M / ((rx * uy - ry * ux) / l);
}

void bd_boom_describe(const bd_boom *b, FILE *f)
{
    const bd_boom_def *d = &b->def;
    double mass = b->tip_mass;
    fprintf(f, "boom model '%s': %d sections, luffing %.1f deg", d->name, b->ns,
            bd_table_eval(&d->luffing_angle, 0.0) / BD_DEG);
    fprintf(f, d->luffing_cylinder.present ? " held by the luffing cylinder\n"
                                           : " held by a moment at the pivot\n");
    for (int k = 0; k < b->ns; k++) {
        const boom_section *S = &b->sec[k];
        mass += S->rhoA * S->L;
        fprintf(f, "  section %d: %.2f m, EA %.3g N, EI %.3g N·m², %.1f kg/m (%.0f kg), pads %.3f m "
                "apart\n", k + 1, S->L, S->EA, S->EI, S->rhoA, S->rhoA * S->L, S->h);
    }
    double end = bd_boom_stroke_end(&d->stroke), s_end, v_, a_;
    bd_boom_stroke_eval(&d->stroke, end, &s_end, &v_, &a_);
    double dur = d->simulation.duration > 0.0 ? d->simulation.duration : end + 2.0;
    fprintf(f, "stroke %.3f -> %.3f m by %.2f s%s; tip load %.0f kg; total mass %.0f kg\n",
            d->stroke.initial, s_end, end, d->synchronized ? " (synchronised by ropes)" : "",
            b->tip_mass, mass);
    fprintf(f, "static telescopic cylinder force by rope statics at t = 0: %.4g N\n",
            boom_static_cylinder_force(b));
    fprintf(f, "static %s by rigid statics: %.4g %s at the initial stroke, %.4g at %.3f m "
            "(ratio %.3f)\n", d->luffing_cylinder.present ? "luffing cylinder force"
            : "pivot moment", boom_static_luffing(b, d->stroke.initial),
            d->luffing_cylinder.present ? "N" : "N·m", boom_static_luffing(b, s_end), s_end,
            boom_static_luffing(b, s_end) / boom_static_luffing(b, d->stroke.initial));
    fprintf(f, "%d nodes (%d elements per segment); highest frequency %.0f Hz; time step %.3g s; "
            "%.0f s simulated = %.3g steps\n", b->N, d->elements_per_segment,
            b->omega_max / BD_TWO_PI, b->dt, dur, dur / b->dt);
    fprintf(f, "structural damping: %.3g of critical at the first bending mode (estimated "
            "%.2f Hz; Rayleigh alpha %.3g 1/s on the motion relative to the rigid boom, beta "
            "%.3g s)\n", d->damping_ratio, b->f1_hz, b->alpha, b->beta);
}

void bd_boom_get_result(const bd_boom *b, bd_boom_result *r)
{
    *r = b->res;
    r->balance_error_rel = b->balance_rel;
    r->kinetic_final_J = b->e_kin;
    r->steps = b->steps;
    r->time_step_s = b->dt;
    r->nodes = b->N;
}
