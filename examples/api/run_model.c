/* run_model: load a beltdyn model, step its simulation to a given time with
 * the public API only, and print what bd_sim_result() says about the run.
 *
 *     run_model MODEL.yaml [DURATION_S]      (default duration 1.0 s)
 *
 * Exit status: 0 ran to the end, 1 the run failed, 2 bad input. */
#include <beltdyn/model.h>
#include <beltdyn/sim.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* print the diagnostic lines not printed yet; returns how many are printed */
static int print_diag(const bd_diag *d, int printed)
{
    for (; printed < d->count + d->warning_count; printed++)
        fprintf(stderr, "%s\n", d->lines[printed]);
    return printed;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: %s MODEL.yaml [DURATION_S]  (default 1.0 s)\n", argv[0]);
        return 2;
    }
    double duration = 1.0;
    if (argc == 3) {
        char *end;
        duration = strtod(argv[2], &end);
        if (end == argv[2] || *end != '\0' || !isfinite(duration) || duration <= 0.0) {
            fprintf(stderr, "%s: duration must be a positive number of seconds, got '%s'\n",
                    argv[0], argv[2]);
            return 2;
        }
    }

    bd_diag diag;
    bd_diag_init(&diag);
    bd_model_def def;
    bd_model_def_init(&def);
    bd_sim *sim = NULL;
    int status = 2;
    int load_failed = bd_model_load(argv[1], &def, &diag) != 0;
    int printed = print_diag(&diag, 0);
    if (!load_failed && bd_sim_create(&def, &sim, &diag) == 0) {
        const double dt = bd_sim_time_step(sim);
        printf("model:        %s\n", def.name);
        printf("time step:    %.6g s\n", dt);
        printf("nodes:        %d\n", bd_sim_node_count(sim));
        char err[512] = "";
        status = 0;
        if (def.simulation.stabilize) {
            /* a warning in err when it did not reach rest: the run goes on */
            if (bd_sim_stabilize(sim, NULL, err, sizeof err) != BD_RUN_OK)
                status = 1;
            else if (err[0])
                printf("warning:      %s\n", err);
        }
        /* at most 1000 steps at a time, up to the last step before duration */
        while (status == 0 && bd_sim_time(sim) < duration - 0.5 * dt) {
            long n = (long)ceil((duration - bd_sim_time(sim)) / dt - 0.5);
            if (bd_sim_step(sim, n < 1 ? 1 : n > 1000 ? 1000 : n, err, sizeof err) != 0)
                status = 1;
        }
        if (status == 0)
            printf("ran to t =    %.4f s\n", bd_sim_time(sim));
        else
            printf("run FAILED at t = %.4f s: %s\n", bd_sim_time(sim), err);

        bd_run_result r;
        bd_sim_result(sim, &r);
        printf("peak tension: %.1f N (lowest %.1f N)\n", r.tension_max_N, r.tension_min_N);
        if (r.drives > 0) {
            printf("tight side:   max %.1f N at t = %.3f s\n", r.tight_max_N, r.tight_max_t_s);
            printf("drive torque: max %.1f N*m\n", r.torque_max_Nm);
            if (r.slipped)
                printf("drive slip:   yes, from t = %.3f s\n", r.slip_t_s);
            else
                printf("drive slip:   no\n");
        } else {
            printf("tight side, drive torque, slip: none (no drive pulley)\n");
        }
    }
    print_diag(&diag, printed);

    bd_sim_free(sim);          /* before def: the sim points into it */
    bd_model_def_free(&def);
    bd_diag_free(&diag);
    return status;
}
