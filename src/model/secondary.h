/* The secondary and special resistances one by one (model-format.md
 * `design.secondary: individual`), from a model's definition: at each
 * pulley (wrap, bearings, cleaners) and at the feed point (loading
 * inertia, skirts). The formulas are laws/secondary_resistance.h's; this
 * file says which pulleys and which inputs. The static calculation and
 * the run both ask it, so they apply the same resistances. */
#ifndef BD_SECONDARY_H
#define BD_SECONDARY_H

#include <math.h>

#include "beltdyn/model.h"

/* m/s, the speed material lands at on a belt running at v: the design's
 * loading_speed in individual mode (none otherwise), and no faster than
 * the belt: material landing faster does not push it (ISO 5048's F_bA
 * and its acceleration zone are 0; in static as in the run) */
static inline double bd_landing_speed(const bd_model_def *m, int individual, double v)
{
    return individual ? fmin(m->design.loading_speed, v) : 0.0;
}

/* what a pulley takes out of the belt, N */
typedef struct bd_pulley_resistance {
    double wrap;      /* bending over it (non-driving pulleys) */
    double bearing;   /* its bearings (pulleys in design.bearings) */
    double cleaners;  /* the cleaners scraping there */
} bd_pulley_resistance;

/* what the feed point takes, N, at belt speed v */
typedef struct bd_feed_resistance {
    double loading_inertia;      /* F_bA */
    double acceleration_length;  /* m, l_b */
    double loading_skirts;       /* F_f: skirts in the acceleration zone */
    double skirts;               /* F_gl: skirts over their whole length */
} bd_feed_resistance;

/* a pulley's resistance as a function of its belt tensions, with its
 * constants taken once from the definition (a run evaluates it every
 * step) */
typedef struct bd_pulley_resistance_law {
    int active;               /* it has a resistance of its own */
    double wrap0, wrap_per_N; /* F_l = wrap0 + wrap_per_N·(mean tension) */
    double bearing_per_N;     /* F_t = bearing_per_N·|F_T|; 0 without bearings */
    double weight;            /* N, its rotating parts' weight (in F_T) */
    double cleaners;          /* N, the cleaners scraping there */
} bd_pulley_resistance_law;

/* 1: the model asks for the resistances one by one */
int bd_secondary_individual(const bd_model_def *m);
/* the pulley the cleaners scrape at: design.cleaners.pulley, else the
 * discharge pulley, else the first drive; -1 without cleaners */
int bd_secondary_cleaner_pulley(const bd_model_def *m);
/* pulley p's resistance law (active 0 when it has none) */
void bd_secondary_pulley_law(const bd_model_def *m, int p, bd_pulley_resistance_law *law);
/* its resistances with T_in arriving along the unit direction u_in and
 * T_out leaving along u_out (N) */
void bd_secondary_pulley_eval(const bd_pulley_resistance_law *law, double T_in, double T_out,
                              const double u_in[2], const double u_out[2],
                              bd_pulley_resistance *out);
/* the feed point's resistances at belt speed v (zero without material) */
void bd_secondary_feed(const bd_model_def *m, double v, bd_feed_resistance *out);

#endif
