/* Initial belt layout: the at-rest tension along the path and the node
 * positions that realise it (model-format.md `initial_state`).
 *
 * At rest, with frictionless support normal to the belt, the tension changes
 * along the belt only by the weight of belt and material:
 *   dT/ds = m'(s)·g·dy/ds   →   T(s) = T_c + W(s),  W(s) = ∫ m'(s)·g dy.
 * The level T_c comes from the takeup (force balance of its pulley along the
 * carriage axis) or, without one, from the installed tension: the belt's
 * unstretched length is L/(1 + T0/EA).
 *
 * Nodes are laid so that every element's length along the path is its
 * stretched length l0·(1 + T/EA): on a wrap too, where an element's length
 * is the belt's round the shell, not its chord (wrap_elements.c). The loop
 * closes for the right level: without takeup we solve for the unstretched
 * element length (the installed tension is kept), with a takeup we move
 * the takeup pulley along its axis (the tension is fixed by its force).
 * This removes the tension steps between sections that seed 001 §6.1
 * reports. */
#include "belt/lumped/layout.h"

#include "base/alloc.h"
#include "model/rest_weight.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define GRID_PER_ELEMENT 8

/* weight potential W(s) sampled on a fine grid of the path */
typedef struct weight_grid {
    long m;      /* long: GRID_PER_ELEMENT × a large node count passes INT_MAX */
    double ds;
    double *W;   /* [m + 1] */
    double *dW;  /* [m] the weight of each grid step of path, unstretched */
} weight_grid;

/* what loads the belt at rest (layout.h) */
bd_rest_load bd_layout_rest_load(const bd_model_def *def, const bd_path *path)
{
    bd_rest_load load = {def->belt.mass_per_length, 0.0, 0.0, 0.0, def->gravity};
    const bd_material_def *mat = &def->material;
    if (mat->present && mat->initially_loaded) {
        double len;
        bd_path_loaded_region(path, mat, &load.from, &len);
        load.material_mpl = mat->mass_per_length;
        load.to = load.from + len;
    }
    return load;
}

/* W(s) = ∫ m'·g dy (model/rest_weight.c) at the grid points */
static void weight_grid_build(const bd_model_def *def, const bd_path *path, double target,
                              weight_grid *g)
{
    g->m = (long)ceil(path->length / target * GRID_PER_ELEMENT) + 16;
    g->ds = path->length / (double)g->m;
    g->W = bd_xcalloc((size_t)g->m + 1, sizeof *g->W);
    g->dW = bd_xcalloc((size_t)g->m, sizeof *g->dW);
    bd_rest_load load = bd_layout_rest_load(def, path);
    g->W[0] = 0.0;
    for (long i = 1; i <= g->m; i++) {
        g->dW[i - 1] = bd_rest_weight(path, &load, (double)(i - 1) * g->ds, (double)i * g->ds, 1);
        g->W[i] = g->W[i - 1] + g->dW[i - 1];
    }
}

/* The belt's mass is its unstretched length's: a path length ds holds
 * ds/(1 + T/EA) of belt, whose weight the tension carries,
 *   dT/ds = m'·g·(dy/ds)/(1 + T/EA),   T = T_c + W(s).
 * The element's nodes carry m'·l0 each (build.c), so this is the rest state
 * their tensions balance; with the stretched length's weight every node of a
 * strand was pulled up by ε·m·g, and a 100 m vertical loop settled 1.3 cm
 * off its laid state (test_vertical_loop). Derived here (statics of a
 * string under its own weight; docs/physics.md §7). */
static void weight_grid_stretch(weight_grid *g, double Tc, double EA)
{
    g->W[0] = 0.0;
    for (long i = 1; i <= g->m; i++)
        g->W[i] = g->W[i - 1] + g->dW[i - 1] / (1.0 + (Tc + g->W[i - 1]) / EA);
}

static void weight_grid_free(weight_grid *g)
{
    free(g->W);
    free(g->dW);
}

static double weight_at(const weight_grid *g, double s)
{
    double u = s / g->ds;
    if (u <= 0.0)
        return g->W[0];
    /* compared before the cast: a layout that does not close marches far
     * past the path's end (or to NaN), beyond what an integer holds */
    if (!(u < (double)g->m))
        return g->W[g->m];
    long i = (long)u;
    double f = u - (double)i;
    return (1.0 - f) * g->W[i] + f * g->W[i + 1];
}

/* lay n elements of unstretched length l0 under T(s) = Tc + W(s); returns
 * the path length consumed (the loop closes when it equals the path's length) */
static double march(const weight_grid *g, double EA, double l0,
                    double Tc, int n, double *s_nodes)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) {
        if (s_nodes)
            s_nodes[i] = s;
        /* stretch by the tension at the element's middle: one fixed-point
         * pass is enough since T varies slowly over one element */
        double T = Tc + weight_at(g, s + 0.5 * l0);
        double ds = l0 * (1.0 + T / EA);
        T = Tc + weight_at(g, s + 0.5 * ds);
        s += l0 * (1.0 + T / EA);
    }
    return s;
}

/* secant solve of f(x) = 0 from two guesses */
typedef double (*closure_fn)(double x, void *ctx);

static int secant(closure_fn f, void *ctx, double x0, double x1, double tol, double *root)
{
    double f0 = f(x0, ctx), f1 = f(x1, ctx);
    for (int it = 0; it < 60; it++) {
        if (fabs(f1) < tol) {
            *root = x1;
            return 0;
        }
        if (f1 == f0)
            break;
        double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = f(x1, ctx);
    }
    *root = x1;
    return fabs(f1) < 100.0 * tol ? 0 : 1;
}

typedef struct length_ctx {
    const bd_path *path;
    const weight_grid *g;
    double EA, Tc;
    int n;
} length_ctx;

static double length_misfit(double l0, void *vctx)
{
    length_ctx *c = vctx;
    return march(c->g, c->EA, l0, c->Tc, c->n, NULL) - c->path->length;
}

/* the takeup's level: force balance of the takeup pulley along its axis,
 *   F + (m_p + m_arc)·g·(ĝ·a) + (T_out·u_out − T_in·u_in)·a = 0,
 * with T_in, T_out at the ends of its wrap. The belt (and load) on the wrap,
 * m_arc, hangs on the pulley too: model-format.md's rule
 * T = force/((u_in − u_out)·a) leaves out both weights, which on a vertical
 * loop is several percent of the tension. */
static int takeup_level(const bd_model_def *def, const bd_path *path, const weight_grid *g,
                        int k, double EA, double *Tc)
{
    const bd_pulley_def *pd = &def->pulleys[k];
    const bd_path_segment *arc = bd_path_arc(path, k);
    const double *u_in, *u_out;
    bd_path_wrap_dirs(path, k, &u_in, &u_out);
    const double *a = pd->takeup.axis;
    double F = bd_table_eval(&pd->takeup.force, 0.0);
    bd_rest_load load = bd_layout_rest_load(def, path);
    double W_in = weight_at(g, arc->s0);
    double W_out = weight_at(g, arc->s0 + arc->length);
    /* the wrap's belt, unstretched (weight_grid_stretch) */
    double arc_mass = bd_rest_mass(path, &load, arc->s0, arc->s0 + arc->length)
                    / (1.0 + (*Tc + 0.5 * (W_in + W_out)) / EA);
    double gravity_pull = -(pd->mass + arc_mass) * def->gravity * a[1];
    double u_in_a = u_in[0] * a[0] + u_in[1] * a[1];
    double u_out_a = u_out[0] * a[0] + u_out[1] * a[1];
    double denom = u_out_a - u_in_a;
    if (fabs(denom) < 1e-6)
        return 1;
    *Tc = (-F - gravity_pull - W_out * u_out_a + W_in * u_in_a) / denom;
    return 0;
}

/* path with the takeup pulley k moved by q along its axis */
typedef struct shift_ctx {
    const bd_model_def *def;
    bd_model_def moved;
    bd_pulley_def *pulleys;
    int k;
    const weight_grid *g;
    double EA, l0, Tc;
    int n;
    bd_path path;
} shift_ctx;

static double shift_misfit(double q, void *vctx)
{
    shift_ctx *c = vctx;
    const bd_pulley_def *pd = &c->def->pulleys[c->k];
    c->pulleys[c->k].x = pd->x + q * pd->takeup.axis[0];
    c->pulleys[c->k].y = pd->y + q * pd->takeup.axis[1];
    bd_path_free(&c->path);
    bd_diag quiet;
    bd_diag_init(&quiet);
    int bad = bd_path_build(&c->moved, &c->path, &quiet);
    bd_diag_free(&quiet);
    if (bad)
        return 1e30;
    return march(c->g, c->EA, c->l0, c->Tc, c->n, NULL) - c->path.length;
}

/* the least stretch 1 + T/EA a belt is laid with: below it the at-rest
 * tension T(s) = Tc + W(s) (a takeup too weak, or an installed tension too
 * low, for the belt's weight) would crush the belt to under half its length,
 * which no belt does, and the layout would need 1/(1 + T/EA) times its
 * elements (a 185 m loop at 3 % took 80,000 and seconds to refuse) */
#define MIN_STRETCH 0.5

/* the most stretch 1 + T/EA a belt is laid with: a belt's strain is a
 * few per cent; at 100 % the tension is beyond any belt's strength, and
 * the unstretched elements would shrink without bound (an initial tension
 * of 2e13 N on EA 2e3 N made 6 nm elements, fuzz_model) */
#define MAX_STRETCH 2.0

/* a belt laid out of those bounds: refused with where and why (the
 * weight table's least and most tension, one scan) */
static int stretch_out_of_bounds(const weight_grid *g, double Tc, double EA, char *err,
                                 size_t errlen)
{
    long lo = 0, hi = 0;
    for (long i = 1; i <= g->m; i++) {
        if (g->W[i] < g->W[lo])
            lo = i;
        if (g->W[i] > g->W[hi])
            hi = i;
    }
    double T = Tc + g->W[lo];
    if (1.0 + T / EA < MIN_STRETCH) {
        snprintf(err, errlen, "could not lay the belt on its path: at rest its tension would be "
                 "%.4g N at s = %.4g m, a strain of %.0f %% with axial stiffness %.4g N (a belt "
                 "is not laid compressed by %.0f %% or more); the takeup or initial tension is "
                 "too low for the belt's weight",
                 T, (double)lo * g->ds, 100.0 * T / EA, EA, 100.0 * (1.0 - MIN_STRETCH));
        return 1;
    }
    T = Tc + g->W[hi];
    if (1.0 + T / EA > MAX_STRETCH) {
        snprintf(err, errlen, "could not lay the belt on its path: at rest its tension would be "
                 "%.4g N at s = %.4g m, a strain of %.3g %% with axial stiffness %.4g N (a belt "
                 "is not laid stretched by %.0f %% or more); the takeup or initial tension is "
                 "too high for the belt",
                 T, (double)hi * g->ds, 100.0 * T / EA, EA, 100.0 * (MAX_STRETCH - 1.0));
        return 1;
    }
    return 0;
}

int bd_layout_belt(const bd_model_def *def, const bd_layout_request *req, bd_layout *out,
                   char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    const bd_path *path = req->path;
    double EA = def->belt.axial_stiffness;
    weight_grid g;
    weight_grid_build(def, path, req->target_length, &g);
    int takeup = -1;
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].has_takeup && def->pulleys[i].takeup.type != BD_TAKEUP_FIXED) {
            takeup = i;
            break;
        }
    int rest = def->simulation.initial_state == BD_INITIAL_REST;
    double L = path->length;
    double Tc = 0.0, L_un;
    out->takeup = takeup;
    if (!rest && takeup >= 0) {
        /* the level and the stretch the weight's tension gives: a fixed
         * point, changing by ε² a pass */
        for (int pass = 0; pass < 3; pass++) {
            if (takeup_level(def, path, &g, takeup, EA, &Tc)) {
                snprintf(err, errlen, "pulleys[%d] '%s': takeup axis is perpendicular to the "
                         "belt's pull on the pulley; it cannot set the tension", takeup,
                         def->pulleys[takeup].name);
                weight_grid_free(&g);
                return 1;
            }
            weight_grid_stretch(&g, Tc, EA);
        }
        /* unstretched length of the belt under T(s) */
        L_un = 0.0;
        for (long i = 0; i < g.m; i++)
            L_un += g.ds / (1.0 + (Tc + 0.5 * (g.W[i] + g.W[i + 1])) / EA);
    } else if (!rest) {
        L_un = L / (1.0 + def->belt.initial_tension / EA);
        Tc = def->belt.initial_tension;
        weight_grid_stretch(&g, Tc, EA);
    } else {
        L_un = L;
        EA = INFINITY;   /* unstretched: elements are l0 */
    }
    if (!rest && stretch_out_of_bounds(&g, Tc, EA, err, errlen)) {
        weight_grid_free(&g);
        return 1;
    }
    int n = (int)lround(L_un / req->target_length);
    if (n < 8)
        n = 8;
    double l0 = L_un / n;
    out->n = n;
    out->level = Tc;

    if (!rest && takeup >= 0) {
        /* the takeup pulley moves so that the loop closes */
        shift_ctx c = {0};
        c.def = def;
        c.moved = *def;
        c.pulleys = bd_xcalloc((size_t)def->pulley_count, sizeof *c.pulleys);
        memcpy(c.pulleys, def->pulleys, (size_t)def->pulley_count * sizeof *c.pulleys);
        c.moved.pulleys = c.pulleys;
        c.k = takeup;
        c.g = &g;
        c.EA = EA;
        c.l0 = l0;
        c.Tc = Tc;
        c.n = n;
        double q;
        int bad = secant(shift_misfit, &c, 0.0, 0.01 * l0, 1e-10 * L, &q);
        /* the path at the solution (1e30: it could not be built) */
        if (shift_misfit(q, &c) >= 1e30)
            bad = 1;
        free(c.pulleys);
        if (bad) {
            bd_path_free(&c.path);
            snprintf(err, errlen, "could not lay the belt on its path: the takeup pulley '%s' "
                     "finds no position that closes the loop", def->pulleys[takeup].name);
            weight_grid_free(&g);
            return 1;
        }
        out->takeup_shift = q;
        out->path = c.path;
    } else {
        /* no takeup: the installed tension T0 (or none, at rest) is kept and
         * the unstretched element length found so the elements close the
         * loop (the weight's stretch makes it differ from L/(1+T0/EA)/n) */
        length_ctx c = {path, &g, EA, Tc, n};
        double l_fit;
        if (secant(length_misfit, &c, l0, l0 * 0.999, 1e-10 * L, &l_fit)) {
            snprintf(err, errlen, "could not lay the belt on its path");
            weight_grid_free(&g);
            return 1;
        }
        l0 = l_fit;
        bd_diag quiet;
        bd_diag_init(&quiet);
        int bad = bd_path_build(def, &out->path, &quiet);
        bd_diag_free(&quiet);
        if (bad) {
            snprintf(err, errlen, "could not lay the belt on its path (out of memory)");
            weight_grid_free(&g);
            return 1;
        }
    }
    out->l0 = l0;
    out->s = bd_xcalloc((size_t)n, sizeof *out->s);
    out->tension = bd_xcalloc((size_t)n, sizeof *out->tension);
    march(&g, EA, l0, Tc, n, out->s);
    for (int i = 0; i < n; i++) {
        double s_mid = 0.5 * (out->s[i] + (i + 1 < n ? out->s[i + 1] : out->path.length));
        out->tension[i] = rest ? 0.0 : Tc + weight_at(&g, s_mid);
    }
    weight_grid_free(&g);
    return 0;
}

void bd_layout_free(bd_layout *l)
{
    free(l->s);
    free(l->tension);
    bd_path_free(&l->path);
    memset(l, 0, sizeof *l);
}
