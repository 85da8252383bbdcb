/* beltdyn telescopic boom (seed 003; ../shared/spec/boom-format.md): the
 * model description of a planar boom of nested sections, its loader, and
 * the run that writes history.csv, beams.csv and summary.json.
 * SI units; angles in rad; x horizontal, y up, gravity along -y. */
#ifndef BELTDYN_BOOM_H
#define BELTDYN_BOOM_H

#include <stddef.h>
#include <stdio.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BD_BOOM_MAX_SECTIONS 16

typedef struct bd_boom_section_def {
    double length;            /* m */
    double axial_stiffness;   /* EA, N */
    double bending_stiffness; /* EI, N·m² (in the plane of the boom) */
    double mass_per_length;   /* kg/m */
    double height;            /* m between this section's top and bottom pads */
    bd_mark mark;             /* the list entry */
} bd_boom_section_def;

typedef struct bd_boom_pads_def {
    double width;          /* m along the axis */
    double stiffness;      /* N/m, normal, one pad (its two ends carry half each) */
    double mu_static;      /* - */
    double mu_dynamic;     /* - */
    double switch_speed;   /* m/s of sliding around which static turns dynamic */
    /* added keys (boom-format.md allows more): */
    double damping_ratio;  /* of a pad's own critical damping on the lighter
                              node it touches; default 0.2 */
    double smoothing;      /* m: the stiffness rises over this much
                              compression (seed 003 eq. 65); default 1e-4 */
} bd_boom_pads_def;

typedef enum bd_stroke_kind {
    BD_STROKE_TABLE = 0,   /* [time, stroke] table */
    BD_STROKE_CUBIC        /* seed 003 §9 speed profile */
} bd_stroke_kind;

typedef struct bd_boom_stroke_def {
    double initial;        /* m, stroke at t = 0 */
    bd_stroke_kind kind;
    bd_table table;        /* BD_STROKE_TABLE: stroke (m) against t (s);
                              its value at t = 0 equals `initial` */
    double v_max;          /* BD_STROKE_CUBIC: m/s (> 0) */
    double accel_time;     /* s (>= 0) */
    double hold_time;      /* s (>= 0) */
    double decel_time;     /* s (>= 0) */
    int direction;         /* +1 extend, -1 retract */
    bd_mark mark;          /* the `stroke` key */
} bd_boom_stroke_def;

typedef struct bd_luffing_cylinder_def {
    int present;
    double base[2];        /* m, fixed point (x, y) */
    double attach[2];      /* m, (s along section 1's axis from the pivot,
                              n off it, positive to the upper side); with a
                              pivot_offset, section 1's material coordinate
                              is s + pivot_offset[0] */
    double stiffness;      /* N/m of the rod (added key); default 1e9 */
    bd_mark mark;
} bd_luffing_cylinder_def;

/* added: the telescopic cylinder between sections 1 and 2 is a position
 * servo in series with its oil column */
typedef struct bd_telescopic_cylinder_def {
    double stiffness;      /* N/m; default 1e8 */
    double damping_ratio;  /* of the cylinder mode with the sections it moves;
                              default 0.2 */
} bd_telescopic_cylinder_def;

/* added: the synchronising ropes (extend and retract rope per stage) */
typedef struct bd_boom_ropes_def {
    double axial_stiffness; /* EA of one rope, N; default 2e8 */
} bd_boom_ropes_def;

typedef struct bd_boom_simulation_def {
    double duration;         /* s; 0 = the stroke profile's end + 2 s */
    double time_step;        /* s; 0 = auto (stable step) */
    double output_interval;  /* s; default 0.01 */
    bd_mark mark;
    bd_mark time_step_mark;
} bd_boom_simulation_def;

typedef struct bd_boom_def {
    char source[1024];       /* the file, for messages */
    char name[BD_NAME_MAX];  /* `name`, default the file's base name */
    double gravity;          /* m/s², default 9.81 */
    double pivot[2];         /* m, default (0, 0) */
    double pivot_offset[2];  /* added: m, the pivot from section 1's bottom end
                                in the boom frame (along the axis, across it,
                                positive to the upper side), seed 003's r1
                                (-0.956, 0.556); default (0, 0): the pivot at
                                the bottom end on the axis, as the spec has it */
    bd_table luffing_angle;  /* rad against t (s); a number is a one-point table */
    bd_luffing_cylinder_def luffing_cylinder;
    int section_count;                 /* >= 2, <= BD_BOOM_MAX_SECTIONS */
    bd_boom_section_def *sections;     /* [section_count], outermost first */
    bd_boom_pads_def pads;
    double gap;                        /* m, default 0.005 */
    bd_boom_stroke_def stroke;
    int synchronized;                  /* default 1 */
    double tip_mass;                   /* kg, default 0 (no tip_load) */
    int elements_per_segment;          /* default 8 */
    double damping_ratio;              /* default 0.01 */
    bd_telescopic_cylinder_def telescopic_cylinder;
    bd_boom_ropes_def ropes;
    bd_boom_simulation_def simulation;
    bd_mark mark;                      /* the `boom` key */
} bd_boom_def;

/* every field at the default of boom-format.md (required ones zero/empty) */
void bd_boom_def_init(bd_boom_def *d);
void bd_boom_def_free(bd_boom_def *d);

/* 1 when the YAML file's top-level mapping has a key `boom` (a boom model,
 * to be loaded with bd_boom_load), else 0 (also when it cannot be read or
 * parsed: bd_model_load then says why) */
int bd_model_is_boom(const char *path);

/* read and validate a boom model file: top-level keys `name`, `gravity`,
 * `boom` (required) and `simulation`; every problem appended to diag as
 * "FILE:LINE:COL: error: PATH: MESSAGE". 0 ok, else nonzero with *out freed. */
int bd_boom_load(const char *path, bd_boom_def *out, bd_diag *diag);
int bd_boom_load_string(const char *text, size_t len, const char *path, bd_boom_def *out,
                        bd_diag *diag);

/* the stroke profile (m) at time t, and its first two derivatives */
void bd_boom_stroke_eval(const bd_boom_stroke_def *s, double t, double *stroke, double *speed,
                         double *accel);
/* the time at which the profile reaches its last value */
double bd_boom_stroke_end(const bd_boom_stroke_def *s);

/* ---- the run ---- */

typedef struct bd_boom bd_boom;

/* compile: nodes, elements, time step; checks what the loader cannot
 * (overlap of the sections over the whole stroke, ...). 0 ok */
int bd_boom_create(const bd_boom_def *def, bd_boom **out, bd_diag *diag);
void bd_boom_free(bd_boom *b);
/* what `check` prints: sections, masses, nodes, step, estimates */
void bd_boom_describe(const bd_boom *b, FILE *f);

/* the run's extremes (summary.json `boom`) */
typedef struct bd_boom_result {
    double tip_x_max_m, tip_y_max_m;
    double tip_deflection_max_m;              /* distance from the rigid boom's tip */
    double telescopic_cylinder_force_max_N;
    double luffing_force_max_N;               /* N, or N·m without a cylinder */
    double pad_normal_force_max_N;
    double balance_error_rel;
    double kinetic_final_J;
    long steps;
    double time_step_s;
    int nodes;
} bd_boom_result;

/* settle under gravity at t = 0 (time held), then run to the duration,
 * writing history.csv, beams.csv and summary.json into opt->out_dir (none
 * when out_dir is NULL). BD_RUN_OK / _FAILED (err says when, where, why) /
 * _INTERRUPTED */
int bd_boom_run(bd_boom *b, const bd_run_options *opt, char *err, size_t errlen);
void bd_boom_get_result(const bd_boom *b, bd_boom_result *r);

#ifdef __cplusplus
}
#endif

#endif
