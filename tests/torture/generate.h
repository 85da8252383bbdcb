/* A seeded generator of random but sensible belt conveyors (issue 10): the
 * models nobody tuned the engine for. Each seed gives one conveyor, the same
 * on every machine (own PRNG, printed with %.6g): a head, tail or dual
 * drive; a head-loop, tail-loop or horizontal tail takeup; incline or
 * decline; empty or loaded; speed or motor control with drive inertia from
 * 0; friction, damping 0–0.2, element lengths up to the default,
 * initial_state static or rest, with or without stabilization. Its design
 * rules are the ones a conveyor engineer would use (enough slack-side
 * tension not to slip while starting, sag below 1.5 %, belt strain below
 * 1.2 %), so every generated conveyor is one that should run. */
#ifndef BD_TORTURE_GENERATE_H
#define BD_TORTURE_GENERATE_H

#include <stddef.h>

typedef struct bd_gen_options {
    const char *formulation;   /* "discrete" or "axial" */
    double max_length;         /* m, upper bound of the conveyor length */
    double settle;             /* s of steady running after the start */
    int curves;                /* 1: a vertical curve on the carry span of some (--curves) */
    double element_scale;      /* > 0: the discrete belt's element length times this
                                  (--element-scale, for mesh studies), 0: as drawn */
    double bending_stiffness;  /* > 0: the belt's EI in N·m² (--bending-stiffness), 0: none */
} bd_gen_options;

/* what the generator chose that the checks need besides the model file */
typedef struct bd_gen_info {
    char summary[256];         /* one line: layout, length, incline, load */
    double speed;              /* m/s target belt speed */
    double ramp_end;           /* s, when the start is over */
    double duration;           /* s */
    int motor;                 /* 1: the drives are induction motors */
} bd_gen_info;

/* writes the YAML of conveyor `seed` into buf (NUL-terminated); returns its
 * length, or a value ≥ size when buf is too small */
size_t bd_gen_conveyor(unsigned long seed, const bd_gen_options *opt, char *buf, size_t size,
                       bd_gen_info *info);

#endif
