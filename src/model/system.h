/* The simulated system: what every part of the simulator reads and writes.
 * Types only (and the warning list); the functions live in the folders
 * above this one: belt/ (the belt formulations), parts/ (pulleys, drives,
 * takeups, transmissions), sensors/ (probes, drive monitors), sim/ (the
 * build, the one step loop, energy). docs/architecture.md draws the
 * picture.
 *
 * Belt nodes and elements are flat arrays (struct of arrays) of length n;
 * element e joins node e to node e+1 (mod n): the belt is a closed loop.
 * Every formulation keeps its nodes here (positions, velocities, forces,
 * masses, element tensions); what only one formulation needs it keeps in
 * its own struct behind sim->belt_data.
 *
 * Who writes what: "build" fields are set once by bd_sim_create and never
 * change while the model runs; "step" fields are advanced by the step loop
 * (sim/step.c) in the phase named; "stats" fields are records of the run
 * so far. */
#ifndef BD_SYSTEM_H
#define BD_SYSTEM_H

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "model/path.h"
#include "model/secondary.h"

struct bd_belt_ops;
struct bd_part;

/* A point fixed on the path (probe, monitor point, feed point, idler) and
 * the belt element over it. The belt moves through the point; the
 * formulation keeps element and gamma current (bd_belt_ops.point_update). */
typedef struct bd_tracker {
    double p[2];      /* build: m, the fixed point */
    double dir[2];    /* build: unit travel direction of the path there */
    double s;         /* build: m, its path coordinate */
    int element;      /* step (sensors): element currently over it */
    double gamma;     /* step (sensors): 0..1 position of the foot point on it */
} bd_tracker;

/* what a start study asks of a drive pulley (sensors/monitor.c), followed
 * every step at O(1) cost: tension just before and after the wrap, the
 * belt's acceleration there and whether the pulley slips under the belt.
 * All stats, written in the sensors phase. */
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
    /* the friction the drive uses, ln(T_hi/T_lo)/(μ_s·φ) of its tight and
     * slack sides either way round (Euler–Eytelwein: the belt starts to
     * slip at 1): its largest and when; friction_cap is μ_s·φ (build) */
    double friction_cap;
    double friction_used_max, friction_used_max_t;
} bd_drive_monitor;

/* A pulley: a body turning on its axle, the axle on a takeup carriage when
 * it has one. What is mounted on it (drive, transmission, takeup) are its
 * parts (parts/parts.h). It never knows which belt formulation carries it:
 * the formulation's wrap coupling fills the "coupling" fields. */
typedef struct bd_pulley_model {
    const bd_pulley_def *def;
    double radius;          /* m */
    double inertia;         /* kg·m², pulley + drive inertia (floored > 0) */
    double wrap;            /* ±1: sense the belt turns (+ ccw) */
    double mu_s, mu_d;      /* belt–pulley friction, - */
    double bearing_damping; /* N·m·s */
    int movable;            /* a gravity or constant_force takeup */
    double axis[2];         /* unit axis of the carriage */
    double carriage_mass;   /* kg moving along the axis (pulley + takeup) */
    bd_pulley_resistance_law resistance; /* its own resistance (design.secondary:
                               individual; active 0: none) */
    double wrap_pull;       /* N along the axis: the weight of a wrap the belt
                               formulation does not resolve (axial), else 0 */
    double x0, y0;          /* m, centre at t = 0 (a takeup's as laid) */
    int first_part, part_count; /* its parts: sim->parts[first_part ..] */
} bd_pulley_model;

typedef struct bd_pulley_body {
    const bd_pulley_model *m;   /* its compiled model (model->pulleys[i]) */
    /* step, part torques: what the drive and bearing put on it */
    double drive_torque;    /* N·m the drive applies: at the present speed
                               (part torques), at the end-of-step speed once
                               the pulley turned (parts advance) */
    double torque_damping;  /* N·m·s, −dT/dω of the drive, taken implicitly:
                               the wrap coupling solves the pulley with
                               bd_pulley_solve_inertia, and the drive applies
                               drive_torque − torque_damping·Δt·α */
    double bearing_torque;  /* N·m bearing torque this step (with its own
                               resistance below) */
    /* its own resistance, design.secondary: individual (wrap, bearings,
     * cleaners; m->resistance, sim/pulley_resistance.c): a force on its
     * surface against its motion, fading linearly to 0 below res_fade */
    bd_tracker res_in, res_out;  /* belt points arriving at / leaving the wrap */
    double res_force;       /* N, this step, from the tensions there */
    double res_fade;        /* m/s */
    /* step, wrap coupling: what the pulley feels from the belt */
    double alpha;           /* rad/s² angular acceleration */
    double f_axis;          /* N belt force on the pulley along its axis */
    double fnc_axis;        /* N its non-conservative part */
    double torque_friction; /* N·m belt friction torque on the pulley */
    /* run control: held still, as a holdback or brake holds it (a drive
     * pulley while stabilizing); its wrap coupling then takes α = 0 */
    int held;
    /* step, parts advance */
    double omega;           /* rad/s, positive drives the belt forward */
    double q, qdot;         /* m, m/s carriage travel along axis */
    double qddot;           /* m/s² its acceleration in the last step */
    double q_step_start;    /* m, carriage travel at the start of the step */
    double cx, cy;          /* m, current centre */
    /* stats */
    double torque_max_abs;  /* N·m largest |drive torque| */
    double travel_min, travel_max;  /* m */
    /* m, N: a movable carriage's least and largest travel in each of the
     * running check's three windows, and its largest pull over them
     * (sensors/running.c) */
    double swing_lo[3], swing_hi[3], swing_pull;
    bd_drive_monitor mon;   /* drive pulleys only */
} bd_pulley_body;

/* An idler the belt rolls over, as a body of its own (the lumped belt;
 * the axial belt spreads its idlers along the path instead). */
typedef struct bd_idler_model {
    double centre[2];      /* m */
    double radius;         /* m */
    /* m, where the belt's running line touches it: the radius less the
     * corner that line cuts at rest (belt/lumped/idler_contact.c) */
    double contact_radius;
    int line_quintic;      /* the belt's running line there is the quintic
                              (belt/lumped/idler_contact.c) */
    double inertia;        /* kg·m² */
    double mu_s, mu_d;     /* belt–idler friction, - */
    double rolling;        /* rolling resistance coefficient, - */
    double k_contact;      /* N/m penalty stiffness */
    int set;               /* index of its idler set */
    double s;              /* m, path coordinate of its contact point */
    double inv_inertia;    /* 1/(kg·m²) */
    double r2_per_inertia; /* 1/kg, R²/I */
    double half_per_k;     /* m/N, 1/(2k_c): a spring's energy f²/(2k_c) */
} bd_idler_model;

typedef struct bd_idler {
    const bd_idler_model *m;   /* its compiled model (model->idlers[i]) */
    bd_tracker tr;         /* the belt element over it (supports phase) */
    double omega;          /* rad/s, + = surface moves with the belt (parts) */
    double alpha;          /* rad/s² this step (supports) */
    double torque;         /* N·m belt friction torque this step (supports) */
    double spring_energy;  /* J, f_n²/(2k_c) of its contact this step (supports) */
    int lazy;              /* its roll's motion kept by the belt, not the parts (a
                              long section of the rfe belt carrying it,
                              belt/rfe/sections.c); omega written when read */
    int landed;            /* the belt has stood on it: only a belt that was on
                              an idler can lift off it (idler_contact.c) */
} bd_idler;

typedef struct bd_probe {
    bd_tracker tr;
    double tension_max, tension_min, tension, speed;   /* stats, N and m/s */
} bd_probe;

typedef enum bd_time_step_limit {
    BD_LIMIT_AXIAL = 0, BD_LIMIT_BENDING, BD_LIMIT_USER, BD_LIMIT_TRANSVERSE,
    BD_LIMIT_TRANSPORT, BD_LIMIT_SHEAR
} bd_time_step_limit;

/* What a run costs, estimated before the build and updated after it with
 * the nodes and time step actually made (sim/estimate.c) */
typedef struct bd_cost {
    double element_length;    /* m, aimed at */
    /* what sets the node count when not belt.element_length, and what to
     * change (bd_belt_estimate), else "" */
    char element_what[96], element_advice[64];
    double nodes, idlers;
    double bytes;             /* peak memory of the build and the run */
    double dt;                /* s, time step */
    double steps;             /* for simulation.duration */
    double seconds;           /* wall time of those steps (stabilization not counted) */
    double stepped;           /* (node + idler)-equivalents each step costs: nodes +
                                 idlers, or fewer when long sections stand for many
                                 (bd_cost_update) */
    double rate;              /* (node + idler)-steps per second it assumes */
    double node_bytes, idler_bytes;
    double available;         /* bytes this process may use */
    double physical;          /* bytes of physical memory */
    const char *available_is; /* what sets `available` */
} bd_cost;

/* The belt off its idlers (model-format.md: a belt that lifts off in a
 * curve is reported: where, when, how long). The formulation notes each
 * idler station it finds lifted in its step; the sensors fold the step
 * into the record (sensors/lift_off.c). */
typedef struct bd_lift_off {
    int step_count;                /* step: stations lifted in this step */
    double step_s_min, step_s_max; /* step: m, their path coordinates */
    double first_t, first_s;       /* stats: the first lift, s and m (first_t < 0: none) */
    double s_min, s_max;           /* stats: m, the stations ever lifted */
    double since;                  /* stats: s, start of the present lift, or −1 */
    double longest, total;         /* stats: s, longest lift of any station run, and in all */
    int max_stations;              /* stats: most stations lifted at once */
} bd_lift_off;

typedef struct bd_energy {
    double kinetic, potential, dissipated, input;   /* J */
    /* J, what the last step added to dissipated and input. Its works are
     * booked with the mid-step velocity v(t) over the whole step, so the
     * sums run half a step ahead of the kinetic and potential energy at t;
     * the energy at t takes half of the last step back (bd_energy_at_t) */
    double step_dissipated, step_input;
    /* J, input this step that is work up to t already (a takeup's set
     * force changing: −ΔF·q at the middle of the interval it changed
     * over), not taken back */
    double step_input_at_t;
    /* J, what the step dissipated and put in that belongs to the state
     * after it, t + Δt (a change of the belt's topology at the step's end,
     * belt/rfe/sections.c): not counted at t, then wholly */
    double step_dissipated_after, step_input_after;
    double initial;        /* E_kin + E_pot at t = 0 */
    /* J, what the contacts' penalty springs (the belt on pulley shells and
     * idlers) hold at t, written by the forces phase (0 for a belt that
     * books them otherwise), and at t = 0. The lumped belt books the
     * contacts' whole normal forces as non-conservative work
     * (pulley_contact.c, idler_contact.c), so the energy a loaded spring
     * gives back as the belt lifts off would read as a fall of the
     * dissipated energy: it counts as potential energy and the dissipated
     * energy is net of it (bd_energy_at_t) */
    double springs, springs0;
    int springs_started;   /* springs0 and initial include the springs */
    double max_kinetic;
    double balance_error_rel; /* largest so far */
    /* negative dissipation: the largest fall of `dissipated` between two
     * balance checks, over the energy scale, and when it ended */
    double dissipated_checked;   /* J, at the last check */
    double dissipation_fall_rel;
    double dissipation_fall_t;
} bd_energy;

/* The compiled model: what bd_sim_create derives from the model
 * definition and no step changes. It is written while the simulation is
 * built (through sim->own) and read-only afterwards (through sim->model).
 * Arrays are commented with their sizes. */
typedef struct bd_model {
    const bd_model_def *def;          /* the validated definition it came from */
    const struct bd_belt_ops *belt;   /* the belt formulation */
    void *belt_model;                 /* the formulation's compiled data */
    bd_path path;                     /* the belt's path at rest */
    double gravity;                   /* m/s² */
    /* belt: n nodes, n elements */
    int n;
    double l0;                        /* m, (mean) unstretched element length */
    double EA, EI;                    /* N, N·m² */
    double belt_mpl;                  /* kg/m */
    double *s_node0;                  /* [n] m, initial path coordinate of node i */
    /* counts of the parts, sensors and supports */
    int pulley_count, idler_count, probe_count;
    bd_pulley_model *pulleys;         /* [pulley_count] */
    bd_idler_model *idlers;           /* [idler_count] */
    int *idlers_per_set;              /* [def->idler_set_count] */
    double *idler_spacing;            /* [def->idler_set_count] m, actual spacing */
    /* the discrete or rfe belt's turn over each idler set at rest, rad, and the
     * belt speed over its transverse wave speed there (belt/lumped/
     * idler_turn.c; NULL for other belts, 0 where not found) */
    double *idler_turn, *idler_turn_speed;   /* [def->idler_set_count] */
    int element_refined;              /* the default element was halved for them
                                         (1), or the rfe belt's shortened for its
                                         polygon on the pulleys (2; belt/lumped/
                                         polygon.c) */
    /* material */
    double material_mpl;              /* kg/m on the loaded belt */
    int feed_individual;              /* the feed point's resistances one by
                                         one (belt/common.c bd_feed_force) */
    int discharge_pulley;
    /* time step and what limits it */
    double dt, dt_limit;              /* s */
    double inv_dt;                    /* 1/s */
    bd_time_step_limit limit_kind;
    /* what the run costs (sim/estimate.c) */
    bd_cost cost;
    /* physical bounds of the parts' state, checked every step (sim/bounds.c) */
    double speed_bound;               /* m/s, pulley surface and carriage speed */
    double travel_bound;              /* m, takeup carriage travel */
    /* the state at t = 0 every run on this model starts from (a compiled
     * model's; NULL while a simulation owns its model) */
    struct bd_sim *initial;
} bd_model;

/* Steady running at the end of a run against the model's own resistance
 * law (sensors/running.c): Hann-weighted sums of the drive force, the
 * belt speed and the pulleys' own resistances over each of the run's last
 * three windows of `window` s (k = 0..2, ending at `end`). O(drives) per step, no allocation; off (window 0)
 * unless a run turned it on. All stats, written in the sensors phase. */
typedef struct bd_running_window {
    double window, end;            /* s */
    int drive;                     /* the first drive pulley, or -1 */
    double travel, travel0;        /* m its surface ran, in all and by the windows */
    double f[3], v[3], r[3], w[3]; /* N, m/s, N, weights summed */
    int window_at;                 /* the window the last step was in, -1 before */
} bd_running_window;

/* A simulation: the compiled model and the state that the step loop
 * advances. */
struct bd_sim {
    const bd_model *model;     /* read-only once built; may be shared */
    bd_model *own;             /* the same when this simulation owns it (and
                                  writes it while building), else NULL */
    void *belt_data;           /* the formulation's own data */

    /* belt nodes and elements [model->n] */
    /* step: integrate phase */
    double *x, *y;         /* [n] m */
    double *vx, *vy;       /* [n] m/s at the half step */
    /* step: forces, wrap and supports phases (scratch of the step) */
    double *fx, *fy;       /* [n] N total force */
    double *fnx, *fny;     /* [n] N non-conservative part (energy account) */
    double *tension;       /* [n] N of element e (spring + dashpot) */
    /* step: material phase */
    double *mass;          /* [n] kg belt + material */
    double *material;      /* [n] kg of material on the node */
    double *dt_per_mass;   /* [n] s/kg, Δt/mass, kept with mass (bd_node_mass_changed) */

    /* parts: their build and state fields as their structs say */
    bd_pulley_body *pulleys;   /* [model->pulley_count] */
    int part_count;
    struct bd_part *parts;     /* [part_count] in pulley order */
    bd_idler *idlers;          /* [model->idler_count] */
    /* sensors */
    bd_probe *probes;          /* [model->probe_count] */

    /* material feed (has_feed is off while stabilizing) */
    int has_feed;
    bd_tracker feed;

    /* time (step) */
    double t;              /* s */
    long steps;
    /* element tension extremes of the current step (forces phase) */
    double step_tension_max, step_tension_min;
    int step_tension_nan;  /* some element's tension is NaN */

    /* stats */
    bd_energy energy;
    bd_lift_off lift;
    bd_running_window running;
    double tension_max, tension_max_t, tension_max_s;
    double tension_min, tension_min_t, tension_min_s;
    long stabilize_iterations;
    int stabilize_resets;
    int stabilize_converged;
    double stabilize_final_kinetic;
    long settle_steps;     /* bd_sim_settle's (0: not settled) */
    int settle_resets;
    double settle_released;   /* J: the mechanical energy it took out */
    /* run control */
    int stabilizing;       /* relaxing before t = 0 (stabilize.c): clock held at
                              0, drives off, drive pulleys held, no feed */
    int want_energy;       /* book the potential energy in the next step */
    int energy_every_step; /* ... and in every step (bd_sim_book_energy_every_step) */
    char fail_msg[512];
    char **warnings;       /* [warning_count] said after the run */
    int warning_count;
    int static_warnings;   /* the static design's warnings in summary.json
                              (io/outputs.c), counted with them */
};

/* the inertia the wrap coupling solves pulley p with: its own and the
 * drive's implicit damping over one step (drive.c) */
static inline double bd_pulley_solve_inertia(const bd_sim *sim, const bd_pulley_body *p)
{
    return p->m->inertia + p->torque_damping * sim->model->dt;
}

/* m the belt must stand off an idler to count as lifted: above the
 * rounding of a resting contact and the discrete belt's chord passing
 * over an idler (its contact gap), well below a lift in a curve (cm) */
#define BD_LIFT_OFF_CLEARANCE 1e-3
/* m the belt must first have come within of an idler for its standing off
 * to count (idler_contact.c): a belt laid on the roll tops falls onto the
 * contact a corner below them, which is no lift-off; half the clearance so
 * that a belt hovering at the clearance does not flip in and out */
#define BD_LIFT_OFF_LANDED (0.5 * BD_LIFT_OFF_CLEARANCE)

/* an idler station at path coordinate s is lifted in this step */
static inline void bd_lift_off_note(bd_sim *sim, double s)
{
    bd_lift_off *l = &sim->lift;
    if (l->step_count == 0 || s < l->step_s_min)
        l->step_s_min = s;
    if (l->step_count == 0 || s > l->step_s_max)
        l->step_s_max = s;
    l->step_count++;
}

/* node i's mass changed: keep what is derived from it */
static inline void bd_node_mass_changed(bd_sim *sim, int i)
{
    sim->dt_per_mass[i] = sim->model->dt / sim->mass[i];
}

/* the state's node and element arrays [n], allocated (zeroed), copied
 * and freed together (system.c); their bytes per node */
void bd_node_arrays_alloc(bd_sim *sim);
size_t bd_node_arrays_bytes(void);
void bd_node_arrays_dup(bd_sim *dst, const bd_sim *src);
void bd_node_arrays_free(bd_sim *sim);

/* add a warning (repeats are dropped); never from inside the step loop */
void bd_sim_warn(bd_sim *sim, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
