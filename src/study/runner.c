/* The case runner (runner.h). One coordinator hands out jobs and gathers
 * their results; workers run them. Three ways, one protocol:
 *
 *   serial   workers = 1, no MPI: the coordinator runs every job itself;
 *   fork     workers = N > 1: N child processes, each with a pipe for its
 *            jobs and a pipe for its results (fork after the model is
 *            loaded, so that every child has it already);
 *   ranks    under mpirun: ranks 1..K-1 are workers, rank 0 coordinates
 *            and runs jobs too (between two of its own run's progress
 *            calls it answers the other ranks; a rank 0 that only waited
 *            would leave one of K cores idle).
 *
 * A frame is a header (type, job, length) and a body: JOB (the job's
 * index; body: 1 when progress is wanted), STOP (no more work), INTERRUPT
 * (stop the running job), PROGRESS (the fraction of the running job
 * done), MESSAGE (a warning line), RESULT (a bd_job_result). A worker
 * hears INTERRUPT in its run's progress call, so a run stops at its next
 * output row, as on SIGINT, and reports itself interrupted. A worker
 * process that dies fails its job (the others go on) and is replaced. */
#if defined(__linux__) && !defined(_GNU_SOURCE)
#define _GNU_SOURCE   /* sched_getaffinity, CPU_COUNT: the cores this process may use */
#endif
#include "study/runner.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sched.h>
#include <sys/prctl.h>
#endif

#include "base/clock.h"
#include "study/ranks.h"

enum { F_JOB = 1, F_STOP, F_INTERRUPT, F_PROGRESS, F_MESSAGE, F_RESULT };

typedef struct frame_head {
    int type, job, len;
} frame_head;

/* a frame is written whole in one write(): below PIPE_BUF, so atomic */
typedef struct frame {
    frame_head h;
    unsigned char body[sizeof(bd_job_result) + 8];
} frame;

_Static_assert(sizeof(frame) <= 4096, "a frame must fit PIPE_BUF");

/* ---- the link of a worker to its coordinator ---- */

typedef struct wlink {
    int ranks;          /* 1: MPI rank 0, else the pipes */
    int rfd, wfd;       /* pipes: jobs in, results out */
} wlink;

static int write_all(int fd, const void *p, size_t n)
{
    const char *c = p;
    while (n > 0) {
        ssize_t k = write(fd, c, n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        c += k;
        n -= (size_t)k;
    }
    return 0;
}

/* 1 read, 0 end of file, -1 error */
static int read_all(int fd, void *p, size_t n)
{
    char *c = p;
    size_t got = 0;
    while (got < n) {
        ssize_t k = read(fd, c + got, n - got);
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0)
            return -1;
        if (k == 0)
            return got == 0 ? 0 : -1;
        got += (size_t)k;
    }
    return 1;
}

static void frame_set(frame *f, int type, int job, const void *body, size_t len)
{
    if (len > sizeof f->body)
        len = sizeof f->body;
    f->h.type = type;
    f->h.job = job;
    f->h.len = (int)len;
    if (len > 0)
        memcpy(f->body, body, len);
}

static size_t frame_size(const frame *f)
{
    return sizeof f->h + (size_t)f->h.len;
}

static int pipe_send(int fd, const frame *f)
{
    return write_all(fd, f, frame_size(f));
}

/* 1 a frame, 0 the other end closed, -1 error */
static int pipe_recv(int fd, frame *f)
{
    int got = read_all(fd, &f->h, sizeof f->h);
    if (got <= 0)
        return got;
    if (f->h.len < 0 || (size_t)f->h.len > sizeof f->body)
        return -1;
    return f->h.len == 0 ? 1 : (read_all(fd, f->body, (size_t)f->h.len) == 1 ? 1 : -1);
}

/* 1 when fd has something to read (or was closed) within timeout_ms */
static int readable(int fd, int timeout_ms)
{
    struct pollfd p = {fd, POLLIN, 0};
    int k;
    do
        k = poll(&p, 1, timeout_ms);
    while (k < 0 && errno == EINTR);
    return k > 0;
}

static int link_send(const wlink *l, const frame *f)
{
    return l->ranks ? bd_ranks_send(0, f, (int)frame_size(f)) : pipe_send(l->wfd, f);
}

/* from the coordinator: 1 a frame, 0 nothing within timeout_ms, -1 gone */
static int link_recv(const wlink *l, frame *f, int timeout_ms)
{
    if (l->ranks) {
        int src, len;
        int got = bd_ranks_recv(&src, f, (int)sizeof *f, &len, timeout_ms);
        return got == 1 && len < (int)sizeof f->h ? -1 : got;
    }
    if (timeout_ms >= 0 && !readable(l->rfd, timeout_ms))
        return 0;
    int got = pipe_recv(l->rfd, f);
    return got == 1 ? 1 : -1;
}

/* ---- a worker ---- */

typedef struct worker {
    const bd_runner *r;
    wlink link;
    int job;
    int want_progress;
    volatile sig_atomic_t stop;   /* the running job's interrupted flag */
    int stopped;                  /* STOP heard already, or the coordinator is gone */
} worker;

/* the run's progress call: pass the fraction on, and hear an interrupt */
static void worker_progress(const bd_run_progress *p, void *ctx)
{
    worker *w = ctx;
    if (w->r->interrupted && *w->r->interrupted)
        w->stop = 1;
    frame f;
    int got;
    while ((got = link_recv(&w->link, &f, 0)) != 0) {
        if (got < 0 || f.h.type == F_STOP) {
            w->stopped = 1;
            w->stop = 1;
            break;
        }
        if (f.h.type == F_INTERRUPT)
            w->stop = 1;
    }
    if (w->want_progress && !w->stopped) {
        double frac = p->duration_s > 0.0 ? p->t_s / p->duration_s : 0.0;
        frame_set(&f, F_PROGRESS, w->job, &frac, sizeof frac);
        link_send(&w->link, &f);
    }
}

static void worker_message(const char *line, void *ctx)
{
    worker *w = ctx;
    frame f;
    size_t n = strlen(line) + 1;
    frame_set(&f, F_MESSAGE, w->job, line, n);
    f.body[sizeof f.body - 1] = '\0';
    link_send(&w->link, &f);
}

/* jobs until STOP; 0, or -1 when the coordinator went away */
static int worker_loop(worker *w)
{
    while (!w->stopped) {
        frame f;
        int got = link_recv(&w->link, &f, -1);
        if (got <= 0)
            return -1;
        if (f.h.type == F_STOP)
            break;
        if (f.h.type != F_JOB)
            continue;   /* an INTERRUPT between jobs: nothing runs */
        w->job = f.h.job;
        int want = 0;
        if (f.h.len >= (int)sizeof want)
            memcpy(&want, f.body, sizeof want);
        w->want_progress = want != 0;
        bd_job_env env = {worker_progress, w, worker_message, w, &w->stop};
        bd_job_result res;
        memset(&res, 0, sizeof res);
        res.job = w->job;
        w->r->run(w->r->run_ctx, w->job, &env, &res);
        res.job = w->job;
        frame_set(&f, F_RESULT, w->job, &res, sizeof res);
        if (link_send(&w->link, &f) != 0)
            return -1;
    }
    return 0;
}

/* ---- the coordinator ---- */

enum { MODE_SERIAL, MODE_FORK, MODE_RANKS };

typedef struct remote {
    int busy;            /* the job it runs, or -1 */
    int alive;           /* 0: gone, or told to stop */
    int told_interrupt;
    pid_t pid;           /* fork: the process and its pipes */
    int task_fd, result_fd;
} remote;

typedef struct coord {
    const bd_runner *r;
    int mode;
    int *order;          /* [total] jobs to run, longest first */
    int total, next;     /* next: the first of order not handed out */
    double *frac;        /* [count] of a running job, done */
    double total_cost, done_cost;
    int ndone, nfailed, nrunning;
    remote *w;           /* [nw] */
    struct pollfd *pfd;  /* [nw] scratch of service() */
    int *pidx;           /* [nw] the worker of each pfd */
    int nw, respawns;
    int spawn_failed;    /* workers that could not be started */
    char spawn_why[96];  /* the first one's reason */
    int local_job;       /* running in this process, or -1 */
    int stopping;        /* interrupted: no more jobs handed out */
    double t0, last_shown;
    char *err;
    size_t errlen;
    int broken;          /* workers could not be started */
} coord;

static double job_cost(const coord *c, int job)
{
    return c->r->cost && c->r->cost[job] > 0.0 ? c->r->cost[job] : 1.0;
}

static const double *sort_cost;

static int by_cost(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    double ci = sort_cost ? sort_cost[i] : 0.0, cj = sort_cost ? sort_cost[j] : 0.0;
    if (ci != cj)
        return ci > cj ? -1 : 1;
    return (i > j) - (i < j);
}

static void show(coord *c, int finished)
{
    if (!c->r->progress)
        return;
    double now = bd_wall_seconds();
    if (!finished && now - c->last_shown < 0.25)
        return;
    c->last_shown = now;
    double work = c->done_cost;
    for (int k = 0; k < c->nw; k++)
        if (c->w[k].busy >= 0)
            work += c->frac[c->w[k].busy] * job_cost(c, c->w[k].busy);
    if (c->local_job >= 0)
        work += c->frac[c->local_job] * job_cost(c, c->local_job);
    int workers = c->mode == MODE_FORK ? 0 : 1;
    for (int k = 0; k < c->nw; k++)
        workers += c->w[k].alive;
    bd_runner_progress p = {c->total, c->ndone, c->nfailed, c->nrunning, workers,
                            c->total_cost > 0.0 ? work / c->total_cost : 1.0, now - c->t0,
                            finished};
    c->r->progress(&p, c->r->progress_ctx);
}

static void finish_job(coord *c, const bd_job_result *res)
{
    c->ndone++;
    c->nrunning--;
    c->done_cost += job_cost(c, res->job);
    if (res->status != BD_RUN_OK)
        c->nfailed++;
    if (c->r->done)
        c->r->done(res, c->r->done_ctx);
    show(c, 0);
}

static int coord_send(coord *c, int k, int type, int job, const void *body, size_t len)
{
    frame f;
    frame_set(&f, type, job, body, len);
    if (c->mode == MODE_RANKS)
        return bd_ranks_send(k + 1, &f, (int)frame_size(&f));
    return pipe_send(c->w[k].task_fd, &f);
}

static int spawn(coord *c, int k);

/* wait for a worker process to end; a signal (SIGINT) does not cut it
 * short, which would leave a zombie and its status unknown */
static void reap(pid_t pid, int *status)
{
    int st = 0;
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
        ;
    if (status)
        *status = st;
}

/* a worker process ended: its job failed; another takes its place */
static void lost_worker(coord *c, int k)
{
    remote *w = &c->w[k];
    int st = 0;
    close(w->task_fd);
    close(w->result_fd);
    w->alive = 0;
    reap(w->pid, &st);
    if (w->busy >= 0) {
        bd_job_result res;
        memset(&res, 0, sizeof res);
        res.job = w->busy;
        res.status = BD_RUN_FAILED;
        if (WIFSIGNALED(st))
            snprintf(res.message, sizeof res.message, "its worker process ended by signal %d "
                     "while running it", WTERMSIG(st));
        else
            snprintf(res.message, sizeof res.message, "its worker process ended (exit %d) "
                     "while running it", WIFEXITED(st) ? WEXITSTATUS(st) : -1);
        w->busy = -1;
        finish_job(c, &res);
    }
    if (!c->stopping && c->next < c->total && c->respawns < c->total) {
        c->respawns++;
        spawn(c, k);
    }
}

static void handle(coord *c, int k, const frame *f)
{
    if (f->h.job < 0 || f->h.job >= c->r->count)
        return;
    switch (f->h.type) {
    case F_PROGRESS:
        if (f->h.len == (int)sizeof(double))
            memcpy(&c->frac[f->h.job], f->body, sizeof(double));
        show(c, 0);
        break;
    case F_MESSAGE:
        if (c->r->message && f->h.len > 0) {
            char line[sizeof f->body + 1];
            memcpy(line, f->body, (size_t)f->h.len);
            line[f->h.len] = '\0';
            c->r->message(line, c->r->message_ctx);
        }
        break;
    case F_RESULT:
        if (f->h.len == (int)sizeof(bd_job_result) && k >= 0 && c->w[k].busy == f->h.job) {
            bd_job_result res;
            memcpy(&res, f->body, sizeof res);
            c->w[k].busy = -1;
            finish_job(c, &res);
        }
        break;
    default:
        break;
    }
}

/* take what the workers sent within timeout_ms (0: only what is there) */
static void service(coord *c, int timeout_ms)
{
    frame f;
    if (c->mode == MODE_RANKS) {
        int src, len, wait = timeout_ms;
        while (bd_ranks_recv(&src, &f, (int)sizeof f, &len, wait) == 1) {
            if (len >= (int)sizeof f.h && src >= 1 && src <= c->nw)
                handle(c, src - 1, &f);
            wait = 0;
        }
        return;
    }
    if (c->mode != MODE_FORK)
        return;
    struct pollfd *p = c->pfd;
    int *idx = c->pidx, n = 0;
    for (int k = 0; k < c->nw; k++)
        if (c->w[k].alive) {
            p[n] = (struct pollfd){c->w[k].result_fd, POLLIN, 0};
            idx[n++] = k;
        }
    if (n == 0)
        return;
    if (poll(p, (nfds_t)n, timeout_ms) <= 0)
        return;
    for (int i = 0; i < n; i++) {
        if (!(p[i].revents & (POLLIN | POLLHUP | POLLERR)))
            continue;
        int k = idx[i];
        /* every frame there is, then the next worker */
        do {
            if (pipe_recv(c->w[k].result_fd, &f) != 1) {
                lost_worker(c, k);
                break;
            }
            handle(c, k, &f);
        } while (c->w[k].alive && readable(c->w[k].result_fd, 0));
    }
}

/* on an interrupt: tell the running workers, hand out nothing more */
static void check_interrupt(coord *c)
{
    if (!c->r->interrupted || !*c->r->interrupted)
        return;
    c->stopping = 1;
    for (int k = 0; k < c->nw; k++)
        if (c->w[k].alive && c->w[k].busy >= 0 && !c->w[k].told_interrupt) {
            coord_send(c, k, F_INTERRUPT, c->w[k].busy, NULL, 0);
            c->w[k].told_interrupt = 1;
        }
}

/* a job to each idle worker, or STOP when there is none */
static void hand_out(coord *c)
{
    for (int k = 0; k < c->nw; k++) {
        remote *w = &c->w[k];
        if (!w->alive || w->busy >= 0)
            continue;
        if (!c->stopping && c->next < c->total) {
            int job = c->order[c->next++], want = c->r->progress != NULL;
            c->frac[job] = 0.0;
            if (coord_send(c, k, F_JOB, job, &want, sizeof want) == 0) {
                w->busy = job;
                c->nrunning++;
            } else {
                c->next--;   /* handed to the next worker instead */
                w->alive = 0;
                if (c->mode == MODE_FORK)
                    lost_worker(c, k);
            }
        } else {
            coord_send(c, k, F_STOP, -1, NULL, 0);
            w->alive = 0;
            if (c->mode == MODE_FORK) {
                close(w->task_fd);
                close(w->result_fd);
                reap(w->pid, NULL);
            }
        }
    }
}

/* the run's progress call of the job this process runs itself */
static void local_progress(const bd_run_progress *p, void *ctx)
{
    coord *c = ctx;
    if (c->local_job >= 0)
        c->frac[c->local_job] = p->duration_s > 0.0 ? p->t_s / p->duration_s : 0.0;
    if (c->mode == MODE_RANKS) {
        check_interrupt(c);
        service(c, 0);
        hand_out(c);
    }
    show(c, 0);
}

static void run_local(coord *c, int job)
{
    const bd_runner *r = c->r;
    c->local_job = job;
    c->frac[job] = 0.0;
    c->nrunning++;
    bd_job_env env = {local_progress, c, r->message, r->message_ctx, r->interrupted};
    bd_job_result res;
    memset(&res, 0, sizeof res);
    res.job = job;
    r->run(r->run_ctx, job, &env, &res);
    res.job = job;
    c->local_job = -1;
    finish_job(c, &res);
}

/* a worker that could not start: said once (the others run the jobs) */
static void spawn_failed(coord *c, const char *what, int err)
{
    if (c->spawn_failed++)
        return;
    snprintf(c->spawn_why, sizeof c->spawn_why, "%s: %s", what, strerror(err));
    if (!c->r->message)
        return;
    char line[256];
    snprintf(line, sizeof line, "warning: a worker process could not be started (%s); the "
             "cases run on the workers that did start", c->spawn_why);
    c->r->message(line, c->r->message_ctx);
}

/* a worker process in slot k; 0, or -1 with the slot left idle and dead
 * (not busy: a slot that never started runs no job) */
static int spawn(coord *c, int k)
{
    c->w[k] = (remote){-1, 0, 0, 0, -1, -1};
    int task[2], result[2];
    if (pipe(task) != 0) {
        spawn_failed(c, "pipe", errno);
        return -1;
    }
    if (pipe(result) != 0) {
        int e = errno;
        close(task[0]);
        close(task[1]);
        spawn_failed(c, "pipe", e);
        return -1;
    }
    fflush(NULL);   /* nothing buffered is written twice */
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0) {
        int e = errno;
        close(task[0]), close(task[1]), close(result[0]), close(result[1]);
        spawn_failed(c, "fork", e);
        return -1;
    }
    if (pid == 0) {
        /* the child: its own two pipe ends only; it dies with the study */
        for (int i = 0; i < c->nw; i++)
            if (i != k && c->w[i].alive) {
                close(c->w[i].task_fd);
                close(c->w[i].result_fd);
            }
        close(task[1]);
        close(result[0]);
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
            _exit(1);
#else
        (void)parent;
#endif
        worker w;
        memset(&w, 0, sizeof w);
        w.r = c->r;
        w.link.rfd = task[0];
        w.link.wfd = result[1];
        int rc = worker_loop(&w);
        _exit(rc == 0 ? 0 : 1);
    }
    close(task[0]);
    close(result[1]);
    c->w[k] = (remote){-1, 1, 0, pid, task[1], result[0]};
    return 0;
}

int bd_runner_cores(void)
{
#ifdef __linux__
    /* taskset, a batch scheduler's cgroup or cpuset: not every online core */
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return CPU_COUNT(&set);
#endif
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

static int coordinate(coord *c)
{
    const bd_runner *r = c->r;
    int local = c->mode != MODE_FORK;
    for (;;) {
        check_interrupt(c);
        hand_out(c);
        if (local && !c->stopping && c->next < c->total) {
            run_local(c, c->order[c->next++]);
            continue;
        }
        int busy = 0, alive = 0;
        for (int k = 0; k < c->nw; k++) {
            busy += c->w[k].busy >= 0;
            alive += c->w[k].alive;
        }
        if (busy == 0 && (c->stopping || c->next >= c->total) && alive == 0)
            break;
        if (!local && alive == 0 && c->next < c->total && !c->stopping) {
            /* every worker is gone and none could be started again */
            snprintf(c->err, c->errlen, "no worker process could be started for %d cases%s%s%s",
                     c->total - c->next, c->spawn_why[0] ? " (" : "", c->spawn_why,
                     c->spawn_why[0] ? ")" : "");
            c->broken = 1;
            break;
        }
        service(c, 250);
        show(c, 0);
    }
    show(c, 1);
    if (c->broken)
        return BD_RUN_FAILED;
    return c->stopping || (r->interrupted && *r->interrupted) ? BD_RUN_INTERRUPTED : BD_RUN_OK;
}

int bd_runner_run(const bd_runner *r, char *err, size_t errlen)
{
    err[0] = '\0';
    if (r->ranks > 1 && r->rank > 0) {
        worker w;
        memset(&w, 0, sizeof w);
        w.r = r;
        w.link.ranks = 1;
        return worker_loop(&w) == 0 ? BD_RUN_OK : BD_RUN_FAILED;
    }
    coord c;
    memset(&c, 0, sizeof c);
    c.r = r;
    c.err = err;
    c.errlen = errlen;
    c.local_job = -1;
    c.t0 = c.last_shown = bd_wall_seconds();
    c.order = malloc((size_t)(r->count > 0 ? r->count : 1) * sizeof *c.order);
    c.frac = calloc((size_t)(r->count > 0 ? r->count : 1), sizeof *c.frac);
    /* no worker processes under an MPI launcher, whatever `workers` says:
     * Open MPI does not support fork after MPI_Init, and a world of one
     * rank runs its jobs here */
    int nw = r->ranks > 1 ? r->ranks - 1
                          : (r->workers > 1 && !bd_ranks_launched() ? r->workers : 0);
    c.w = calloc((size_t)(nw > 0 ? nw : 1), sizeof *c.w);
    c.pfd = calloc((size_t)(nw > 0 ? nw : 1), sizeof *c.pfd);
    c.pidx = calloc((size_t)(nw > 0 ? nw : 1), sizeof *c.pidx);
    if (!c.order || !c.frac || !c.w || !c.pfd || !c.pidx) {
        free(c.order), free(c.frac), free(c.w), free(c.pfd), free(c.pidx);
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    for (int j = 0; j < r->count; j++)
        if (!r->todo || r->todo[j]) {
            c.order[c.total++] = j;
            c.total_cost += job_cost(&c, j);
        }
    sort_cost = r->cost;
    qsort(c.order, (size_t)c.total, sizeof *c.order, by_cost);
    int status;
    if (r->ranks > 1) {
        c.mode = MODE_RANKS;
        c.nw = nw;
        for (int k = 0; k < nw; k++)
            c.w[k] = (remote){-1, 1, 0, 0, -1, -1};
        status = coordinate(&c);
    } else if (nw > 0 && c.total > 1) {
        /* a closed pipe is an error to see, not a signal to die of */
        struct sigaction ign, old;
        memset(&ign, 0, sizeof ign);
        ign.sa_handler = SIG_IGN;
        sigaction(SIGPIPE, &ign, &old);
        c.mode = MODE_FORK;
        c.nw = nw < c.total ? nw : c.total;
        for (int k = 0; k < c.nw; k++)
            spawn(&c, k);   /* one that fails is left idle; the others run the jobs */
        status = coordinate(&c);
        sigaction(SIGPIPE, &old, NULL);
    } else {
        c.mode = MODE_SERIAL;
        status = coordinate(&c);
    }
    free(c.order);
    free(c.frac);
    free(c.w);
    free(c.pfd);
    free(c.pidx);
    return status;
}
