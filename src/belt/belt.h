/* The belt-formulation interface: what the one step loop (sim/step.c) asks
 * of a belt, whichever it is. Each formulation lives in a folder of its own
 * below src/belt/ and fills one bd_belt_ops table (as SUNDIALS' stepper
 * modules do); bd_belt_ops_for picks it from the model. Adding a
 * formulation: docs/architecture.md.
 *
 * The step loop calls, in this order, every step:
 *   forces     → the belt's own forces at t (elements, bending, gravity,
 *                distributed loads) into fx/fnx, and the element tensions
 *                with their extremes (bd_tension_extremes)
 *   wrap       → at each pulley, after the parts' torques: the belt–pulley
 *                coupling, its forces on the belt, and what the pulley feels
 *                (p->alpha, torque_friction, f_axis, fnc_axis)
 *   supports   → contacts after the wraps (idlers); may be NULL
 *   integrate  → nodes to t + Δt, adding their kinetic energy (at mid step)
 *                and the work of the non-conservative forces
 *   after_parts→ what follows the pulleys' and carriages' motion (a takeup
 *                changing element lengths); may be NULL
 *   material   → material lands, rides and leaves
 * and its sensors read the belt only through point_update and sample. */
#ifndef BD_BELT_H
#define BD_BELT_H

#include "model/system.h"

/* the node after and before node i of a closed belt of n nodes */
static inline int bd_node_next(int i, int n)
{
    return i + 1 == n ? 0 : i + 1;
}

static inline int bd_node_prev(int i, int n)
{
    return i == 0 ? n - 1 : i - 1;
}

/* what a sensor reads at a point of the belt */
typedef struct bd_belt_sample {
    double x, y;      /* m, where the belt is at the point (its foot on the
                         element over it) */
    double tension;   /* N, interpolated between element midpoints */
    double speed;     /* m/s along the direction of travel */
} bd_belt_sample;

/* what the formulation would build from a model, estimated before anything
 * is allocated (sim/estimate.c): cheap, from the definition and the path */
typedef struct bd_belt_estimate {
    double element_length;   /* m, the length its build aims at */
    double nodes, idlers;    /* how many (idlers as bodies; 0 when spread) */
    double node_bytes;       /* bytes per node at the build's peak */
    double idler_bytes;      /* bytes per idler body */
    double stable_step;      /* s, of elements element_length long */
    double rate;             /* (node + idler)-steps per second, measured */
    double stepped;          /* what a step costs in those units, if fewer than
                                nodes + idlers (long sections); 0: not */
    /* the key and value that set the node count, for messages, when it is
     * not belt.element_length ("belt.span_element_length: 1e-07 m"), else "" */
    char element_what[96];
    char element_advice[64]; /* what to change ("a larger wrap_element_angle_deg"), or "" */
} bd_belt_estimate;

/* a long section costs a step about what this many free elements do, the
 * idlers it carries nothing (sim/estimate.c: the rfe belt's cement plant,
 * 9746 elements, 207 sections standing for 9575 and 1130 idlers, stepped
 * its 40 s start in 39.4-40.5 s at b345e68, 52 µs a step, about 830
 * (node + idler)-steps at its rate; its 171 free elements, 3 per section
 * and the 20 idlers outside them make 812) */
#define BD_SECTION_STEP_ELEMENTS 3.0

/* what a belt whose topology varies (belt/rfe: long sections) did */
typedef struct bd_belt_topology {
    int windows;              /* where long sections may stand */
    double window_length;     /* m, their length together */
    int dof_now, dof_min, dof_max;   /* the belt's degrees of freedom */
    long joined, left;        /* elements tied into a section, freed from one */
    double lost_J, gained_J;  /* the energy tying booked as dissipated, as input */
    /* the kink at the sections' ends (belt/rfe/sections.c): what the kept
     * spans' kinks cost, as a share of the whole belt's running
     * resistance, and the spans left free for theirs */
    double kink_share;
    int kink_free_spans;
} bd_belt_topology;

typedef struct bd_belt_ops {
    const char *name;          /* as model-format.md `belt.formulation` */
    const char *description;   /* for `beltdyn check` */
    int node_dof;              /* degrees of freedom per node */
    /* its layout (the string's path, `static` or `rest`) not its own
     * equilibrium: how long (s of the step's clock) its own fast modes take
     * to settle there, which the build lets them before t = 0
     * (bd_sim_settle); NULL when laid in its own equilibrium */
    double (*settle_time)(const bd_sim *sim);
    const char *dof_text;      /* how `check` counts the degrees of freedom */

    /* build the belt on the model's path: nodes, elements, the parts'
     * coupling data, probes and feed point; 0 ok, else problems in diag */
    int (*build)(bd_sim *sim, bd_diag *diag);
    /* free the state behind sim->belt_data; free the compiled data behind
     * model->belt_model */
    void (*free)(bd_sim *sim);
    void (*free_model)(bd_model *model);
    /* dst->belt_data as a deep copy of src's, for a new run on the same
     * model; dst owns each pointer as soon as it is set (a jump out of
     * memory half way leaves nothing shared for bd_sim_free) */
    void (*clone)(bd_sim *dst, const bd_sim *src);
    /* largest stable time step, and what limits it */
    double (*stable_step)(const bd_sim *sim, bd_time_step_limit *limit);
    /* what build would make of def on path (before it allocates) */
    void (*estimate)(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out);

    /* the step's phases (see above) */
    void (*forces)(bd_sim *sim);
    void (*wrap)(bd_sim *sim, bd_pulley_body *p, double external_torque);
    void (*supports)(bd_sim *sim);
    void (*integrate)(bd_sim *sim, double *ke, double *w_nc);
    /* velocities of its own beyond the nodes' vx, vy (an element's spin),
     * at rest at t: after the forces, the half-step values −h·acceleration
     * with h = Δt/2, or 0 with h = 0 (sim/step.c, sim/stabilize.c); and
     * whatever the belt keeps of past speeds, restarted from vx, vy; may
     * be NULL */
    void (*rest_velocities)(bd_sim *sim, double h);
    void (*after_parts)(bd_sim *sim);
    void (*material)(bd_sim *sim);

    /* energy: the belt's potential (elastic, gravity of belt and load),
     * the elastic energy alone, and what the wrap of pulley p stores
     * (NULL: the forces phase sums it into bd_energy `springs`) */
    double (*potential)(const bd_sim *sim);
    double (*elastic_energy)(const bd_sim *sim);
    double (*wrap_energy)(const bd_sim *sim, const bd_pulley_body *p);
    /* J += the supports' inertia reflected to a pulley of radius R */
    double (*support_inertia)(const bd_sim *sim, double R, double J);

    /* sensors: a point fixed on the path at s, kept current; the belt there */
    void (*point_init)(const bd_sim *sim, bd_tracker *tr, double s);
    void (*point_update)(const bd_sim *sim, bd_tracker *tr);
    void (*sample)(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out);
    /* the tension field: element e's midpoint path coordinate (Eulerian),
     * its speed along the belt, its strain */
    double (*element_s)(const bd_sim *sim, int e);
    double (*element_speed)(const bd_sim *sim, int e);
    double (*element_strain)(const bd_sim *sim, int e);
    /* node i's velocity along the belt there, m/s */
    double (*node_speed)(const bd_sim *sim, int i);

    /* its state made whole for reading from outside the step: a belt that
     * keeps some of it in a lumped form within the step (the rfe belt's
     * long sections place their elements lazily) writes it out; called
     * before and after a step that books energy, after bd_sim_step and
     * after a step that failed; may be NULL */
    void (*sync)(bd_sim *sim);
    /* events the formulation recorded in the step, said after the run */
    void (*report_events)(bd_sim *sim);
    /* its variable topology so far; NULL: it has none */
    void (*topology)(const bd_sim *sim, bd_belt_topology *out);
    /* it notes idler stations the belt lifts off (bd_lift_off_note) */
    int records_lift_off;
} bd_belt_ops;

/* the formulation of f, or NULL for a value not in bd_formulation */
const bd_belt_ops *bd_belt_ops_for(bd_formulation f);

/* the formulations (one folder each) */
extern const bd_belt_ops bd_lumped_ops;   /* belt/lumped: seed 001 */
extern const bd_belt_ops bd_axial_ops;    /* belt/axial: seed 004 */
extern const bd_belt_ops bd_moving_node_ops; /* belt/moving_node: seed 003 */
extern const bd_belt_ops bd_rfe_ops;      /* belt/rfe: seed 000 */

/* shared by the formulations' builds (belt/common.c) */
/* probes and the feed point: points fixed on the path */
void bd_setup_probes_and_feed(bd_sim *sim);
/* idlers of set k that fit its span evenly (0 on a vertical span, with a
 * warning) and their actual spacing */
int bd_idler_set_layout(bd_sim *sim, int k, double *spacing);
/* 1: span `span` starts vertical (no idlers can stand on it) */
int bd_span_vertical(const bd_path *path, int span);
/* the rule it follows, without a sim: idler set k's count on its span
 * (none on a vertical one) and the spacing that fits the span evenly */
int bd_idler_count(const bd_model_def *def, const bd_path *path, int k, double *spacing);
/* the element tensions' extremes of this step into sim->step_tension_*
 * (the forces phase of every formulation ends with it) */
void bd_tension_extremes(bd_sim *sim);
/* the force on the belt at the feed point along the travel, N: the
 * landing material's momentum flux (`landing`; the lumped belt shares the
 * momentum in its material phase instead) and, with design.secondary:
 * individual, the skirts (`loaded`: material lies at the feed point). v m/s
 * the belt's speed there, m kg the mass the force acts on. */
double bd_feed_force(const bd_sim *sim, double v, double m, int landing, int loaded);
/* the first element whose tension is value (an extreme of this step): the
 * one a scan taking only strictly larger values would keep */
int bd_tension_element(const bd_sim *sim, double value);
/* a point fixed on the path at s (taken modulo the loop): its place and
 * direction, and the node with the largest initial s not beyond it in
 * tr->element (the formulation's point_init then finds the element) */
void bd_belt_point_place(const bd_sim *sim, bd_tracker *tr, double s);
/* tension at a point: element tensions belong to element midpoints,
 * interpolated linearly between the two nearest */
double bd_belt_point_tension(const bd_sim *sim, const bd_tracker *tr);
/* where the belt is at a point: the nodes of the element over it,
 * interpolated */
void bd_belt_point_position(const bd_sim *sim, const bd_tracker *tr, double *x, double *y);

/* belts whose nodes are stations fixed on the path (axial, moving_node),
 * their speed along it in vx (belt/common.c) */
/* a point between the two stations around it; len[e] is element e's
 * length along the path */
void bd_station_point_init(const bd_sim *sim, bd_tracker *tr, double s, const double *len);
/* the stations stay where they are: nothing to follow */
void bd_station_point_update(const bd_sim *sim, bd_tracker *tr);
/* place, tension and speed interpolated between the two stations */
void bd_station_sample(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out);
/* element e's midpoint on the path (len as above) */
double bd_station_element_s(const bd_sim *sim, int e, const double *len);
/* element e's speed: the mean of its nodes'; node i's: vx */
double bd_station_element_speed(const bd_sim *sim, int e);
double bd_station_node_speed(const bd_sim *sim, int i);
/* the wraps store nothing of their own (their elastic energy, if any, is
 * the belt's elements') */
double bd_station_wrap_energy(const bd_sim *sim, const bd_pulley_body *p);
/* the idlers' rotating mass is in the node masses already: J unchanged */
double bd_station_support_inertia(const bd_sim *sim, double R, double J);

#endif
