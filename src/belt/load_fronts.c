/* The loaded region of the station belts (load_fronts.h). */
#include "belt/load_fronts.h"

#include <math.h>

#include "model/rest_weight.h"

void bd_fronts_init(const bd_sim *sim, bd_load_fronts *f, int hint)
{
    const bd_material_def *mat = &sim->model->def->material;
    f->e_tail = f->e_head = hint;
    if (!mat->present)
        return;
    bd_path_loaded_region(&sim->model->path, mat, &f->s_feed, &f->load_len);
    f->d_tail = 0.0;
    f->d_head = mat->initially_loaded ? f->load_len : 0.0;
    /* an empty belt that is not fed stays empty */
    f->head_free = !mat->initially_loaded && mat->feeding;
    f->tail_free = !mat->feeding && mat->initially_loaded;
}

int bd_fronts_zone(const bd_sim *sim, const bd_load_fronts *f, int full, double *from,
                   double *to)
{
    double d0 = full ? 0.0 : f->d_tail, d1 = full ? f->load_len : f->d_head;
    if (!sim->model->def->material.present || d1 <= d0)
        return 0;
    *from = fmod(f->s_feed + d0, sim->model->path.length);
    *to = *from + (d1 - d0);
    return 1;
}

double bd_fronts_loaded_length(const bd_sim *sim, const bd_load_fronts *f, int full, double a,
                               double b)
{
    double from, to;
    if (!bd_fronts_zone(sim, f, full, &from, &to))
        return 0.0;
    return bd_loop_overlap(a, b, from, to, sim->model->path.length, NULL, NULL);
}

double bd_fronts_weight(const bd_sim *sim, const bd_load_fronts *f, double a, double b,
                        int pieces)
{
    bd_rest_load load = {sim->model->belt_mpl, sim->model->def->material.mass_per_length, 0.0,
                         0.0, sim->model->gravity};
    if (!bd_fronts_zone(sim, f, 0, &load.from, &load.to))
        load.to = load.from;
    return bd_rest_weight(&sim->model->path, &load, a, b, pieces);
}

/* the element holding path point s, searched from *e */
static int element_at(const bd_sim *sim, double s, int *e, const double *len)
{
    const int n = sim->model->n;
    const double L = sim->model->path.length, *s0 = sim->model->s_node0;
    for (int it = 0; it < n; it++) {
        double rel = s - s0[*e];
        rel -= L * floor(rel / L + 0.5);   /* into [−L/2, L/2) */
        if (rel < 0.0)
            *e = *e == 0 ? n - 1 : *e - 1;
        else if (rel >= len[*e])
            *e = *e + 1 == n ? 0 : *e + 1;
        else
            return *e;
    }
    return *e;
}

/* a free front moves with the belt, ds/dt = v interpolated between the
 * nodes of its element, within [lo, hi] from the feed point; the nodes of
 * the elements it crossed get their new load. Returns 1 when it reached
 * hi. */
static int move_front(bd_sim *sim, const bd_load_fronts *f, double *d, int *e, double lo,
                      double hi, const double *len, void (*reload)(bd_sim *, int))
{
    const int n = sim->model->n;
    const double L = sim->model->path.length;
    int e0 = element_at(sim, f->s_feed + *d, e, len);
    int j = e0 + 1 == n ? 0 : e0 + 1;
    double rel = f->s_feed + *d - sim->model->s_node0[e0];
    rel -= L * floor(rel / L);
    double g = rel / len[e0];
    double v = (1.0 - g) * sim->vx[e0] + g * sim->vx[j];
    double d_new = *d + v * sim->model->dt;
    d_new = d_new < lo ? lo : (d_new > hi ? hi : d_new);
    if (d_new == *d)
        return d_new >= hi;
    *d = d_new;
    int e1 = element_at(sim, f->s_feed + *d, e, len);
    /* the nodes of every element from the one behind to the one ahead
     * (a node reloaded with no change keeps its load to the bit) */
    int from = v >= 0.0 ? e0 : e1, to = v >= 0.0 ? e1 : e0;
    for (int k = from;; k = k + 1 == n ? 0 : k + 1) {
        reload(sim, k);
        if (k == to)
            break;
    }
    reload(sim, to + 1 == n ? 0 : to + 1);
    return d_new >= hi;
}

void bd_fronts_move(bd_sim *sim, bd_load_fronts *f, const double *len,
                    void (*reload)(bd_sim *sim, int node))
{
    if (f->head_free
        && move_front(sim, f, &f->d_head, &f->e_head, f->d_tail, f->load_len, len, reload))
        f->head_free = 0;
    if (f->tail_free)
        move_front(sim, f, &f->d_tail, &f->e_tail, 0.0, f->d_head, len, reload);
}
