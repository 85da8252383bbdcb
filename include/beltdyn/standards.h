/* beltdyn design-standard ("static") calculation: DIN 22101 / ISO 5048 and
 * CEMA belt tensions at steady running (seed 001 ch. 2, model-format.md
 * `design`, cli.md `static`). SI units throughout; docs/standards.md lists
 * every formula, its source and what the program assumes. */
#ifndef BELTDYN_STANDARDS_H
#define BELTDYN_STANDARDS_H

#include <stdio.h>

#include "beltdyn/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* one straight span of the belt path (the span leaving pulley `pulley`) */
typedef struct bd_static_span {
    int pulley;              /* index of the pulley the span leaves */
    int to;                  /* index of the pulley it runs to */
    double length_m;         /* m, straight tangent length */
    double lift_m;           /* m, end height minus start height */
    double slope_rad;        /* rad, inclination (+ uphill in travel) */
    double loaded_length_m;  /* m carrying material (0 if unloaded) */
    double idler_spacing_m;  /* m, largest spacing of its idler sets; 0 none */
    double mR_kg_per_m;      /* kg/m, sum of rotating_mass/spacing */
    int loaded;              /* 1: carries material (from feed to discharge) */
    int carry;               /* 1: carrying run (sag check, CEMA Kx/Ky) */
    double main_N;           /* N, main resistance (DIN F_H,i; CEMA friction) */
    double secondary_N;      /* N, secondary (DIN F_N,i share; CEMA T_am) */
    double slope_N;          /* N, slope resistance (lift of belt + load) */
    double special_N;        /* N, special resistances acting on it (skirts,
                                cleaners; secondary: individual) */
    double T_start_N;        /* N, belt tension where the span starts */
    double T_end_N;          /* N, belt tension where it ends */
    double cema_Kx;          /* N/m, CEMA eq 2.2 (carry spans; 0 otherwise) */
    double cema_Ky;          /* -, CEMA Ky used on this span (0 for DIN) */
} bd_static_span;

/* a pulley's own resistances (secondary: individual), N */
typedef struct bd_static_pulley {
    double T_in_N, T_out_N;  /* N, belt tension arriving and leaving */
    double wrap_N;           /* bending of the belt over it (non-driving) */
    double bearing_N;        /* its bearings (design.bearings) */
    double cleaners_N;       /* the cleaners scraping there */
} bd_static_pulley;

typedef struct bd_static_result {
    bd_standard standard;
    /* resistances summed over the loop, N (total = effective tension) */
    double main_N, secondary_N, slope_N, total_N;
    double special_N;           /* N, F_S (0 unless secondary: individual) */
    /* design.secondary: individual (ISO 5048 §5.2): secondary_N is the sum
     * of the first four, special_N of skirts and cleaners */
    int individual;
    double loading_inertia_N;   /* F_bA */
    double loading_skirts_N;    /* F_f, skirts in the acceleration zone */
    double wrap_N;              /* Σ over the non-driving pulleys */
    double bearings_N;          /* Σ over design.bearings */
    double skirts_N;            /* F_gl over the skirts' whole length */
    double cleaners_N;          /* F_r */
    double acceleration_length_m;  /* l_b */
    bd_static_pulley *pulleys;  /* [span_count] (NULL unless individual) */
    double effective_tension_N; /* N, Te = T1 - T2 over all drives; < 0 regenerative */
    double power_kW;            /* kW, Te * speed at the drive pulley(s) */
    double motor_power_kW;      /* kW, power_kW / design.efficiency */
    double speed_mps;           /* m/s design speed (0: unknown, no power) */
    int regenerative;           /* 1 when Te < 0: the drive brakes */
    /* the drive: the first pulley with `drive`; Te is shared equally among
     * drive_count drives; T1/T2/wrap/mu are those of the first drive */
    int drive_pulley;
    int drive_count;
    double T1_N;                /* N, tight side of the first drive */
    double T2_N;                /* N, slack side of the first drive */
    double wrap_angle_rad;      /* rad, wrap of the first drive (from the path) */
    double mu;                  /* -, its dynamic friction coefficient */
    double T2_min_slip_N;       /* N, |Te_drive| / (e^(mu*phi) - 1) */
    double T_min_sag_N;         /* N, (m'G + m'L) g a / (8 sag_ratio) */
    double sag_spacing_m;       /* m, the largest carry idler spacing a */
    double T_max_N, T_min_N;    /* N, extremes of the span-end tensions */
    double safety_factor;       /* belt.rated_tension / T_max_N; 0 if not rated */
    int takeup_pulley;          /* index of the level-setting takeup, -1 none */
    double takeup_force_N;      /* N, takeup pull (fixed: the reaction); 0 none */
    double carry_length_m;      /* m, length used for C auto */
    /* DIN/ISO */
    double f;                   /* -, artificial friction coefficient used */
    double C;                   /* -, secondary-resistance coefficient used */
    /* CEMA */
    double cema_Kt, cema_Ai_N, cema_C1;
    int cema_iterations;
    int span_count;
    bd_static_span *spans;      /* [span_count], in the order of travel */
    int warning_count;
    char **warnings;            /* [warning_count] failed checks, in words */
    int note_count;
    char **notes;               /* [note_count] assumptions the program made */
} bd_static_result;

/* design-standard calculation of the validated model m with m->design (its
 * defaults when m->design.present is 0). Returns 0 and fills *out (free it
 * with bd_static_free); otherwise nonzero with the problem in diag. */
int bd_static_compute(const bd_model_def *m, bd_static_result *out, bd_diag *diag);
void bd_static_free(bd_static_result *r);

/* human-readable table (units in every header) */
void bd_static_print_table(const bd_static_result *r, const bd_model_def *m, FILE *f);
/* cli.md `static --json` object plus extra keys; malloc'd, caller frees */
char *bd_static_to_json(const bd_static_result *r, const bd_model_def *m);

/* name as in the model file: "din22101", "iso5048", "cema" */
const char *bd_standard_name(bd_standard s);

#ifdef __cplusplus
}
#endif
#endif
