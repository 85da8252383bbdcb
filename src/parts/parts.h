/* The parts a belt runs on and is driven by, one file each: pulley.c (the
 * rotating body and its carriage), drive.c, takeup.c, transmission.c,
 * idler.c. Parts never know which belt formulation carries them: they
 * read what the formulation's wrap coupling left in the pulley body
 * (alpha, torque_friction, f_axis, fnc_axis) and nothing else of the belt. */
#ifndef BD_PARTS_H
#define BD_PARTS_H

#include "model/system.h"

/* The parts mounted on pulleys, one kind per file, as a tagged union with
 * one switch per phase (part.c), as Box2D's joints. A new part type (a
 * holdback, a brake, a fluid coupling) is a file, an enum value and a case
 * in each phase it takes part in. */
typedef enum bd_part_type {
    BD_PART_DRIVE = 0,      /* drive.c: speed loop, torque table or motor */
    BD_PART_TRANSMISSION,   /* transmission.c: a drive through a flat or V belt */
    BD_PART_TAKEUP          /* takeup.c: the pull on a takeup carriage, its limits */
} bd_part_type;

/* a drive's controller (drive.c) */
typedef struct bd_drive {
    const bd_drive_def *def;
    double ctrl_inertia;    /* build: kg·m² the speed controller is tuned for */
    double ctrl_bandwidth;  /* build: rad/s of its closed speed loop */
    double motor_breakdown; /* build: N·m at the motor shaft (motor control) */
    double motor_slip_b;    /* build: breakdown slip, - */
    double integral;        /* step: speed-controller integral state (rad) */
    double driving_peak;    /* stats: N·m, largest |torque| applied while it
                               drives (not stopped: a brake is not the drive) */
} bd_drive;

/* a takeup's pull and travel limits (takeup.c); the carriage itself is the
 * pulley body's (q, qdot) */
typedef struct bd_takeup {
    const bd_takeup_def *def;
    double force_prev;      /* step: N takeup force at the previous step */
    int at_limit;           /* step: carriage at a travel limit */
    int limit_hits;         /* stats: times it arrived at a limit */
    double limit_first_t;   /* stats: s, the first arrival */
    double limit_first_q;   /* stats: m, at which limit */
} bd_takeup;

typedef struct bd_part {
    bd_part_type type;
    int pulley;             /* the pulley it is mounted on */
    union {
        bd_drive drive;                 /* BD_PART_DRIVE */
        struct {
            bd_drive drive;             /* the motor's controller */
            struct bd_transmission *belt;
        } transmission;                 /* BD_PART_TRANSMISSION */
        bd_takeup takeup;               /* BD_PART_TAKEUP */
    } u;
} bd_part;

/* part.c: the parts of the model, in pulley order (build) */
void bd_parts_create(bd_sim *sim);
void bd_parts_free(bd_sim *sim);
/* dst's parts as a deep copy of src's (a new run on the same model) */
void bd_parts_clone(bd_sim *dst, const bd_sim *src);
/* the drive (or transmission) part of pulley p, or NULL */
bd_part *bd_pulley_drive_part(const bd_sim *sim, const bd_pulley_body *p);
/* the drive's controller of a drive or transmission part, else NULL (as
 * strchr, a const part gives a pointer the caller keeps const) */
bd_drive *bd_part_drive(const bd_part *part);
/* phases, one switch each */
double bd_part_torque(bd_sim *sim, bd_part *part, double *slope);
void bd_part_advance(bd_sim *sim, bd_part *part, double omega_old, double w_mid, double *ke,
                     double *w_nc);
/* a takeup's potential −(F + wrap weight)·q; 0 for the others */
double bd_part_potential(const bd_sim *sim, const bd_part *part);
/* the transmissions' stored energy, J */
double bd_parts_stored_energy(const bd_sim *sim);
/* its state back to zero (after stabilization; its statistics start again
 * with bd_sim_records_restart) */
void bd_part_reset(bd_part *part);
/* its run statistics alone (a drive's driving peak, a takeup's limit
 * hits): the records start again (bd_sim_records_restart) */
void bd_part_records_clear(bd_part *part);
/* after stabilization, the pulley's holdback lets go: a drive takes over
 * the torque it held (N·m on the pulley) */
void bd_part_release(bd_part *part, double holding_torque);
/* events the step recorded, said after the run */
void bd_part_report_events(bd_sim *sim, const bd_part *part);

/* pulley.c */

/* what every pulley's model takes from its definition (build) */
void bd_pulley_model_init(bd_model *model, bd_pulley_model *pm, const bd_pulley_def *pd);
/* part torques phase: the drive's (or transmission's) and the bearing's
 * torque on pulley p this step */
double bd_pulley_external_torque(bd_sim *sim, bd_pulley_body *p);
/* the drive's implicit torque held to max_torque (the wrap couplings) */
int bd_pulley_drive_clip(const bd_sim *sim, bd_pulley_body *p, double alpha, double *external);
/* the carriage of pulley p for the wrap coupling, which solves it with the
 * belt (its acceleration is one of the coupling's unknowns): its outside
 * pull (N along the axis), and in *mass its mass; *mass is 0 when it does
 * not move this step (no takeup, a fixed one, or resting at a travel limit) */
double bd_pulley_carriage(const bd_sim *sim, const bd_pulley_body *p, double *mass);
/* parts advance phase: pulley rotations, transmissions and takeup
 * carriages to the next step; adds their kinetic energy to *ke and their
 * non-conservative work to *w_nc */
void bd_pulleys_advance(bd_sim *sim, double *ke, double *w_nc);

/* idler.c: idler rotations to the next step (parts advance phase) */
void bd_idlers_advance(bd_sim *sim, double *ke, double *w_nc);

/* drive.c */
/* the fastest belt speed a drive asks for, m/s (0: no drive with a speed):
 * speed drives' speed or creep speed, motors' synchronous speed at the
 * pulley */
double bd_drives_reference_speed(const bd_model_def *def);
/* a motor's rated torque at its shaft, N·m: rated power over rated speed */
double bd_motor_rated_torque(const bd_motor_def *m);
/* tune the speed loop of drive d on pulley p for the inertia it moves */
void bd_drive_prepare(bd_sim *sim, bd_drive *d, const bd_pulley_body *p,
                      double reflected_inertia);
/* the drive's torque on pulley p when the shaft turns at omega (rad/s);
 * *slope (NULL: not wanted) gets −dT/dω ≥ 0, the part the pulley solve
 * takes implicitly (bd_pulley_body.torque_damping) */
double bd_drive_torque(const bd_sim *sim, bd_drive *d, const bd_pulley_body *p, double omega,
                       double *slope);
/* a speed loop takes over torque (N·m) from the holdback that held its
 * pulley (after stabilization) */
void bd_drive_take_over(bd_drive *d, double torque);
/* 1: the drive has been stopped (its stop mode acts) at time t */
int bd_drive_stopped(const bd_drive *d, double t);
/* the drive applied torque (N·m at the pulley, or its equivalent behind a
 * transmission) at time t: kept in driving_peak while it drives */
void bd_drive_note_torque(bd_drive *d, double t, double torque);

/* takeup.c */
double bd_takeup_force(const bd_takeup *tk, double t);
/* the carriage's outside pull along its axis now (N): the takeup force and
 * the pulley's weight */
double bd_takeup_pull(const bd_sim *sim, const bd_takeup *tk, const bd_pulley_body *p);
/* advance pulley p's carriage one step; returns the non-conservative work
 * done on it this step (J) and adds the set-point work to *input and to
 * *input_at_t (it is work up to t already, sim/energy.c bd_energy_at_t) */
double bd_takeup_advance(bd_sim *sim, bd_takeup *tk, bd_pulley_body *p, double *input,
                         double *input_at_t);

/* transmission.c: belt transmissions of drives (seed 004) */
struct bd_transmission *bd_transmission_create(const bd_sim *sim, bd_pulley_model *pm);
struct bd_transmission *bd_transmission_clone(const struct bd_transmission *tr);
/* torque of the transmission on its pulley this step */
double bd_transmission_torque(bd_sim *sim, bd_part *part);
/* advance the transmission over the step in which its pulley went from
 * omega_old to p->omega; books its energy */
void bd_transmission_advance(bd_sim *sim, bd_part *part, double omega_old, double *ke,
                             double *w_nc);
/* after the drives are prepared: its speed loop */
void bd_transmission_tune(const bd_sim *sim, bd_part *part);
/* elastic energy of its spans, J */
double bd_transmission_potential(const struct bd_transmission *tr);
/* motor sheave speed (rad/s) and the belt's slip on both sheaves (m/s) */
void bd_transmission_state(const bd_part *part, const bd_pulley_body *p, double *w_motor,
                           double *slip_motor, double *slip_pulley);
/* largest slip of the belt on either sheave so far, m/s */
double bd_transmission_slip_max(const bd_part *part);

#endif
