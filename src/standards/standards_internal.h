/* shared state of the design-standard calculation: the belt loop cut into
 * sections (a span, or the unloaded and loaded parts of the feed span) with
 * their masses and geometry; din22101.c and cema.c fill the resistances,
 * standards.c propagates tensions and checks. */
#ifndef BD_STANDARDS_INTERNAL_H
#define BD_STANDARDS_INTERNAL_H

#include "beltdyn/standards.h"
#include "model/path.h"

typedef struct bd_std_section {
    int span;          /* pulley index of the span holding it */
    double length;     /* m */
    double lift;       /* m, Δh = end y - start y */
    double cos_delta;  /* -, cos of the inclination */
    double mL;         /* kg/m material on it (0 unloaded) */
    double mR;         /* kg/m rotating idler mass, Σ rotating_mass/spacing */
    double spacing;    /* m, largest idler spacing on its span, 0 none */
    double roll_radius;/* m, radius of that idler set's rolls */
    int carry;         /* carrying run */
    double main, secondary, slope; /* N, resistances (filled per standard) */
    /* secondary: individual (individual.c): the resistances of the pulley
     * the section leaves, in T0: secondary (wrap, bearings) and special
     * (its cleaners: they scrape the belt on the pulley, as the run has
     * them, sim/pulley_resistance.c); and what acts on the section from its
     * start on, in its rise (feed point; skirts, special) */
    double pulley_res, pulley_special, local_secondary, local_special;
    double Kx, Ky;     /* CEMA factors used (0 for DIN) */
    double T0, T1;     /* N, tension at its start and end */
    double T0_prev, T1_prev; /* N, previous iteration (CEMA) */
} bd_std_section;

typedef struct bd_std_ctx {
    const bd_model_def *m;
    bd_design_def design;
    bd_path path;
    double g;          /* m/s² */
    double mG;         /* kg/m belt */
    double speed;      /* m/s design speed */
    int n;             /* pulleys = spans */
    int nsec;
    bd_std_section *sec;  /* [nsec] in the order of travel, from span 0 */
    int *is_drive;     /* [n] */
    int drive_count;
    int drive;         /* first drive pulley */
    int takeup;        /* first takeup pulley, -1 none */
    double takeup_force;  /* N */
    int feed_span;     /* span holding the feed point, -1 without material */
    bd_static_result *out;
} bd_std_ctx;

/* append to out->warnings / out->notes (printf-style) */
void bd_std_warn(bd_static_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void bd_std_note(bd_static_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* total resistance of the loop (Σ main + secondary + slope and the
 * individual resistances), N */
double bd_std_total(const bd_std_ctx *c);
/* the first section of a span; tension arriving at and leaving pulley p */
int bd_std_first_sec(const bd_std_ctx *c, int span);
double bd_std_T_arrive(const bd_std_ctx *c, int p);
double bd_std_T_leave(const bd_std_ctx *c, int p);
/* tensions T0/T1 of every section from the resistances and the level rule
 * (takeup, else initial_tension at the drive's slack side) */
void bd_std_propagate(bd_std_ctx *c);

/* per-standard resistances; cema also iterates with bd_std_propagate */
void bd_din22101_resistances(bd_std_ctx *c);
int bd_cema_resistances(bd_std_ctx *c);
/* design.secondary: individual, after the DIN resistances: the secondary
 * and special resistances one by one in place of (C − 1)·F_H, iterated
 * with bd_std_propagate (wrap and bearings depend on the tensions); 1 when
 * out of memory */
int bd_individual_resistances(bd_std_ctx *c);
/* CEMA Table 2.1 (seed 001): Ky by eq 2.3 for average tension T (N), idler
 * spacing S (m) and Wb + Wm (kg/m); *clamped set when (T, S) left the table */
double bd_cema_ky(double T_avg, double spacing, double W_kg_per_m, int *clamped);
/* DIN 22101 Table 2.3 (seed 001): C by conveyor length (m) */
double bd_din22101_C(double L);

#endif
