/* Runs one model and checks the invariants every conveyor must satisfy
 * (issue 10): it completes; energy balances; no energy is created by a
 * dissipative force; the belt reaches the target speed; in steady running
 * the drives deliver the force of the model's own resistance law. */
#ifndef BD_TORTURE_INVARIANTS_H
#define BD_TORTURE_INVARIANTS_H

#include "beltdyn/sim.h"

typedef struct bd_torture_result {
    int loaded;                /* the model loaded and built */
    int completed;             /* the run reached its duration */
    char message[700];         /* why not */
    double balance;            /* largest |E_k+E_p+E_d−E_in−E_0| / energy scale */
    double dissipation_drop;   /* largest fall of E_d between checks / scale */
    double drop_from_s, drop_to_s; /* ... between the checks at these times */
    double speed, speed_target;/* m/s, mean over the last window */
    double force, force_law;   /* N, mean drive force over the last window, the law */
    double force_scale;        /* N, the law's terms summed in magnitude */
    double wall_s;
    int nodes;
    int not_at_rest;           /* stabilization stopped short of rest */
    int steady;                /* the last three checks agreed */
    double ran_s;              /* s simulated, the extension included */
    double averaged_s;         /* s over which force and speed were averaged */
} bd_torture_result;

typedef struct bd_torture_options {
    double window;             /* s of steady running averaged at the end */
    double target_speed;       /* m/s of a speed drive; 0: from the model (a
                                  speed drive's speed, the motor curve's) */
    /* running is steady when the means of three successive checks differ
     * by no more than these (force: of the law's terms summed in
     * magnitude; speed: relative); until then the run is extended window
     * by window, by at most max_extension s past its duration */
    double steady_force, steady_speed, max_extension;
} bd_torture_options;

/* run the model text (YAML) to its duration, and on until steady */
void bd_torture_run(const char *yaml, const char *label, const bd_torture_options *opt,
                    bd_torture_result *res);


#endif
