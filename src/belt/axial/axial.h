/* The axial (1D) belt (docs/physics.md §11): nodes are stations fixed on
 * the path; each carries the belt's displacement u along the path (vx
 * holds its velocity, fx its force; vy, fy stay 0). Element e joins node e
 * to e+1. Pulleys act on one node each through the seed-004 law. Its data
 * behind sim->belt_data and the functions its files share. */
#ifndef BD_AXIAL_H
#define BD_AXIAL_H

#include "belt/belt.h"
#include "belt/load_fronts.h"
#include "laws/belt_pulley_law.h"
#include "laws/rolling.h"


/* what the axial belt keeps of each pulley: compiled (in the model) */
typedef struct bd_axial_pulley {
    int node;               /* the belt node on its wrap */
    double c_in, c_out;     /* u_in·a, u_out·a: spans along the takeup axis */
    bd_bpl law;             /* seed-004 law of its wrap */
} bd_axial_pulley;

/* ... and as it runs (in the state) */
typedef struct bd_axial_pulley_state {
    int slack_warned;       /* stats: a belt end lost tension (recorded once) */
    int slack_arriving;     /* it was the arriving end */
    double slack_t;         /* s, when */
    double slack_tension;   /* N, its tension then */
} bd_axial_pulley_state;

/* the axial belt's compiled data (in the model, behind model->belt_model) */
typedef struct bd_axial_model {
    double *k;          /* [n] N/m, EA/l0 of element e */
    double *c;          /* [n] N·s/m, its dashpot */
    double *l0;         /* [n] m, its unstretched length */
    double *s_len;      /* [n] m, its length along the initial path */
    bd_axial_pulley *pulleys;   /* [pulley_count] */
    int feed_node;      /* node at the feed point, -1 = none */
    double min_mass;    /* kg, lightest node without material */
    /* the nodes whose share of a span with idlers lies in a vertical curve
     * (build.c curve_turn): there the idlers' rolling resistance has a part
     * that follows the tension, rr·T/R per metre, kr·T on the node */
    int curve_count;
    int *curve_node;    /* [curve_count] */
    /* [curve_count] -, the idlers' normal force (kn) and rolling
     * resistance (kr) per newton of tension, + convex (presses), − concave */
    double *curve_kn, *curve_kr;
} bd_axial_model;

/* the axial belt's state (behind sim->belt_data) */
typedef struct bd_axial {
    double *u;          /* [n] step (integrate): m displacement along the path */
    double *gap;        /* [n] step (after parts): m, l − l0 of element e at u = 0 */
    double *gap_rate;   /* [n] step (after parts): m/s its rate (takeup motion) */
    double *td;         /* [n] step (forces): N, the dashpot's part of the tension */
    double *f_const;    /* [n] N, gravity along the path on node i (material phase) */
    double *resist;     /* [n] N, rolling resistance on node i at speed (material) */
    double *normal;     /* [n] N, the weight's share the idlers carry there (material) */
    bd_axial_pulley_state *pulleys;   /* [pulley_count] */
    bd_load_fronts fronts;  /* the loaded region (belt/load_fronts.h) */
} bd_axial;

static inline bd_axial *bd_axial_of(const bd_sim *sim)
{
    return (bd_axial *)sim->belt_data;
}

static inline const bd_axial_model *bd_axial_model_of(const bd_sim *sim)
{
    return (const bd_axial_model *)sim->model->belt_model;
}

/* writable, while building only (a run made from a shared model has no
 * own model) */
static inline bd_axial_model *bd_axial_model_build(bd_sim *sim)
{
    return (bd_axial_model *)sim->own->belt_model;
}

/* build.c */
int bd_axial_build(bd_sim *sim, bd_diag *diag);
void bd_axial_free(bd_sim *sim);
void bd_axial_free_model(bd_model *model);
void bd_axial_clone(bd_sim *dst, const bd_sim *src);
double bd_axial_stable_step(const bd_sim *sim, bd_time_step_limit *limit);
void bd_axial_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out);
/* node i's material, mass, gravity along the path and rolling resistance
 * for the loaded region (build.c) */
void bd_axial_node_load(bd_sim *sim, int i);
void bd_axial_point_init(const bd_sim *sim, bd_tracker *tr, double s);

/* step.c */
void bd_axial_forces(bd_sim *sim);
void bd_axial_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque);
void bd_axial_integrate(bd_sim *sim, double *ke, double *w_nc);
void bd_axial_takeup_geometry(bd_sim *sim);
void bd_axial_material(bd_sim *sim);
double bd_axial_potential(const bd_sim *sim);
double bd_axial_elastic_energy(const bd_sim *sim);
void bd_axial_report_events(bd_sim *sim);

#endif
