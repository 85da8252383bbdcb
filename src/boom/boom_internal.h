/* The telescopic boom's compiled model and state (seed 003).
 *
 * Each section is a planar geometrically nonlinear beam (corotational
 * Euler-Bernoulli elements: axial and bending) whose nodes are spatial
 * points: their material coordinate s (arc length from the section's
 * bottom end, unstretched) moves with the physics. A section's nodes that
 * matter are its two ends (material points), for section 1 the luffing
 * cylinder's attachment (a material point) and for every inner section its
 * outer contact point (where the outer neighbour's top pads sit: a spatial
 * point). Between two of them, `elements_per_segment` equal elements
 * (seed 003 eq. 5). The inner contact point (where the inner neighbour's
 * bottom pads sit) floats between nodes, as the seed does (§5) so that it
 * never makes a zero-length element when it crosses the outer contact
 * point.
 *
 * Velocities stored at a node are material velocities (of the material
 * point the node stands on at that instant); moving a node through the
 * material is a remap along the section (boom/layout.c), the operator
 * split form of seed 003 eq. (3): d/dt = ∂/∂t + ṡ ∂/∂s. */
#ifndef BD_BOOM_INTERNAL_H
#define BD_BOOM_INTERNAL_H

#include <signal.h>

#include "beltdyn/boom.h"

enum { BOOM_KEY_NONE = 0, BOOM_KEY_ATTACH, BOOM_KEY_OUTER };

typedef struct boom_section {
    double L, EA, EI, rhoA, h;  /* m, N, N·m², kg/m, m (pad spacing) */
    int first;                  /* first node */
    int n;                      /* nodes, n - 1 elements */
    int per_seg;                /* elements per segment */
    int key;                    /* BOOM_KEY_*: the node between the segments */
    double key_s;               /* its material coordinate now, m */
} boom_section;

/* a point of a section between two of its nodes: element (node a = first
 * node of the element) and its parameter xi in [0, 1] */
typedef struct boom_where {
    int sec, a;
    double xi;
} boom_where;

/* one pad contact: an inner section's point A against an outer section's
 * point B; the pads at +-h/2 across the axis, each with two ends at +-w/2
 * along it (seed 003 §8.2: the contact resultants at the pad ends) */
typedef struct boom_contact {
    int inner_sec, outer_sec;
    double h;                 /* m, spacing of the two pads */
    boom_where A, B;          /* where on each section, this step */
    int surface_on_A;         /* 1: the pads (on B) slide on A's surface (the
                                 outer contact), 0: the pads (on A) slide on
                                 B's (the inner contact) */
    /* results of the last force evaluation */
    double npad[2];           /* N, the upper and the lower pad */
    double normal;            /* N, sum of the pad forces */
    double offset;            /* m, the inner axis off the outer along the
                                 surface's normal */
    double friction;          /* N, on the inner section along its axis */
    double slide;             /* m/s, sliding speed of A relative to B */
    double face_force[2];     /* N, friction of the upper and lower pad on A */
    double face_speed[2];     /* m/s, their faces' sliding speed at the force */
} boom_contact;

typedef struct bd_boom {
    bd_boom_def def;          /* owned copy (tables copied) */
    int ns;                   /* sections */
    boom_section sec[BD_BOOM_MAX_SECTIONS];
    int N;                    /* nodes */
    double g;
    double tip_mass;
    double base_a, base_n;    /* section 1's bottom end from the pivot in the
                                 boom frame (along, across), m: minus the
                                 added key pivot_offset */
    double attach_s;          /* section 1's luffing attachment, m (if any) */
    double attach_n;          /* the attachment's offset across the axis, m */
    int attach_node;          /* its node */

    /* contacts: [2k] inner contact of boundary k (section k+1's bottom in
     * section k), [2k+1] outer contact (section k's top on section k+1) */
    int nc;
    boom_contact c[2 * BD_BOOM_MAX_SECTIONS];

    /* damping: Rayleigh, alpha on the velocity relative to the rigid boom,
     * beta on the strain rates */
    double alpha, beta, f1_hz;
    double dt;
    double omega_max;         /* rad/s, highest frequency found */

    /* ---- state: [N] each ---- */
    double *x, *y, *phi;      /* m, m, rad (cross-section angle) */
    double *vx, *vy, *w;      /* material velocities, m/s, rad/s */
    double *s;                /* material coordinate on its section, m */
    double *m, *J;            /* lumped mass kg, rotary inertia kg·m² */
    double *fx, *fy, *mz;     /* forces this step */
    /* elements [N] (index of node a; the last node of a section unused) */
    double *eN, *eMa, *eMb, *eV;   /* axial force, end moments, shear */
    /* remap scratch [N] */
    double *tx, *ty, *tphi, *tvx, *tvy, *tw, *ts;

    double t;
    long steps;
    double stroke_ref, stroke_v, stroke_a;   /* profile now */
    double theta, theta_dot;                 /* luffing now */
    double cos_theta, sin_theta;             /* of theta (every node reads them) */

    /* actuators, last evaluation */
    double cyl_force;          /* N, telescopic cylinder (push positive) */
    double luff_force;         /* N rod (push positive) or N·m pivot moment */
    double rope_ext[BD_BOOM_MAX_SECTIONS], rope_ret[BD_BOOM_MAX_SECTIONS]; /* N, stage k */
    double rope_ext_l0[BD_BOOM_MAX_SECTIONS], rope_ret_l0[BD_BOOM_MAX_SECTIONS];
    double cyl_c, rod_c;       /* dashpots N·s/m */

    /* energy */
    double e_kin, e_pot, e_diss, e_in, e_0, balance_rel, diss_fall;
    double e_norm;             /* largest kinetic seen */
    double pend_kin, pend_diss, pend_in;   /* boom_evaluate -> boom_advance */
    long steps_run;            /* steps of the run proper (after settling) */

    /* records */
    bd_boom_result res;
    int settled;               /* 1 once the static state is reached */
    long settle_steps;
} bd_boom;

/* ---- boom/layout.c ---- */
/* section k's bottom position along the rigid boom's axis for the strokes
 * of the profile now (m from the pivot) */
double boom_rigid_offset(const bd_boom *b, int k, double stroke);
/* the rigid boom's point at material s of section k, and its velocity */
void boom_rigid_point(const bd_boom *b, int k, double s, double *x, double *y, double *vx,
                      double *vy);
/* place every node on the rigid boom at time t, at rest relative to it */
void boom_place_rigid(bd_boom *b);
/* node material coordinates from the key nodes; masses and inertias */
void boom_distribute(bd_boom *b, int k);
void boom_masses(bd_boom *b);
/* locate the point of section k nearest to (px, py), starting from *at */
void boom_project(const bd_boom *b, int k, double px, double py, boom_where *at);
/* material coordinate of a located point */
double boom_where_s(const bd_boom *b, const boom_where *at);
/* position, tangent angle, material velocity and angular velocity there */
void boom_eval(const bd_boom *b, const boom_where *at, double *x, double *y, double *phi,
               double *vx, double *vy, double *w);
/* a force (fx, fy) and moment mz at a located point, to its two nodes
 * (the virtual work of the interpolation boom_eval uses) */
void boom_apply(bd_boom *b, const boom_where *at, double fx, double fy, double mz);
/* 1/effective translational mass at a located point */
double boom_inv_mass(const bd_boom *b, const boom_where *at);
/* 1/effective rotary inertia there (the angle is linear along an element) */
double boom_inv_inertia(const bd_boom *b, const boom_where *at);
/* move the inner sections' outer contact nodes to where their outer
 * neighbours' tops are, and every node of theirs through the material */
void boom_remap(bd_boom *b);
/* where an outer contact node may stand: at least a sixth of the section
 * from either end. Nearer, its segment's elements would shrink with the
 * overlap or the protrusion (to nothing when a boom retracts fully) and the
 * stable step with the square of their length; the contact itself is
 * always found by projection, so past the limit it floats between nodes
 * as the inner contact does */
double boom_key_clamp(const boom_section *S, double key_s);
/* section k's key node to material coordinate key_s, its nodes remapped */
void boom_move_key(bd_boom *b, int k, double key_s);

/* ---- boom/beam.c ---- */
/* internal and damping forces of every element into f; the elastic
 * energy and the damping power (W) returned through the pointers */
void boom_beam_forces(bd_boom *b, double *elastic, double *damp_power);

/* ---- boom/pads.c ---- */
/* locate every contact and add its pad forces; energy and dissipation */
void boom_pads(bd_boom *b, double *elastic, double *diss_power);
/* the friction's dissipation over the step just taken beyond what
 * boom_pads booked at the step's starting speed (W): half the change of
 * the faces' speed times their forces, so the work counts the mean speed */
double boom_pads_friction_correction(const bd_boom *b);

/* ---- boom/actuators.c ---- */
void boom_actuators_init(bd_boom *b);
/* cylinder, ropes, luffing rod or moment; elastic energy, dissipated and
 * input power */
void boom_actuators(bd_boom *b, double *elastic, double *diss_power, double *in_power);

/* ---- boom/step.c ---- */
/* the profile and luffing angle at time t into b */
void boom_kinematics(bd_boom *b, double t);
/* every force at the current state into fx, fy, mz; energies */
void boom_forces(bd_boom *b, double *elastic, double *diss_power, double *in_power);
/* one step of dt; settle = 1: time held, kinetic damping. 0 ok, else the
 * node index at which the state left physical bounds (err written) */
int boom_step(bd_boom *b, int settle, char *err, size_t errlen);
/* the two halves of a step: every force and energy at the state now
 * (what an output row shows), then the advance by dt */
void boom_evaluate(bd_boom *b);
int boom_advance(bd_boom *b, int settle, char *err, size_t errlen);
/* settle at t = 0 (time held, the first bending mode critically damped)
 * until no node moves faster than 1e-5 m/s over 2000 steps: 0 settled,
 * 1 not within max_steps (err has the warning), -1 diverged (err), 2
 * interrupted (*interrupted set) */
int boom_settle(bd_boom *b, long max_steps, volatile sig_atomic_t *interrupted, char *err,
                size_t errlen);
/* rope statics: the telescopic cylinder's force at rest at t = 0, N */
double boom_static_cylinder_force(const bd_boom *b);
/* rigid statics of the luffing at time 0's angle and the given stroke:
 * the rod's force (N, push positive) or, without a rod, the pivot moment
 * (N·m) that holds the boom's weight and tip load */
double boom_static_luffing(const bd_boom *b, double stroke);
/* tip position and the rigid boom's */
void boom_tip(const bd_boom *b, double *x, double *y, double *vx, double *vy);
void boom_tip_rigid(const bd_boom *b, double *x, double *y);

#endif
