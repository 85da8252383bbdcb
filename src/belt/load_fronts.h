/* The loaded region of the belts whose nodes are stations fixed on the
 * path (axial, moving_node; docs/physics.md §11): the material lies on
 * [s_feed + d_tail, s_feed + d_head]. A free front rides with the belt, a
 * pinned one stays at the feed point (tail, while feeding) or the
 * discharge (head). The formulation says what a node's load is
 * (`reload`); this file moves the fronts and says which nodes they
 * crossed. */
#ifndef BD_LOAD_FRONTS_H
#define BD_LOAD_FRONTS_H

#include "model/system.h"

typedef struct bd_load_fronts {
    double s_feed;          /* build: m, path coordinate of the feed point */
    double load_len;        /* build: m, feed point → discharge pulley */
    double d_tail, d_head;  /* step (material): m from the feed point,
                               0 ≤ d_tail ≤ d_head ≤ load_len */
    int tail_free, head_free;
    int e_tail, e_head;     /* element holding each front (a search hint) */
} bd_load_fronts;

/* the region from the model's material, loaded at t = 0 or not; the
 * search hints at element `hint` */
void bd_fronts_init(const bd_sim *sim, bd_load_fronts *f, int hint);
/* the loaded region on the loop, [from, to] with from in [0, L); or with
 * `full` all that can be loaded; 0 when empty */
int bd_fronts_zone(const bd_sim *sim, const bd_load_fronts *f, int full, double *from,
                   double *to);
/* m of [a, b] that is loaded (or can be, `full`) */
double bd_fronts_loaded_length(const bd_sim *sim, const bd_load_fronts *f, int full, double a,
                               double b);
/* weight of belt and material along the path from a to b, ∫ m'·g dy, in
 * `pieces` pieces (model/rest_weight.c) */
double bd_fronts_weight(const bd_sim *sim, const bd_load_fronts *f, double a, double b,
                        int pieces);
/* the material phase: the head rides with the belt until it reaches the
 * discharge pulley, the tail once feeding has stopped; each node of the
 * elements a front crossed is reloaded. len[e] is element e's length
 * along the path. */
void bd_fronts_move(bd_sim *sim, bd_load_fronts *f, const double *len,
                    void (*reload)(bd_sim *sim, int node));

#endif
