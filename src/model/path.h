/* Belt path: the closed loop of wrap arcs and straight common tangents that
 * the belt follows at t = 0, and the path coordinate s along it.
 *
 * Order of segments (n pulleys): span 0 (leaves pulley 0), arc of pulley 1,
 * span 1, arc of pulley 2, ..., span n-1, arc of pulley 0. s = 0 where the
 * belt leaves pulley 0 (model-format.md). Segment 2i is span i, segment
 * 2i+1 is the arc of pulley (i+1) mod n. */
#ifndef BD_PATH_H
#define BD_PATH_H

#include "beltdyn/model.h"

typedef enum bd_segment_kind { BD_SEGMENT_SPAN = 0, BD_SEGMENT_ARC } bd_segment_kind;

/* A piece of a routed span (one with vertical curves or corners): a
 * straight line or a circular arc, the pieces of a span joined end to
 * end. A straight span has none. */
typedef struct bd_path_piece {
    int is_arc;
    double s0;         /* m, path coordinate of its start */
    double length;     /* m */
    double p0[2];      /* m, start point */
    double dir[2];     /* line: unit direction of travel */
    double centre[2];  /* arc: centre of curvature */
    double radius;     /* arc: m */
    double angle0;     /* arc: polar angle of p0 about the centre, rad */
    double sweep;      /* arc: signed angle swept, rad (+ ccw) */
} bd_path_piece;

typedef struct bd_path_segment {
    bd_segment_kind kind;
    int pulley;        /* span: the pulley it leaves; arc: the pulley wrapped */
    double s0;         /* m, path coordinate of its start */
    double length;     /* m */
    double p0[2];      /* m, start point */
    double p1[2];      /* m, end point */
    double dir[2];     /* span: unit direction of travel where it starts;
                          arc: where it ends */
    double dir1[2];    /* span: unit direction of travel where it ends */
    int piece_first, piece_count;  /* span: its pieces (0: straight) */
    double centre[2];  /* arc: pulley centre */
    double radius;     /* arc: m */
    double angle0;     /* arc: polar angle of p0 about the centre, rad */
    double sweep;      /* arc: signed angle swept, rad (+ ccw), |sweep| = wrap */
} bd_path_segment;

typedef struct bd_path {
    int pulley_count;
    int segment_count;         /* 2 * pulley_count */
    bd_path_segment *segments; /* [segment_count] */
    double length;             /* m, whole loop */
    int piece_count;
    bd_path_piece *pieces;     /* [piece_count] of the routed spans */
} bd_path;

/* build from pulley centres, radii and wrap senses; problems (pulleys that
 * overlap so no tangent exists) go to diag with the pulley's mark. 0 = ok */
int bd_path_build(const bd_model_def *m, bd_path *path, bd_diag *diag);
void bd_path_free(bd_path *path);

/* point and unit tangent (direction of travel) at path coordinate s
 * (taken modulo the loop length) */
void bd_path_point(const bd_path *path, double s, double p[2], double tangent[2]);
/* the point of a routed span's piece at distance u from its start, and the
 * travel direction there */
void bd_path_piece_point(const bd_path_piece *g, double u, double p[2], double tangent[2]);
/* index of the segment holding s (s modulo the loop length) */
int bd_path_segment_at(const bd_path *path, double s);

/* along a circular arc (centre, radius, polar angle of its start, signed
 * sweep): the distance from its start of the point nearest (x, y), the
 * circle's part outside the arc split half before it (negative), half
 * beyond its end */
double bd_path_arc_position(const double centre[2], double radius, double angle0, double sweep,
                            double x, double y);
/* along span g: the distance from its start of the point nearest (x, y);
 * before its start negative, beyond its end more than its length */
double bd_path_span_project(const bd_path *path, const bd_path_segment *g, double x, double y);
/* the unit normal of travel direction t on the side away from the idlers
 * (they stand below the belt): up, +x for a vertical t */
static inline void bd_path_up_normal(const double t[2], double n[2])
{
    n[0] = -t[1];
    n[1] = t[0];
    if (n[1] < 0.0 || (n[1] == 0.0 && n[0] < 0.0)) {
        n[0] = -n[0];
        n[1] = -n[1];
    }
}

/* the belt's unit direction of travel where it arrives on pulley i's wrap
 * (the end of the span before it, dir1: on a routed span not its start's)
 * and where it leaves (the start of the span after it) */
void bd_path_wrap_dirs(const bd_path *path, int pulley, const double **u_in,
                       const double **u_out);
/* the span leaving pulley i, and the arc of pulley i */
const bd_path_segment *bd_path_span(const bd_path *path, int pulley);
const bd_path_segment *bd_path_arc(const bd_path *path, int pulley);
/* s of the point at fraction `at` (0..1) along span `pulley` */
double bd_path_span_s(const bd_path *path, int pulley, double at);
/* the region of the path that carries material (model-format.md
 * `material`): from the feed point, *s_feed, to where the belt reaches the
 * discharge pulley (the start of its arc), *length along the path */
void bd_path_loaded_region(const bd_path *path, const bd_material_def *mat, double *s_feed,
                           double *length);
/* whether path coordinate s lies in the region [s_from, s_from + length] */
int bd_path_in_region(const bd_path *path, double s, double s_from, double length);
/* m of [x0, x0 + w] (path coordinates) inside that region */
double bd_path_region_overlap(const bd_path *path, double x0, double w, double s_from,
                              double length);
/* wrap angle of pulley i, rad (>= 0) */
double bd_path_wrap_angle(const bd_path *path, int pulley);

#endif
