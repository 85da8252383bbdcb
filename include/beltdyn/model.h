/* beltdyn model description: what a model file says, after validation.
 * Filled once by bd_model_load() (or by hand from the bd_*_default
 * functions), never changed by a run. SI units throughout; angles in rad. */
#ifndef BELTDYN_MODEL_H
#define BELTDYN_MODEL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define BD_NAME_MAX 64

/* where a value came from in the model file (1-based; 0 = not from a file) */
typedef struct bd_mark {
    int line;
    int column;
} bd_mark;

/* diagnostics: one finished line per problem, "FILE:LINE:COL: error: MSG" */
typedef struct bd_diag {
    int count;          /* number of errors */
    int warning_count;  /* number of warnings */
    int capacity;
    char **lines;       /* [count + warning_count] owned strings */
} bd_diag;

/* the library's version, "MAJOR.MINOR.PATCH" */
const char *bd_version(void);

void bd_diag_init(bd_diag *d);
void bd_diag_free(bd_diag *d);
/* append "FILE:LINE:COL: error: MSG" (printf-style MSG) */
void bd_diag_error(bd_diag *d, const char *file, bd_mark at, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
void bd_diag_warning(bd_diag *d, const char *file, bd_mark at, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* piecewise-linear table of (t, value), held constant outside its ends */
typedef struct bd_table {
    int n;        /* number of points, 0 = empty */
    double *t;    /* [n] abscissae (s), strictly increasing */
    double *v;    /* [n] values */
} bd_table;

double bd_table_eval(const bd_table *tab, double t);
/* its points freed, the table left empty */
void bd_table_free(bd_table *tab);

typedef struct bd_friction {
    double mu_static;   /* static (stick) coefficient, - */
    double mu_dynamic;  /* dynamic (slip) coefficient, - */
} bd_friction;

typedef enum bd_drive_control {
    BD_CONTROL_SPEED = 0,  /* speed controller following a start curve */
    BD_CONTROL_TORQUE,     /* prescribed torque table */
    BD_CONTROL_MOTOR       /* induction motor, direct on line */
} bd_drive_control;

typedef enum bd_start_curve {
    BD_CURVE_LINEAR = 0,
    BD_CURVE_HARRISON,
    BD_CURVE_NORDELL,
    BD_CURVE_SCURVE
} bd_start_curve;

typedef enum bd_stop_mode {
    BD_STOP_NONE = 0,
    BD_STOP_COAST,
    BD_STOP_RAMP,
    BD_STOP_BRAKE
} bd_stop_mode;

typedef struct bd_motor_def {
    double rated_power;            /* W at the motor shaft */
    double rated_speed_rpm;        /* rpm at rated load */
    double synchronous_speed_rpm;  /* rpm */
    double breakdown_torque_ratio; /* breakdown / rated torque, - */
    double gear_ratio;             /* motor speed / pulley speed, - */
    double start_time;             /* s: when the motor is switched on */
} bd_motor_def;

typedef struct bd_transmission_def {
    int v_belt;                    /* 0 flat, 1 V */
    double sheave_angle;           /* rad, V-belt groove angle */
    double motor_sheave_radius;    /* m */
    double pulley_sheave_radius;   /* m */
    double friction;               /* belt-sheave coefficient, - */
    double belt_mass_per_length;   /* kg/m */
    double pretension;             /* N in each span at rest */
    double span_stiffness;         /* N/m of each span */
    double velocity_threshold;     /* m/s, tanh friction regularisation */
    double force_threshold;        /* N, tanh tension regularisation */
    double bearing_damping;        /* N·m·s per rad/s, motor sheave */
    double center_distance;        /* m between sheave axes; 0 = 3·(r_m + r_p) */
} bd_transmission_def;

typedef struct bd_drive_def {
    bd_drive_control control;
    double speed;             /* m/s target belt speed (speed control) */
    bd_start_curve curve;     /* start curve shape */
    double start_time;        /* s, ramp duration T */
    double start_delay;       /* s, pre-start held at creep_speed */
    double creep_speed;       /* m/s during the delay */
    double max_torque;        /* N·m at the pulley; INFINITY = unlimited */
    double inertia;           /* kg·m² of motor+gearbox at the pulley shaft */
    double bandwidth;         /* Hz, the speed loop's (speed control) */
    bd_table torque;          /* (s, N·m) for torque control */
    bd_motor_def motor;       /* for motor control */
    bd_stop_mode stop_mode;   /* BD_STOP_NONE = never stops */
    double stop_at;           /* s */
    double stop_time;         /* s, ramp-down duration (ramp) */
    double brake_torque;      /* N·m (brake) */
    int has_transmission;
    bd_transmission_def transmission;
    bd_mark mark;             /* the `drive` key */
} bd_drive_def;

typedef enum bd_takeup_type {
    BD_TAKEUP_GRAVITY = 0,
    BD_TAKEUP_CONSTANT_FORCE,
    BD_TAKEUP_FIXED
} bd_takeup_type;

typedef struct bd_takeup_def {
    bd_takeup_type type;
    double mass;          /* kg of carriage + counterweight (besides pulley) */
    bd_table force;       /* (s, N) pull along axis; gravity: one point
                             mass*gravity; constant_force: value or table */
    double axis[2];       /* unit vector of the pull, default (0, -1) */
    int has_travel;
    double travel_min;    /* m along axis from the initial position */
    double travel_max;    /* m */
    bd_mark mark;         /* the `takeup` key */
} bd_takeup_def;

/* a corner of a span's route: the belt runs straight from corner to
 * corner and round a circular arc of `radius` at each (0: a sharp corner,
 * the belt bent over the idler standing there). Routes come from a
 * `profile` layout and from idler `curve`s (model-format.md). */
typedef struct bd_route_vertex {
    double x, y;      /* m, where the two straight legs meet */
    double radius;    /* m, vertical-curve radius; 0 = sharp */
    bd_mark mark;     /* what made it, for messages (0: its span's pulley) */
} bd_route_vertex;

typedef struct bd_pulley_def {
    char name[BD_NAME_MAX];
    double x, y;              /* m, centre */
    double radius;            /* m, outer (with lagging) */
    int wrap;                 /* +1 ccw, -1 cw: sense the belt turns */
    double mass;              /* kg */
    double inertia;           /* kg·m² about the axle */
    bd_friction friction;     /* belt-pulley */
    double bearing_damping;   /* N·m·s, viscous bearing torque per rad/s */
    double velocity_threshold;/* m/s, seed-004 friction threshold (axial) */
    double force_threshold;   /* N, seed-004 tension threshold (axial) */
    int has_drive;
    bd_drive_def drive;
    int has_takeup;
    bd_takeup_def takeup;
    int route_count;          /* corners of the span leaving this pulley */
    bd_route_vertex *route;   /* [route_count] in travel order, owned */
    bd_mark mark;             /* the list entry */
} bd_pulley_def;

typedef struct bd_idler_set_def {
    int span;                  /* index of the pulley the span leaves */
    double spacing;            /* m */
    double radius;             /* m */
    double inertia;            /* kg·m² of one set's rotating parts */
    double rotating_mass;      /* kg of one set's rotating parts */
    double rolling_resistance; /* force per normal force, - */
    bd_friction friction;      /* belt-idler */
    /* a vertical curve on part of the span (`curve`): the idlers between
     * fractions curve_from and curve_to stand on a circular arc of
     * curve_radius through the span's points there, below the straight
     * span (concave) or above it (convex) */
    int has_curve;
    double curve_radius;       /* m */
    double curve_from, curve_to;
    int curve_convex;
    bd_mark curve_mark;
    bd_mark mark;
} bd_idler_set_def;

typedef enum bd_formulation {
    BD_FORMULATION_DISCRETE = 0,  /* 2D lumped-mass belt (seed 001) */
    BD_FORMULATION_AXIAL,         /* 1D chain with capstan pulleys (seed 004) */
    BD_FORMULATION_MOVING_NODE,   /* nodes fixed in space, material flowing (seed 003) */
    BD_FORMULATION_RFE            /* rigid finite elements joined by spring-damping elements (seed 000) */
} bd_formulation;

typedef struct bd_belt_def {
    double mass_per_length;   /* kg/m, belt alone */
    double axial_stiffness;   /* N, EA */
    double bending_stiffness; /* N·m², EI */
    double damping_ratio;     /* fraction of an element's critical damping */
    double rated_tension;     /* N, 0 = not given */
    double initial_tension;   /* N, installed tension without takeup */
    double element_length;    /* m target, 0 = formulation default */
    double wrap_element_angle;  /* rad, moving_node: one arc element on a wrap */
    double span_element_length; /* m, moving_node: span element target, 0 = default */
    double shear_stiffness;   /* N, rfe: GA of the spring-damping elements, 0 = 10·EA */
    int group_sections;       /* rfe: variable_topology.enabled (default 1) */
    double group_length;      /* m, rfe: variable_topology.group_length (default 10) */
    double width;             /* m, 0 = not given */
    double thickness;         /* m, 0 = not given */
    double modulus;           /* Pa, 0 = not given */
    bd_formulation formulation;
    bd_mark mark;
} bd_belt_def;

typedef struct bd_material_def {
    int present;
    double mass_per_length;   /* kg/m on the loaded belt */
    int feed_span;            /* pulley index of the span fed */
    double feed_at;           /* fraction of that span */
    int discharge;            /* pulley index where material leaves */
    int initially_loaded;     /* belt loaded from feed to discharge at t=0 */
    int feeding;              /* material keeps landing while belt moves */
    bd_mark mark;
} bd_material_def;

typedef enum bd_standard {
    BD_STANDARD_DIN22101 = 0,
    BD_STANDARD_ISO5048,
    BD_STANDARD_CEMA
} bd_standard;

typedef struct bd_cema_def {
    double Kt;      /* ambient temperature correction factor, - (1.0) */
    double Ai;      /* N, idler friction allowance per idler set (CEMA Ai) */
    double Kx_extra;/* reserved: user override of Kx, N/m; <0 = compute */
} bd_cema_def;

/* allowable belt tension = belt.rated_tension / factor: in steady running
 * (the static calculation) and during starts and stops (a run's peak) */
typedef struct bd_safety_factor_def {
    double running, starting;
} bd_safety_factor_def;

/* design.secondary: the secondary resistances by DIN 22101's C, or one by
 * one (DIN 22101 / ISO 5048) from the keys below */
typedef enum bd_secondary_mode {
    BD_SECONDARY_C = 0,
    BD_SECONDARY_INDIVIDUAL
} bd_secondary_mode;

/* the belt's carcass, for ISO 5048's wrap resistance */
typedef enum bd_carcass {
    BD_CARCASS_FABRIC = 0,
    BD_CARCASS_STEEL_CORD
} bd_carcass;

/* skirt plates from the feed point on (model-format.md `design.skirts`) */
typedef struct bd_skirts_def {
    int present;
    double width;            /* m between the skirt plates, b1 */
    double length;           /* m of skirting, l */
    double mu_material;      /* material–skirt friction, μ2 */
    double mu_belt_material; /* material–belt friction, μ1 */
} bd_skirts_def;

/* belt cleaners (model-format.md `design.cleaners`) */
typedef struct bd_cleaners_def {
    int present;
    double count;            /* how many */
    double width, thickness; /* m, contact area of one: width × thickness */
    double pressure;         /* Pa between cleaner and belt */
    double mu;               /* cleaner–belt friction, μ3 */
    int pulley;              /* index of the pulley they scrape at; -1: the
                                discharge pulley (else the first drive) */
} bd_cleaners_def;

/* one pulley's bearings (model-format.md `design.bearings`) */
typedef struct bd_bearing_def {
    int pulley;              /* index of the pulley */
    double bore;             /* m, bearing diameter d0 */
    double mass;             /* kg of the pulley's rotating parts */
    bd_mark mark;
} bd_bearing_def;

typedef struct bd_design_def {
    int present;
    bd_standard standard;
    double f;          /* DIN/ISO artificial friction coefficient */
    double C;          /* secondary-resistance coefficient; 0 = auto */
    double speed;      /* m/s design speed; 0 = the drive's speed */
    double sag_ratio;  /* admissible h/a */
    bd_cema_def cema;
    bd_safety_factor_def safety_factor;
    double efficiency;  /* coupling × gearbox, 0 < η ≤ 1: motor power = Te·v/η */
    /* the secondary and special resistances one by one */
    bd_secondary_mode secondary;
    double bulk_density;     /* kg/m³ (the file gives t/m³); 0 = not given */
    double loading_speed;    /* m/s of the material along the belt as it lands */
    bd_skirts_def skirts;
    bd_cleaners_def cleaners;
    double belt_thickness;   /* m, for the wrap resistance; 0 = belt.thickness */
    bd_carcass carcass;
    int bearing_count;
    bd_bearing_def *bearings;   /* [bearing_count] */
    bd_mark mark;
} bd_design_def;

typedef struct bd_probe_def {
    char name[BD_NAME_MAX];
    int span;          /* pulley index of the span */
    double at;         /* fraction of the span, 0..1 */
    bd_mark mark;
} bd_probe_def;

typedef enum bd_initial_state {
    BD_INITIAL_STATIC = 0,   /* pre-stretched to the at-rest tension */
    BD_INITIAL_REST          /* laid unstretched */
} bd_initial_state;

typedef struct bd_simulation_def {
    double duration;         /* s */
    double time_step;        /* s, 0 = auto */
    double output_interval;  /* s */
    double tension_interval; /* s between tension.csv rows, 0 = output_interval */
    double tension_spacing;  /* m between tension.csv rows along the belt,
                                0 = every element */
    bd_initial_state initial_state;
    int stabilize;           /* kinetic-energy damping before t = 0 */
    int probe_count;
    bd_probe_def *probes;    /* [probe_count] */
    bd_mark mark;            /* the `simulation` key (or 0) */
    bd_mark time_step_mark;  /* the `time_step` value (or 0) */
} bd_simulation_def;

typedef struct bd_model_def {
    char name[256];
    char source[1024];       /* path of the model file, for messages */
    double gravity;          /* m/s² along -y */
    bd_belt_def belt;
    int pulley_count;
    bd_pulley_def *pulleys;  /* [pulley_count] in the order of travel */
    int idler_set_count;
    bd_idler_set_def *idler_sets; /* [idler_set_count] */
    bd_material_def material;
    bd_design_def design;
    bd_simulation_def simulation;
    int from_profile;        /* pulleys and idlers laid out from `profile` */
} bd_model_def;

/* defaults, as model-format.md lists them */
bd_belt_def bd_belt_default(void);
bd_pulley_def bd_pulley_default(void);
bd_drive_def bd_drive_default(void);
bd_takeup_def bd_takeup_default(void);
bd_idler_set_def bd_idler_set_default(void);
bd_material_def bd_material_default(void);
bd_design_def bd_design_default(void);
bd_simulation_def bd_simulation_default(void);
/* the tension field's snapshot interval: tension_interval, else
 * output_interval, s */
double bd_tension_interval(const bd_simulation_def *s);
/* tension.csv writes every k-th element: k = tension_spacing over the mean
 * element length (loop / elements), rounded, from 1 to elements */
int bd_tension_stride(const bd_simulation_def *s, double loop, double elements);
void bd_model_def_init(bd_model_def *m);

/* read and validate a model file. Returns 0 on success; otherwise a nonzero
 * code, every problem appended to diag, and *out left freed/empty. */
int bd_model_load(const char *path, bd_model_def *out, bd_diag *diag);
/* parse from a string (path is used only in messages) */
int bd_model_load_string(const char *text, size_t len, const char *path,
                         bd_model_def *out, bd_diag *diag);
void bd_model_def_free(bd_model_def *m);

/* index of the pulley called name, or -1 */
int bd_model_find_pulley(const bd_model_def *m, const char *name);

#ifdef __cplusplus
}
#endif
#endif
