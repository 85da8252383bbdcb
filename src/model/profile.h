/* A conveyor given by its route (model-format.md `profile`): the carry
 * strand's chainage/elevation points with vertical curves, the head and
 * tail pulleys, the takeup and the idlers. bd_profile_layout turns it into
 * pulleys, routed spans and idler sets, which is all the rest of beltdyn
 * sees. */
#ifndef BD_PROFILE_H
#define BD_PROFILE_H

#include "beltdyn/model.h"

typedef struct bd_profile_curve {
    double at;        /* index of the inner point it rounds */
    double radius;    /* m */
    bd_mark mark;
} bd_profile_curve;

typedef struct bd_profile_takeup {
    bd_takeup_def t;  /* first: the takeup's own fields parse into it */
    int at_head;      /* 1: vertical gravity loop behind the head; 0: tail */
    double depth;     /* m, loop: takeup centre below the bends' (0 = default) */
} bd_profile_takeup;

typedef struct bd_profile_def {
    int point_count;
    double (*points)[2];      /* [point_count] chainage, elevation: top of the carry idlers */
    bd_mark *point_marks;     /* [point_count] where each was given */
    int curve_count;
    bd_profile_curve *curves; /* [curve_count] */
    bd_pulley_def head, tail;
    bd_profile_takeup takeup;
    double return_drop;       /* m, carry to return strand at the idlers */
    double bend_radius;       /* m, bends and takeup pulley of a loop; 0 = tail's */
    bd_idler_set_def carry, ret;
    bd_mark mark;
} bd_profile_def;

/* the pulleys (tail, head, and for a head loop bend1, takeup, bend2), the
 * routes of the carry and return strands and the two idler sets, into m
 * (its pulleys and idler sets, which must be empty). Problems go to diag
 * at the profile's marks; 0 = ok. The tables parsed into head, tail and
 * takeup pass to m's pulleys (freed here when the layout fails) */
int bd_profile_layout(bd_profile_def *p, bd_model_def *m, bd_diag *diag);
/* its points and curves */
void bd_profile_free(bd_profile_def *p);
/* the tables parsed into head, tail and takeup, when no layout took them */
void bd_profile_free_tables(bd_profile_def *p);

#endif
