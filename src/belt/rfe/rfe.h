/* The rigid-finite-element (RFE) belt of seed 000 (Guo & Wang 2020): the
 * belt cut into rigid elements of length l0, each with a mass centre
 * (x, y), an orientation φ, its mass and rotary inertia (§2.1, assumption
 * i), joined by spring–damping elements (SDE, Voigt) with axial, shear and
 * bending stiffness and damping (§2.3), moving by Lagrange's equations of
 * the second kind (§2.4), written here in absolute coordinates
 * (docs/physics.md §15 says why).
 *
 * It extends the lumped belt (belt/lumped): the elements' mass centres are
 * its nodes, and the SDE between elements i and i + 1 is its element i.
 * The SDE's axial part is the lumped element's (EA/l0 on the stretch of
 * the belt between the centres, round a pulley along the shell,
 * wrap_elements.c), and the centres meet pulleys and idlers through the
 * lumped belt's contacts, friction laws and material. What the rigid
 * elements add is in this folder: the orientations φ, the SDE's shear and
 * bending, the rotary inertia, and the rotations' implicit step
 * (rotation_solve.c). */
#ifndef BD_RFE_H
#define BD_RFE_H

#include "belt/lumped/lumped.h"

/* Variable topology (seed 000 §3.1; sections.c): a long section stands
 * on a window of a straight span on its idlers, fixed on the path, from
 * the middle of one bay to the middle of another, clear of pulleys and
 * idler curves by a margin; the belt flows through it */
typedef struct bd_rfe_window {
    double p0[2], d[2];       /* m, the span's start; unit direction of travel */
    double cos_slope;         /* |d_x|: the weight's share normal to the span */
    double a, b;              /* m along d from p0: where the window begins and ends */
    double bay;               /* m, its idlers' spacing */
    int before, after;        /* the window that ends where it begins, and the one
                                 that begins where it ends, or −1 */
    int idler_first, idler_count;  /* the idlers it carries (model idler_list) */
    int has_feed;             /* the feed point lies in it (its section is
                                 summed element by element: mass lands there) */
    /* its idlers' sums about a (x = an idler's place less a): of
     * kr = I/R², Σ kr, Σ kr·x, Σ kr·x² (kg, kg·m, kg·m²), and of
     * c = rr·g·cos δ·share, Σ c and Σ c·x (m²/s², m³/s²) */
    double k0, k1, k2, c0, c1;
    double along_min, along_max;  /* m, its first and last idler's place along d */
    int idler_lo, idler_hi;   /* those two idlers (model index), or −1: they
                                 carry what the free belt beside the section's
                                 first and last element presses on it */
} bd_rfe_window;

/* an affine function of an idler's place x in its window, f0 + f1·x */
typedef struct bd_rfe_affine {
    double f0, f1;
} bd_rfe_affine;

/* the long section on window w now: elements first .. first + count − 1
 * (round the loop), on the window's line, evenly spaced between its two
 * ends, whose places along the line and speeds are its two degrees of
 * freedom (sections.c) */
typedef struct bd_rfe_section {
    int first, count;         /* count 0: not tied yet */
    double s1, s2;            /* m along the line: its first and last element */
    double v1, v2;            /* m/s along the line, at the half step */
    /* step (supports): what the idlers it carries add, at t − Δt/2: their
     * rolls' inertia as mass at its ends (K, kg), their momentum (P,
     * kg·m/s) and their rolling resistance (F, N) */
    double k11, k12, k22, p1, p2, f1, f2;
    /* its mass matrix Σ m_j·N_j·N_jᵀ, kept from when it last changed, and
     * its mean mass per length Σm/(count·l0), kg/m */
    double m11, m12, m22, mbar;
    /* step (forces): summed element by element (the feed in its window,
     * or an idler of it not carried), else from its ends and its mass */
    int full;
    /* its elements stand where s1, s2 say (place); a section summed from
     * its ends moves only those in the step, the others when read
     * (bd_rfe_sync) */
    int placed;
    /* its rolls turn with it: every idler of its window was carried last
     * step, each then at ω = v(ξ)/R with ξ from where its ends stood then
     * (s1p, s2p) and v its speeds now; nothing has changed it since */
    int stuck;
    double s1p, s2p;
    /* step: its idlers summed from the window's sums (stuck, rolling one
     * way faster than BD_ROLLING_SPEED); lazy: their rolls left to it */
    int idler_sums, lazy_idlers;
    int rolls_written;        /* its lazy rolls written out since it last moved */
    /* step (supports), with idler_sums: an idler's ξ and its roll's ω⁻·R
     * as affine functions of its place in the window (sections.c) */
    bd_rfe_affine xi, wm;
} bd_rfe_section;

/* compiled data (behind model->belt_model) */
typedef struct bd_rfe_model {
    bd_lumped_model lumped;   /* first: the centres' chain and its contacts
                                 (its k_bend is 0: bending is the SDE's) */
    double k_shear;           /* N·m = GA·l0: an SDE's energy ½·k_shear·γ² */
    double c_shear;           /* N·m·s: its dashpot on dγ/dt */
    double k_bend;            /* N·m/rad = EI/l0 */
    double c_bend;            /* N·m·s/rad */
    double gyration2;         /* m², (l0² + h²)/12 */
    double inertia;           /* kg·m², an element's J = m′·l0·gyration2 (the
                                 belt's section; material adds mass, not J) */
    double *k_align;          /* [n] N·m/rad: the tension's pull at element i's
                                 joints turning it into the line of the belt,
                                 l0·T of the belt at rest there (build.c) */
    double *c_align;          /* [n] N·m·s/rad, its dashpot */
    double k_align_max;       /* N·m/rad, the largest (stable step) */
    /* variable topology (sections.c): none when off or nowhere */
    bd_rfe_window *windows;   /* [window_count] */
    int window_count;
    double kink_share;        /* the kink at their ends, a share of the running
                                 resistance (sections.c kink_spans) */
    int kink_free_spans;      /* spans left free for their kink */
    int *idler_list;          /* the idlers the windows carry, window by window */
    int *idler_window;        /* [idler_count] the window carrying idler i, or −1 */
    double *idler_share;      /* [idler_count] m of the span each idler carries
                                 (sim/running_law.c's rule) */
    double *idler_along;      /* [idler_count] m, a window's idler's place along
                                 its line */
} bd_rfe_model;

/* state (behind sim->belt_data) */
typedef struct bd_rfe {
    bd_lumped lumped;         /* first: the centres' chain */
    /* integrate: element i's orientation φ as its unit vector (cos φ,
     * sin φ), turned by ω·Δt each step (no angle is kept: it needs no
     * cosine in the step and does not grow round the loop) */
    double *ct, *st;          /* [n] */
    double *omega;            /* [n] rad/s at the half step */
    /* forces phase */
    double *tq, *tqn;         /* [n] N·m on element i, its non-conservative part */
    double *q, *qd;           /* [n] N·m, SDE e's shear force k·γ + c·dγ/dt, its dashpot part */
    double *mb, *mbd;         /* [n] N·m, SDE e's bending moment, its dashpot part */
    double *thdot;            /* [n] rad/s, the turn rate of the line from centre e to e + 1 */
    double *px, *py;          /* [n] 1/m, that line's perp(u)/|x_e+1 − x_e| = ∂θ_u/∂x_e+1 */
    double *h, *hd;           /* [n] N·m, element i's aligning moment, its dashpot part */
    /* integrate: element i's rotation, power of its non-conservative
     * torque (W) and twice its kinetic energy (J) */
    double *pw, *ek;          /* [n] */
    /* integrate: the implicit rotations' system (rotation_solve.c): its
     * factors for the step rdt (0: none yet) — pivots' reciprocals,
     * eliminated couplings, the response to element 0, row 0's Schur
     * complement's reciprocal, the uniform coupling — and Δω */
    double *rinv, *rcp, *rz;  /* [n] */
    double rs0, ro, rdt;
    double *rb;               /* [n] rad/s, Δω = ω⁺ − ω⁻ of the step */
    /* variable topology (sections.c): node i's window (−1: free), the
     * sections, the free nodes' runs for the step */
    int *sec;                 /* [n] */
    bd_rfe_section *sections; /* [window_count] */
    int *carried;             /* [idler_count] step: the section carrying idler i, or −1 */
    int *free_idlers;         /* the idlers no section carries, pressing on the belt */
    int free_idler_n, idlers_stale;   /* their count; carried changed since listed */
    int tied;                 /* the sections have been tied */
    int *run_first, *run_count;   /* [n] */
    int run_n;
    /* the nodes whose forces the step takes (the free ones, the sections'
     * ends, a full section's every one), in runs; rebuilt when stale */
    int *live_first, *live_count; /* [n] */
    int live_n, live_stale;
    int *order;               /* [window_count] the tied sections round the loop */
    /* what the topology did (summary.json) */
    long joined, left;
    double booked_lost, booked_gained;   /* J, the events' energy change */
    int belt_dof_min, belt_dof_max;
} bd_rfe;

static inline bd_rfe *bd_rfe_of(const bd_sim *sim)
{
    return (bd_rfe *)sim->belt_data;
}

static inline const bd_rfe_model *bd_rfe_model_of(const bd_sim *sim)
{
    return (const bd_rfe_model *)sim->model->belt_model;
}

/* whether the SDE between elements i and j = i + 1 joins two tied
 * elements (inside a section, or where two meet): the sections' lines
 * hold both across and in their turn, so it has no shear or bending
 * (forces.c), and its two elements no turn to relax (build.c) */
static inline int bd_rfe_sde_held(const bd_rfe *R, int i, int j)
{
    return R->sec[i] >= 0 && R->sec[j] >= 0;
}

/* whether any element is tied into a section now (sections.c): the step
 * then works on the free runs only */
static inline int bd_rfe_some_tied(const bd_sim *sim)
{
    const bd_rfe *R = bd_rfe_of(sim);
    return R->tied && !(R->run_n == 1 && R->run_count[0] == sim->model->n);
}

/* build.c */
int bd_rfe_build(bd_sim *sim, bd_diag *diag);
/* the free elements first .. first + count − 1 (count ≥ n: the whole
 * loop) turned to the least shear, alignment and bending energy with
 * every centre held; with turn_tied, the tied ones among them too (a
 * section's end, turning on its SDE to the free belt alone) */
void bd_rfe_relax_turns(bd_sim *sim, int first, int count, int turn_tied);
/* GA, N: belt.shear_stiffness, default 10·EA */
double bd_rfe_shear_stiffness(const bd_model_def *def);
void bd_rfe_free(bd_sim *sim);
void bd_rfe_free_model(bd_model *model);
void bd_rfe_clone(bd_sim *dst, const bd_sim *src);
double bd_rfe_stable_step(const bd_sim *sim, bd_time_step_limit *limit);
double bd_rfe_settle_time(const bd_sim *sim);
void bd_rfe_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out);

/* forces.c */
void bd_rfe_forces(bd_sim *sim);
void bd_rfe_integrate(bd_sim *sim, double *ke, double *w_nc);
void bd_rfe_rest_velocities(bd_sim *sim, double h);
double bd_rfe_elastic_energy(const bd_sim *sim);
double bd_rfe_potential(const bd_sim *sim);
/* from the present positions: SDE e's shear γ (its bend β in *bend) and
 * element i's angle ψ to the line of the belt, rad */
double bd_rfe_sde_angles(const bd_sim *sim, int e, double *bend);
double bd_rfe_align_angle(const bd_sim *sim, int i);

/* sections.c: variable topology */
void bd_rfe_sections_build(bd_sim *sim, bd_rfe_model *RM);
/* before the build (bd_rfe_estimate): the length the windows will hold,
 * m, and how many there will be (*windows), from the definition and its
 * path by set_windows' rules, the idlers at their given spacing */
double bd_rfe_windows_estimate(const bd_model_def *def, const bd_path *path, double l0,
                               double *windows);
void bd_rfe_sections_alloc(bd_sim *sim);
void bd_rfe_sections_free(bd_rfe *R);
void bd_rfe_sections_free_model(bd_rfe_model *RM);
void bd_rfe_sections_clone(bd_sim *dst, const bd_sim *src);
/* the forces phase's lumped part with sections: the idlers they carry,
 * the nodes it takes */
void bd_rfe_sections_forces(bd_sim *sim);
/* the supports phase: the idlers the sections carry, the others' contacts */
void bd_rfe_supports(bd_sim *sim);
/* every section's elements where it stands (belt.h sync) */
void bd_rfe_sync(bd_sim *sim);
/* a sensor's point: the elements about it placed, then followed */
void bd_rfe_point_update(const bd_sim *sim, bd_tracker *tr);
/* the integrate phase for the sections and the idlers they carry */
void bd_rfe_sections_move(bd_sim *sim, double *ke, double *w_nc);
/* after the parts have moved (belt.h after_parts): elements join and
 * leave the sections (the first time, every section is tied) */
void bd_rfe_sections_regroup(bd_sim *sim);
void bd_rfe_material(bd_sim *sim);
/* the belt's degrees of freedom now: 3 per free element, 2 per section */
int bd_rfe_belt_dof(const bd_sim *sim);
void bd_rfe_topology(const bd_sim *sim, bd_belt_topology *out);
/* forces.c: SDE e's energy (axial, and shear and bending unless both its
 * elements are tied) and element i's alignment's (none when tied) */
double bd_rfe_sde_energy(const bd_sim *sim, int e);
double bd_rfe_align_energy(const bd_sim *sim, int i);

/* rotation_solve.c: the implicit rotation step's Δω into rb from the
 * moments tq, and its dashpots' mid-step share into tqn (after the forces
 * phase, before the elements turn) */
void bd_rfe_rotation_implicit(bd_sim *sim);


#endif
