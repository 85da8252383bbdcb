/* The secondary and special resistances one by one (model-format.md
 * `design.secondary: individual`), from a model's definition: at each
 * pulley (wrap, bearings, cleaners) and at the feed point (loading
 * inertia, skirts). The formulas are laws/secondary_resistance.h's; this
 * file says which pulleys and which inputs. The static calculation and
 * the run both ask it, so they apply the same resistances. */
#ifndef BD_SECONDARY_H
#define BD_SECONDARY_H

#include "beltdyn/model.h"

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

/* 1: the model asks for the resistances one by one */
int bd_secondary_individual(const bd_model_def *m);
/* the pulley the cleaners scrape at: design.cleaners.pulley, else the
 * discharge pulley, else the first drive; -1 without cleaners */
int bd_secondary_cleaner_pulley(const bd_model_def *m);
/* 1: pulley p has a resistance of its own (wrap, bearing or cleaners) */
int bd_secondary_at_pulley(const bd_model_def *m, int p);
/* pulley p's resistances with T_in arriving along the unit direction
 * u_in and T_out leaving along u_out (N) */
void bd_secondary_pulley(const bd_model_def *m, int p, double T_in, double T_out,
                         const double u_in[2], const double u_out[2],
                         bd_pulley_resistance *out);
/* the feed point's resistances at belt speed v (zero without material) */
void bd_secondary_feed(const bd_model_def *m, double v, bd_feed_resistance *out);

#endif
