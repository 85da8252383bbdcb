/* The lumped (discrete) belt of seed 001 §4.1: 2D nodes joined by
 * Kelvin–Voigt elements and bending springs, penalty contact with pulley
 * shells and idlers, stick–slip friction. Its data behind sim->belt_data
 * and the functions its files share. */
#ifndef BD_LUMPED_H
#define BD_LUMPED_H

#include "belt/belt.h"

/* a wrap's sector, the nodes its contact tests (pulley_contact.c) */
typedef struct bd_wrap_sector {
    double mid[2];          /* unit vector from the centre to the arc's middle */
    double cos_limit;       /* a node is in the sector when cos(angle to mid) ≥ this */
    double reach;           /* m, and nearer the centre than this */
    int node_max;           /* the most nodes the sector can hold */
} bd_wrap_sector;

/* the lumped belt's compiled data (in the model, behind model->belt_model) */
typedef struct bd_lumped_model {
    double k_axial;        /* N/m = EA/l0 */
    double c_axial;        /* N·s/m dashpot of one element */
    double k_bend;         /* N·m/rad = EI/l0 */
    double k_contact;      /* N/m penalty stiffness of a node on a shell or idler */
    /* whether an idler may press on the quintic running line, and at its
     * contact radius (the discrete belt; build.c, idler_contact.c): else on
     * the quadratic line round each node, at its radius (the rfe belt) */
    int quintic_allowed;
    bd_wrap_sector *sectors;   /* [pulley_count] */
} bd_lumped_model;

/* the arc of a pulley one element may span before the build warns
 * (build.c) */
#define BD_WRAP_WARN_DEG 60.0

/* the contact of the belt with one pulley's shell (pulley_contact.c) */
typedef struct bd_wrap_contact {
    /* step: the node nearest the arc's middle, where the next step's
     * search for the sector's nodes starts */
    int anchor;
    /* step (wrap coupling): J, Σ f_n²/(2k_c) of its contacts this step
     * (pulley_contact.c, the springs' energy) */
    double spring_e;
    /* step scratch of the contact solve [its sector's node_max]: the
     * candidate nodes, after the solve those the shell pushes or whose
     * friction carries a wrapped arc's share */
    int *c_node;
    double *c_fn0;          /* N, normal force were the carriage not to accelerate */
    double *c_g;            /* kg, its growth with the carriage's acceleration */
    double *c_arc;          /* N, the arcs' pressure its friction carries */
    /* step (forces phase) [node_max]: N, the wrapped arcs' pressure each
     * node of the run carries, by its place in the run (wrap_elements.c
     * writes, gather reads) */
    double *run_arc;
    double *c_tx, *c_ty;    /* unit direction of its friction: the belt's
                               at the node (positive in the wrap sense) */
    double *c_nx, *c_ny;    /* unit normal of the shell (outward, radial) */
    double *c_f;            /* N, friction (+ = retards the belt) */
    int *c_state;           /* sticking, slipping forward or back, off */
    int *c_press;           /* 1: the shell pushes it (f_n > 0) */
    int contact_count;
    /* step (forces phase): the sector's run of nodes, first and count */
    int run_first, run_count;
    /* step (forces phase): what the wrapped elements' arcs press on the
     * shell directly (wrap_elements.c), N, and its dashpot part */
    double react[2], react_d[2];
} bd_wrap_contact;

/* an element that runs round a pulley this step (wrap_elements.c): its
 * length's gradients at its start node i and end node j (its tension and
 * the tension's dashpot part are in sim->tension[e] and td[e]) */
typedef struct bd_wrapped_element {
    int e;
    double gi[2], gj[2];
} bd_wrapped_element;

/* the nodes an idler presses on, at most (idler_contact.c) */
#define BD_TOUCH_NODES 6
/* step (supports phase): where an idler's roll meets the belt's running
 * line (idler_contact.c), found for every idler before any force */
typedef struct bd_idler_touch {
    int node[BD_TOUCH_NODES];
    double w[BD_TOUCH_NODES];
    int count;       /* of nodes: 3 (quadratic line) or 6 (quintic) */
    double d;        /* m, from the roll's centre to the contact point */
    double n[2];     /* that direction */
} bd_idler_touch;

/* the lumped belt's state (behind sim->belt_data) */
typedef struct bd_lumped {
    bd_wrap_contact *wraps;    /* [pulley_count] */
    /* step (forces phase): element geometry */
    double *ux, *uy;       /* [n] unit vector of element e */
    double *len;           /* [n] m current length of element e */
    double *td;            /* [n] N dashpot part of its tension */
    /* step (integrate): node i's mid-step power of the non-conservative
     * forces (W) and twice its kinetic energy (J), summed in node order */
    double *pw, *ek;       /* [n] */
    /* a cache for the Eulerian s of elements, not state */
    int *seg_hint;         /* [n] segment guess */
    /* step (forces phase): the elements wrapped on a pulley, at most the
     * sectors' node counts together; wrap_mark[e] is set while e is listed */
    bd_wrapped_element *wrapped;
    int wrapped_count;
    unsigned char *wrap_mark;   /* [n] */
    bd_idler_touch *touch; /* [idler_count] */
} bd_lumped;

static inline bd_lumped *bd_lumped_of(const bd_sim *sim)
{
    return (bd_lumped *)sim->belt_data;
}

static inline const bd_lumped_model *bd_lumped_model_of(const bd_sim *sim)
{
    return (const bd_lumped_model *)sim->model->belt_model;
}

/* m, the height the material's weight is measured from: the discharge
 * pulley's centre as laid. Material lands at the feed with the potential
 * m·g·(y − y_d), booked as input, and leaves the belt at the discharge
 * with about none, so its weight's work on the belt between feed and
 * discharge is all the input it brings and the dissipated energy only
 * grows (docs/physics.md §9) */
static inline double bd_lumped_material_datum(const bd_sim *sim)
{
    return sim->model->material_mpl > 0.0
               ? sim->pulleys[sim->model->discharge_pulley].m->y0 : 0.0;
}

/* build.c */
int bd_lumped_build(bd_sim *sim, bd_diag *diag);
/* the same, the state and the compiled data allocated state_size and
 * model_size bytes (zeroed): a belt that extends the lumped one (belt/rfe)
 * keeps bd_lumped and bd_lumped_model as its first members */
int bd_lumped_build_sized(bd_sim *sim, bd_diag *diag, size_t state_size, size_t model_size);
void bd_lumped_clone_sized(bd_sim *dst, const bd_sim *src, size_t state_size);
void bd_lumped_free(bd_sim *sim);
void bd_lumped_free_model(bd_model *model);
void bd_lumped_clone(bd_sim *dst, const bd_sim *src);
double bd_lumped_stable_step(const bd_sim *sim, bd_time_step_limit *limit);
/* idler_turn.c: whether the belt's default element is halved over
 * sharply turning idlers (the node-based belts: discrete and rfe); the
 * chord of 30° of the smallest pulley; φ (rad) and v/c of every idler
 * set of such a belt without bending stiffness at rest (0 where none;
 * returns whether any was found); the default element length, *refined
 * when halved for the idlers' turn (phi may be NULL for other belts) */
int bd_lumped_turns_refine(const bd_model_def *def);
/* each idler set's span at rest on its supports (the `static` layout of
 * the string, whatever the start and the formulation): the mean tension,
 * N; belt and load, kg/m; cos of its slope; the idlers' spacing, m. All 0
 * for a set without idlers; returns whether any was found */
typedef struct bd_span_rest {
    double tension, mass_per_length, cos_slope, spacing;
} bd_span_rest;
int bd_lumped_span_rest(const bd_model_def *def, const bd_path *path, bd_span_rest *out);
/* the index of the pulley with the smallest radius (the first of equals) */
int bd_lumped_smallest_pulley(const bd_model_def *def);
double bd_lumped_pulley_element(const bd_model_def *def);
int bd_lumped_idler_turns(const bd_model_def *def, const bd_path *path, double *phi,
                          double *voc);
/* the default element: *refined 1 where halved for the idlers' turns, 2
 * where the rfe belt's is shortened for its polygon on the pulleys */
double bd_lumped_default_element(const bd_model_def *def, const bd_path *path, const double *phi,
                                 int *refined);
/* polygon.c: the running resistance's scale at speed v (N), as
 * sim/running_law.c sums it in magnitude, from the definition and the
 * path: each span's idlers carrying its whole length */
double bd_lumped_resistance_scale(const bd_model_def *def, const bd_path *path, double v);
/* polygon.c: the rfe belt's running force lost to its elements' polygon on
 * the pulleys, as a share of the running resistance, at element l0 (NaN
 * without idlers or load to resist); and the element no longer than l0
 * that keeps it within 1 % */
double bd_lumped_polygon_share(const bd_model_def *def, const bd_path *path, double l0);
/* the share the default element may lose to its polygon: a third of the
 * torture test's 3 % */
#define BD_POLYGON_SHARE_MAX 0.01
double bd_lumped_polygon_element(const bd_model_def *def, const bd_path *path, double l0);
/* the same from the definition and its path alone (the estimate, tests) */
double bd_lumped_default_element_on(const bd_model_def *def, const bd_path *path,
                                    int *refined);
void bd_lumped_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out);
double bd_lumped_support_inertia(const bd_sim *sim, double R, double J);

/* forces.c: elastic, damping, bending, gravity forces on nodes; energy */
void bd_lumped_forces(bd_sim *sim);
void bd_lumped_forces_runs(bd_sim *sim, const int *first, const int *count, int runs);
void bd_lumped_integrate(bd_sim *sim, double *ke, double *w_nc);
/* nodes first .. first + count − 1 (no wrap round the loop) to t + Δt as
 * bd_lumped_integrate moves them, each node's mid-step power and twice its
 * kinetic energy into pw[i] and ek[i] (not summed) */
void bd_lumped_advance_range(bd_sim *sim, int first, int count);
double bd_lumped_elastic_energy(const bd_sim *sim);
double bd_lumped_potential(const bd_sim *sim);

/* wrap_elements.c: elements that run round a pulley */
void bd_lumped_wrap_elements(bd_sim *sim);
void bd_lumped_wrap_forces(bd_sim *sim);
double bd_lumped_wrap_elastic_correction(const bd_sim *sim);

/* pulley_contact.c / idler_contact.c */
void bd_lumped_sector_init(bd_sim *sim, int pulley, bd_wrap_sector *S);
void bd_lumped_sector_anchor(bd_sim *sim, int pulley, bd_wrap_contact *W);
int bd_lumped_find_sector(const bd_sim *sim, const bd_pulley_body *p, const bd_wrap_contact *W,
                          int *first, int *count);
int bd_lumped_in_sector(const bd_sim *sim, const bd_pulley_body *p, int k);
void bd_lumped_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque);
void bd_lumped_idlers(bd_sim *sim);
/* the same for the idlers listed, whose trackers the caller has updated
 * (the others the belt formulation moves itself: belt/rfe/sections.c) */
void bd_lumped_idlers_listed(bd_sim *sim, const int *list, int count);
/* idler i's contact let go: its spring's energy to 0 (booked as the
 * contact books it), no torque */
void bd_lumped_idler_release(bd_sim *sim, int i);
/* how far the running line, quintic or quadratic, cuts the corner of the
 * free lines over a roll that turns the belt by phi (idler_contact.c) */
double bd_lumped_line_corner(double phi, double l0, int quintic);

/* material.c: feed and discharge */
void bd_lumped_material(bd_sim *sim);

/* tracker.c: points fixed on the path, the tension field */
void bd_tracker_init(const bd_sim *sim, bd_tracker *tr, double s);
void bd_tracker_update(const bd_sim *sim, bd_tracker *tr);
double bd_tracker_speed(const bd_sim *sim, const bd_tracker *tr);
void bd_lumped_sample(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out);
double bd_lumped_element_s(const bd_sim *sim, int e);
double bd_lumped_element_speed(const bd_sim *sim, int e);
double bd_lumped_element_strain(const bd_sim *sim, int e);
double bd_lumped_node_speed(const bd_sim *sim, int i);

#endif
