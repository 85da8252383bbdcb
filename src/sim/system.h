/* The simulated system: parameters derived once from the model (never
 * changed by a step) and the state that the step loop advances. Belt nodes
 * and elements are stored as flat arrays (struct of arrays). Element e joins
 * node e to node e+1 (mod N): the belt is a closed loop. */
#ifndef BD_SYSTEM_H
#define BD_SYSTEM_H

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "model/path.h"
#include "laws/belt_pulley_law.h"

struct bd_transmission;

/* a tracker follows which belt element is currently over a fixed point of
 * the path (idler, probe, feed point): the belt moves through it */
typedef struct bd_tracker {
    double p[2];      /* m, the fixed point */
    double dir[2];    /* unit travel direction of the path there */
    double s;         /* m, its path coordinate */
    int element;      /* element currently over it */
    double gamma;     /* 0..1 position of the foot point on that element */
} bd_tracker;

/* what a start study asks of a drive pulley (monitor.c), followed every
 * step at O(1) cost: tension just before and after the wrap, the belt's
 * acceleration there and whether the pulley slips under the belt */
typedef struct bd_drive_monitor {
    bd_tracker tight, slack;     /* belt points arriving at / leaving the wrap */
    double tight_max, tight_max_t;   /* N, s */
    double slack_min, slack_min_t;   /* N, s */
    double ramp_end;             /* s, when the start curve reaches full speed */
    double swing_max, swing_min; /* N, tight-side extremes after ramp_end */
    double win_sum;              /* m/s summed tight-side speed, this window */
    long win_count;
    double win_end;              /* s, end of the current window */
    double win_prev;             /* m/s mean speed of the previous window */
    int win_have_prev;
    double accel_max, accel_max_t;   /* m/s², s: largest |window acceleration| */
    double slip_dv_max;          /* m/s largest |surface − belt| speed */
    double slip_since;           /* s, start of the current slip, or −1 */
    double slip_longest;         /* s, longest slip */
    double slip_first_t;         /* s, when slip was first confirmed, or −1 */
} bd_drive_monitor;

typedef struct bd_pulley_body {
    const bd_pulley_def *def;
    double radius;          /* m */
    double inertia;         /* kg·m², pulley + drive inertia (floored > 0) */
    double wrap;            /* ±1: sense the belt turns (+ ccw) */
    double mu_s, mu_d;
    double bearing_damping; /* N·m·s */
    int movable;            /* a gravity or constant_force takeup */
    double axis[2];         /* unit axis of the carriage */
    double carriage_mass;   /* kg moving along the axis (pulley + takeup) */
    double k_contact;       /* N/m penalty stiffness of a node on it */
    /* contact window: nodes first .. first+count-1 (mod N) were in contact */
    int win_first, win_count;
    int win_max;            /* capacity of the scratch arrays below */
    /* per-contact scratch for the stick-force solve [win_max] */
    int *c_node;
    double *c_normal;       /* N, normal force */
    double *c_tx, *c_ty;    /* unit tangent (positive in the wrap sense) */
    double *c_f;            /* N, friction (+ = retards the belt) */
    int *c_slip;
    int contact_count;
    /* results of the contact pass of this step */
    double alpha;           /* rad/s² angular acceleration */
    double f_axis;          /* N belt force on the pulley along its axis */
    double fnc_axis;        /* N its non-conservative part */
    double torque_friction; /* N·m belt friction torque on the pulley */
    double torque_external; /* N·m drive + bearing torque this step */
    /* state */
    double omega;           /* rad/s, positive drives the belt forward */
    double q, qdot;         /* m, m/s carriage travel along axis */
    double qddot;           /* m/s² its acceleration in the last step */
    double cx, cy;          /* m, current centre */
    double drive_torque;    /* N·m last applied by the drive */
    double torque_max_abs;  /* N·m largest |drive torque| */
    double travel_min, travel_max;
    double integral;        /* speed-controller integral state (rad) */
    double ctrl_inertia;    /* kg·m² the speed controller is tuned for */
    double ctrl_bandwidth;  /* rad/s of its closed speed loop */
    double motor_breakdown; /* N·m at the motor shaft (motor control) */
    double motor_slip_b;    /* breakdown slip, - */
    double bearing_torque;  /* N·m bearing torque this step */
    double force_prev;      /* N takeup force at the previous step */
    int at_limit;           /* takeup carriage at a travel limit */
    int limit_hits;         /* times it arrived at a limit */
    double limit_first_t;   /* s, the first arrival */
    double limit_first_q;   /* m, at which limit */
    bd_drive_monitor mon;   /* drive pulleys only */
    /* axial formulation (src/axial/): the pulley acts on one belt node */
    int node;               /* the belt node on its wrap */
    double c_in, c_out;     /* u_in·a, u_out·a: spans along the takeup axis */
    double wrap_pull;       /* N, weight of the wrapped belt along the axis */
    double q_step_start;    /* m, carriage travel at the start of the step */
    bd_bpl law;             /* seed-004 law of its wrap */
    double belt_force;      /* N, its friction force on the belt this step */
    int slack_warned;       /* a belt end lost tension (recorded once) */
    int slack_arriving;     /* it was the arriving end */
    double slack_t;         /* s, when */
    double slack_tension;   /* N, its tension then */
    struct bd_transmission *trans; /* belt transmission to its drive, or NULL */
} bd_pulley_body;

typedef struct bd_idler {
    bd_tracker tr;
    double centre[2];      /* m */
    double radius;         /* m */
    double inertia;        /* kg·m² */
    double mu_s, mu_d;
    double rolling;        /* rolling resistance coefficient */
    double k_contact;      /* N/m penalty stiffness */
    double omega;          /* rad/s, + = surface moves with the belt */
    double alpha;          /* rad/s² this step */
    double torque;         /* N·m belt friction torque this step */
    int set;               /* index of its idler set */
} bd_idler;

typedef struct bd_probe {
    bd_tracker tr;
    double tension_max, tension_min, tension, speed;
} bd_probe;

typedef enum bd_time_step_limit {
    BD_LIMIT_AXIAL = 0, BD_LIMIT_BENDING, BD_LIMIT_USER
} bd_time_step_limit;

typedef struct bd_energy {
    double kinetic, potential, dissipated, input;
    double initial;        /* E_kin + E_pot at t = 0 */
    double max_kinetic;
    double balance_error_rel; /* largest so far */
} bd_energy;

/* the axial (1D) belt (src/axial/): nodes are stations fixed on the path;
 * each carries the belt's displacement u along the path (vx holds its
 * velocity, fx its force; vy, fy stay 0). Element e joins node e to e+1. */
/* m/s: the axial belt's rolling resistance fades to zero below this speed
 * (as the discrete idlers' does, idler_contact.c) */
#define BD_AXIAL_ROLLING_SPEED 0.01

typedef struct bd_axial {
    double *u;          /* [n] m displacement along the path */
    double *gap;        /* [n] m, l − l0 of element e at u = 0 (with takeup travel) */
    double *gap_rate;   /* [n] m/s its rate (takeup motion), 0 elsewhere */
    double *k;          /* [n] N/m, EA/l0 of element e */
    double *c;          /* [n] N·s/m, its dashpot */
    double *l0;         /* [n] m, its unstretched length */
    double *s_len;      /* [n] m, its length along the initial path */
    double *f_const;    /* [n] N, gravity along the path on node i */
    double *resist;     /* [n] N, rolling resistance on node i at speed */
    int feed_node;      /* node at the feed point, -1 = none */
    double min_mass;    /* kg, lightest node without material */
    /* the loaded region [s_feed + d_tail, s_feed + d_head] along the path
     * (docs/physics.md §11): a free front rides with the belt, a pinned one
     * stays at the feed point (tail, while feeding) or the discharge (head) */
    double s_feed;      /* m, path coordinate of the feed point */
    double load_len;    /* m, feed point → discharge pulley */
    double d_tail, d_head; /* m from the feed point, 0 ≤ d_tail ≤ d_head ≤ load_len */
    int tail_free, head_free;
    int e_tail, e_head; /* element holding each front (a search hint) */
} bd_axial;

struct bd_sim {
    const bd_model_def *def;
    int axial;             /* 1: belt.formulation axial (the bd_axial below) */
    bd_axial ax;
    bd_path path;
    double gravity;

    /* belt: N nodes, N elements */
    int n;
    double l0;             /* m, unstretched element length (all equal) */
    double EA, EI;         /* N, N·m² */
    double k_axial;        /* N/m = EA/l0 */
    double c_axial;        /* N·s/m dashpot of one element */
    double k_bend;         /* N·m/rad = EI/l0 */
    double belt_mpl;       /* kg/m */
    double *x, *y;         /* [n] m */
    double *vx, *vy;       /* [n] m/s at the half step */
    double *fx, *fy;       /* [n] N total force */
    double *fnx, *fny;     /* [n] N non-conservative part (energy account) */
    double *mass;          /* [n] kg belt + material */
    double *material;      /* [n] kg of material on the node */
    double *tension;       /* [n] N of element e (spring + dashpot) */
    double *ux, *uy;       /* [n] unit vector of element e */
    double *len;           /* [n] m current length of element e */
    double *s_node0;       /* [n] m initial path coordinate of node */
    int *seg_hint;         /* [n] segment guess for Eulerian s of elements */

    int pulley_count;
    bd_pulley_body *pulleys;
    int idler_count;
    bd_idler *idlers;
    int *idlers_per_set;   /* [idler_set_count] */
    double *idler_spacing; /* [idler_set_count] actual spacing, m */
    int probe_count;
    bd_probe *probes;

    /* material feed/discharge */
    int has_feed;
    bd_tracker feed;
    double material_mpl;
    int discharge_pulley;

    /* time */
    double dt, dt_limit;
    bd_time_step_limit limit_kind;
    double t;
    long steps;
    /* element tension extremes of the current step (belt_lumped.c) */
    double step_tension_max, step_tension_min, step_tension_sum;
    int step_element_max, step_element_min;

    /* bookkeeping */
    bd_energy energy;
    double tension_max, tension_max_t, tension_max_s;
    double tension_min, tension_min_t, tension_min_s;
    int stabilize_iterations;
    double stabilize_final_kinetic;
    int friction_off;      /* during stabilization */
    int want_energy;       /* book the potential energy in the next step */
    char fail_msg[512];
    char **warnings;
    int warning_count;
};

/* element tension extremes of one step (a NaN anywhere makes sum NaN) */
typedef struct bd_extremes {
    double hi, lo, sum;
    int ihi, ilo;
} bd_extremes;

static inline void bd_extremes_add(bd_extremes *x, double T, int e)
{
    x->sum += T;
    if (T > x->hi) {
        x->hi = T;
        x->ihi = e;
    }
    if (T < x->lo) {
        x->lo = T;
        x->ilo = e;
    }
}

/* store a step's extremes in sim->step_tension_* */
void bd_extremes_store(bd_sim *sim, const bd_extremes *x);

/* step.c: divergence check and tension extremes after an element pass */
int bd_check_elements(bd_sim *sim);

/* run.c: turn the events the step recorded into warnings */
void bd_sim_report_events(bd_sim *sim);

/* build.c */
void bd_alloc_node_arrays(bd_sim *sim);
void bd_setup_probes_and_feed(bd_sim *sim);
void bd_pulley_body_init(bd_sim *sim, bd_pulley_body *p, const bd_pulley_def *pd);
/* idlers of set k that fit its span evenly (0 on a vertical span, with a
 * warning) and their actual spacing */
int bd_idler_set_layout(bd_sim *sim, int k, double *spacing);
void *bd_xcalloc(size_t n, size_t size);
void bd_sim_warn(bd_sim *sim, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* tracker.c */
void bd_tracker_init(const bd_sim *sim, bd_tracker *tr, double s);
void bd_tracker_update(const bd_sim *sim, bd_tracker *tr);
double bd_tracker_tension(const bd_sim *sim, const bd_tracker *tr);
/* belt speed along the path at the tracked point, m/s */
double bd_tracker_speed(const bd_sim *sim, const bd_tracker *tr);

/* monitor.c: drive monitors (set up in build, reset when a run starts) */
void bd_monitor_init(bd_sim *sim, bd_pulley_body *p);
void bd_monitor_reset(bd_sim *sim, bd_pulley_body *p);
double bd_monitor_swing(const bd_drive_monitor *m);
void bd_monitor_update(bd_sim *sim, bd_pulley_body *p);

/* belt_lumped.c: elastic, damping, bending, gravity forces on nodes */
void bd_belt_forces(bd_sim *sim);
double bd_belt_elastic_energy(const bd_sim *sim);

/* pulley_contact.c / idler_contact.c */
void bd_pulley_contact(bd_sim *sim, bd_pulley_body *p, double external_torque);
void bd_idler_contact(bd_sim *sim, bd_idler *id);
double bd_pulley_contact_energy(const bd_sim *sim, const bd_pulley_body *p);

/* drive.c */
void bd_drive_prepare(bd_sim *sim, bd_pulley_body *p, double reflected_inertia);
double bd_drive_torque(const bd_sim *sim, bd_pulley_body *p);
/* takeup.c */
double bd_takeup_force(const bd_sim *sim, const bd_pulley_body *p, double t);
double bd_takeup_advance(bd_sim *sim, bd_pulley_body *p, double *input);

/* energy.c */
double bd_energy_potential(const bd_sim *sim);
void bd_energy_update_balance(bd_sim *sim);

/* step.c */
/* the drive (or transmission) and bearing torque on pulley p this step */
double bd_pulley_external_torque(bd_sim *sim, bd_pulley_body *p);
/* pulley rotations and takeup carriages to the next step; adds their
 * kinetic energy to *ke and their non-conservative work to *w_nc */
void bd_pulleys_advance(bd_sim *sim, double *ke, double *w_nc);
int bd_step_once(bd_sim *sim);
void bd_sim_start_at_rest(bd_sim *sim);

/* axial formulation (src/axial/) */
int bd_axial_build(bd_sim *sim, bd_diag *diag);
void bd_axial_free(bd_sim *sim);
int bd_axial_forces(bd_sim *sim);
int bd_axial_step(bd_sim *sim);
double bd_axial_potential(const bd_sim *sim);
double bd_axial_elastic_energy(const bd_sim *sim);
double bd_axial_stable_step(const bd_sim *sim);
/* node i's material, mass, gravity along the path and rolling resistance
 * for the loaded region in sim->ax (axial_build.c) */
void bd_axial_node_load(bd_sim *sim, int i);

/* parts/transmission.c: belt transmissions of drives (seed 004) */
int bd_transmissions_create(bd_sim *sim, bd_diag *diag);
/* torque of the transmission on its pulley this step */
double bd_transmission_torque(bd_sim *sim, bd_pulley_body *p);
/* advance the transmission over the step in which its pulley went from
 * omega_old to p->omega; books its energy */
void bd_transmission_advance(bd_sim *sim, bd_pulley_body *p, double omega_old, double *ke,
                             double *w_nc);
void bd_transmissions_free(bd_sim *sim);
/* after the drives are prepared: the speed loops of transmission drives */
void bd_transmissions_tune(bd_sim *sim);
/* elastic energy of the transmissions' spans, J */
double bd_transmissions_potential(const bd_sim *sim);
/* motor sheave speed (rad/s) and the belt's slip on both sheaves (m/s) */
void bd_transmission_state(const bd_pulley_body *p, double *w_motor, double *slip_motor,
                           double *slip_pulley);
/* largest slip of the belt on either sheave so far, m/s */
double bd_transmission_slip_max(const bd_pulley_body *p);

/* output helpers: Eulerian path coordinate of element e's midpoint */
double bd_element_s(const bd_sim *sim, int e);
double bd_element_speed(const bd_sim *sim, int e);

#endif
