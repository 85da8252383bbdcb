/* The moving-node belt (docs/physics.md §14; seed 003's spatial
 * description applied to a conveyor belt).
 *
 * Its nodes are points fixed in space where the physics is: the tangent
 * points and points on every wrap arc, every idler station, the feed point
 * and the probes, with span nodes between. The belt's material flows
 * through them. Node i carries
 *   - the belt's speed along the path relative to the node, v_i (sim->vx):
 *     the material velocity of seed 003 §3 (a node on a takeup carriage
 *     moves with it; v is then the speed relative to the node);
 *   - through it the belt flows at v_i/λ_i of unstretched length per
 *     second (λ the stretch; seed 003 eq 2, the spatial node whose
 *     material coordinate changes while it stands still, §4);
 *   - on a span, a transverse displacement w_i along the span's normal
 *     (sim->vy its rate): sag, lift-off, bending where EI > 0.
 * Element e (node e → e+1) holds the unstretched belt ΔX_e, which gains
 * what flows in at node e and loses what flows out at node e+1; its strain
 * is ε_e = l_e/ΔX_e − 1 (geometrically exact,
 * l_e its length in space). Arc nodes lie on their pulley: no transverse
 * freedom, a normal pressure from tension, v²κ and weight, stick or slip.
 *
 * The axial equations are solved implicitly (trapezoidal, β = 1/4) along
 * the whole loop together with every pulley's rotation (solve.c), so the
 * short wrap elements set no time step; the transverse motion is explicit. */
#ifndef BD_MOVING_NODE_H
#define BD_MOVING_NODE_H

#include <math.h>

#include "belt/belt.h"
#include "belt/load_fronts.h"

/* what stands at a node */
enum { BD_MN_FREE = 0,   /* span node between supports: transverse freedom */
       BD_MN_IDLER = 1,  /* span node on an idler: lifts off, or rests */
       BD_MN_ARC = 2 };  /* on a pulley's wrap (tangent points included) */

/* contact state of an arc node, kept from step to step */
enum { BD_MN_STICK = 0, BD_MN_SLIP_POS = 1, BD_MN_SLIP_NEG = 2, BD_MN_OFF = 3 };

/* a movable pulley's share in the element lengths: elements
 * first .. first+count−1 (mod n) of each stretch change their length in
 * space by dsq_e·q (compiled) */
typedef struct bd_mn_stretch {
    int first, count;
} bd_mn_stretch;

typedef struct bd_mn_pulley {
    int first, count;          /* its arc nodes, tangent points included */
    bd_mn_stretch in, out;     /* movable: the span stretches that follow it */
} bd_mn_pulley;

/* compiled (in the model, behind model->belt_model) */
typedef struct bd_mn_model {
    /* nodes [n] */
    unsigned char *kind;      /* BD_MN_FREE, _IDLER, _ARC */
    int *pulley;              /* arc node: its pulley, else −1 */
    double *nx, *ny;          /* span: unit normal (w > 0 away from the
                                 idlers); arc: unit normal to the centre */
    double *arc_len;          /* arc node: m of arc it stands for */
    double *rolling;          /* idler node: rolling-resistance coefficient */
    double *idler_mass;       /* idler node: rotating mass I/r², kg */
    double *belt_mass;        /* kg of belt in its cell */
    double *inv_cell;         /* 1/m, over its cell's length (half of each
                                 element beside it) */
    double *mx, *my;          /* m per m of carriage travel (movable) */
    int *mover;               /* the movable pulley moving it, or −1 */
    double *x0, *y0;          /* m, position at q = 0, w = 0 */
    /* elements [n] */
    double *ds0;              /* m, its length along the path at q = 0 */
    double *dsq;              /* m/m: ds/dq of the movable pulley moving it */
    int *eq;                  /* that pulley, or −1 */
    double *k;                /* N/m, EA/ΔX at rest (the implicit part) */
    double *c;                /* N·s/m, Kelvin–Voigt dashpot (seed 001 eq 4.3) */
    unsigned char *on_arc;    /* element on a wrap (no transverse freedom) */
    double *radius;           /* arc element: its pulley's radius */
    double *kw;               /* span element: half the path's turn over it,
                                 rad, + towards the nodes' normal (a
                                 vertical curve; 0 on a straight span) */
    bd_mn_pulley *pulleys;    /* [pulley_count] */
    double tension_bound;     /* N, the tension the transverse step allows */
    double wave_speed;        /* m/s, √(EA/m') of the empty belt */
    int feed_node;            /* node at the feed point, −1 = none */
    int first_arc;            /* the first arc node (the transverse solve's
                                 walk round the loop starts there) */
    int *idler_nodes;         /* the idler nodes, idler_node_count of them */
    int idler_node_count;
} bd_mn_model;

/* state (behind sim->belt_data) */
typedef struct bd_mn {
    double *w;                /* [n] step (integrate): m transverse, span nodes */
    double *dX;               /* [n] step (integrate): m unstretched in element e */
    double *len;              /* [n] step (forces): m, element length in space */
    double *cos_e, *sin_e;    /* [n] step (forces): its direction in its span */
    double *td;               /* [n] step (forces): N, the dashpot's part */
    double *tdw;              /* [n] step (forces): N, the dashpot on the
                                 span's transverse stretching (forces.c) */
    double *f_grav;           /* [n] N, weight along the path (material phase) */
    double *f_norm;           /* [n] N, weight along the normal (material phase) */
    double *normal;           /* [n] step (forces): N, pulley or idler support */
    double *vnew;             /* [n] step (supports): v at t + Δt/2 */
    double *rhs;              /* [n] scratch of the solve */
    double *p0, *qa, *qb;     /* [n] scratch of the solve (qa, qb also of
                                 forces: the convective term) */
    double *cp;               /* [n] scratch: the Thomas sweep (also of
                                 forces: bending; of integrate: the flux) */
    double *fr;               /* [n] step (supports): N, pulley friction on node i */
    /* [n] step (forces): the transverse solve (forces.c): ẇ at t + Δt/2,
     * the pull across without the Coriolis term, 1 where ẇ is set (an
     * arc node, an idler node held on its idler), and its sweep's scratch */
    double *wdn, *gw, *pin, *sweep_c, *sweep_d;
    double *kap;              /* [n] step (forces): kg/s, κ_e = ρ_e·v̄_e */
    double *frg;              /* [3n] scratch: a stuck node's friction per pulley speed */
    int *frp;                 /* [3n] scratch: ... and which pulleys */
    int *run_prev, *run_next; /* [n] scratch: a stuck node's stuck neighbours
                                 across the runs beside it */
    double *omega;            /* [pulley_count] scratch: ω⁺ of the solve */
    double *q_seen;           /* [pulley_count] step (after parts): m, the carriage
                                 travel the geometry follows, summed step by step
                                 (the run's own q restarts at 0 after
                                 stabilization; the belt's lengths must not) */
    double *ca, *cb;          /* [n] step (supports): the solve's a_e, b_e */
    double *cna, *cnb, *cnc;  /* [n] their numerical parts, on Δv⁺, Δv⁻, Δv⁻⁻
                                 (solve.c) */
    double *vold;             /* [n] step (integrate): v at t − 3Δt/2 */
    double coef_dt;           /* s, the last step's (0 before the first) */
    int four_level;           /* wrap elements on the four-level rule now */
    unsigned char *contact;   /* [n] step (supports): BD_MN_STICK .. OFF */
    double *Q;                /* [pulley_count] step (wrap): external torque */
    double *A;                /* [pulley_count²] scratch: the pulleys' system */
    double *b;                /* [pulley_count] scratch */
    double grav_work;         /* J, work of gravity on the flowing belt so far */
    bd_load_fronts fronts;    /* the loaded region (belt/load_fronts.h) */
    /* stats, said after the run */
    long solve_fallbacks;     /* steps whose contact set did not settle */
    long liftoff_steps;       /* node-steps with an arc node off its pulley */
    double liftoff_first_t;
    int liftoff_first_node;
} bd_mn;

static inline bd_mn *bd_mn_of(const bd_sim *sim)
{
    return (bd_mn *)sim->belt_data;
}

static inline const bd_mn_model *bd_mn_model_of(const bd_sim *sim)
{
    return (const bd_mn_model *)sim->model->belt_model;
}

static inline bd_mn_model *bd_mn_model_build(bd_sim *sim)
{
    return (bd_mn_model *)sim->own->belt_model;
}

/* element e's length along its path now: at q = 0, plus its share of
 * the carriage travel the belt has seen (forces.c, integrate.c) */
static inline double bd_mn_element_ds(const bd_mn_model *mm, const bd_mn *mn, int e)
{
    double ds = mm->ds0[e];
    if (mm->eq[e] >= 0)
        ds += mm->dsq[e] * mn->q_seen[mm->eq[e]];
    return ds;
}

/* element e's length in space and its direction against the path (cos,
 * sin): on a wrap its length along the arc; on a span the chord between
 * its nodes' offsets w, which in a vertical curve shortens as the belt
 * moves towards the centre of curvature, by kw·(w_e + w_j) — the turn
 * over the element times its mean offset (plane geometry: an arc of
 * radius R − w is (1 − w/R) as long); its derivative is the pull T·Δθ
 * across. forces.c takes the tension from it, integrate.c the elastic
 * energy, so the energy booked is the forces' own. */
static inline double bd_mn_element_length(const bd_mn_model *mm, const bd_mn *mn, int e, int n,
                                          double *cs, double *sn)
{
    double ds = bd_mn_element_ds(mm, mn, e);
    *cs = 1.0;
    *sn = 0.0;
    if (mm->on_arc[e])
        return ds;
    int j = bd_node_next(e, n);
    double dw = mn->w[j] - mn->w[e], dl = ds - mm->kw[e] * (mn->w[e] + mn->w[j]);
    double l = sqrt(dl * dl + dw * dw);
    *cs = dl / l;
    *sn = dw / l;
    return l;
}

/* layout.c: the nodes on the path */
void bd_mn_layout_fill(bd_sim *sim);
/* the layout's node count (a double: the estimate refuses counts past an
 * int before the build asks), and in *arc_nodes (may be NULL) those on
 * the wraps */
double bd_mn_layout_count(const bd_model_def *def, const bd_path *path, double *arc_nodes);
double bd_mn_span_target(const bd_model_def *def, const bd_path *path, int span);

/* build.c */
int bd_mn_build(bd_sim *sim, bd_diag *diag);
void bd_mn_free(bd_sim *sim);
void bd_mn_free_model(bd_model *model);
void bd_mn_clone(bd_sim *dst, const bd_sim *src);
double bd_mn_stable_step(const bd_sim *sim, bd_time_step_limit *limit);
void bd_mn_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out);
void bd_mn_node_load(bd_sim *sim, int i);

/* forces.c */
void bd_mn_forces(bd_sim *sim);

/* solve.c */
void bd_mn_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque);
void bd_mn_solve(bd_sim *sim);

/* integrate.c */
void bd_mn_integrate(bd_sim *sim, double *ke, double *w_nc);
void bd_mn_rest_velocities(bd_sim *sim, double h);
void bd_mn_takeup_geometry(bd_sim *sim);
void bd_mn_material(bd_sim *sim);
double bd_mn_potential(const bd_sim *sim);
double bd_mn_elastic_energy(const bd_sim *sim);

#endif
