/* MPI behind the small interface of ranks.h. Only this file includes
 * mpi.h (BD_HAVE_MPI comes from CMake when find_package(MPI) found it).
 *
 * Waiting is MPI_Iprobe and a 1 ms sleep, not a blocking MPI_Recv: Open
 * MPI's blocking calls spin a core, and rank 0 waits while a worker shares
 * its node. */
#include "study/ranks.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#ifdef BD_HAVE_MPI
#include <mpi.h>
#endif

int bd_ranks_launched(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") != NULL || getenv("PMIX_RANK") != NULL
           || getenv("PMI_RANK") != NULL;
}

#ifdef BD_HAVE_MPI

static int started;

int bd_ranks_begin(int *rank, int *size, char *err, size_t errlen)
{
    *rank = 0;
    *size = 1;
    if (!bd_ranks_launched())
        return 0;
    int flag = 0;
    MPI_Finalized(&flag);
    if (flag) {
        snprintf(err, errlen, "MPI was finalized already: one study per process under mpirun");
        return -1;
    }
    MPI_Initialized(&flag);
    if (!flag) {
        if (MPI_Init(NULL, NULL) != MPI_SUCCESS) {
            snprintf(err, errlen, "MPI_Init failed");
            return -1;
        }
        started = 1;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, rank);
    MPI_Comm_size(MPI_COMM_WORLD, size);
    return 0;
}

void bd_ranks_end(void)
{
    if (started)
        MPI_Finalize();
    started = 0;
}

int bd_ranks_send(int dest, const void *buf, int len)
{
    return MPI_Send(buf, len, MPI_BYTE, dest, 0, MPI_COMM_WORLD) == MPI_SUCCESS ? 0 : -1;
}

int bd_ranks_recv(int *src, void *buf, int cap, int *len, int timeout_ms)
{
    const struct timespec pause = {0, 1000000};
    for (int waited = 0;; waited++) {
        /* twice: a probe that finds nothing makes MPI progress, which may
         * only then bring in a message that has arrived (Open MPI) */
        for (int look = 0; look < 2; look++) {
            int flag = 0;
            MPI_Status st;
            if (MPI_Iprobe(MPI_ANY_SOURCE, 0, MPI_COMM_WORLD, &flag, &st) != MPI_SUCCESS)
                return -1;
            if (!flag)
                continue;
            int n = 0;
            MPI_Get_count(&st, MPI_BYTE, &n);
            if (n > cap)
                return -1;
            if (MPI_Recv(buf, n, MPI_BYTE, st.MPI_SOURCE, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
                != MPI_SUCCESS)
                return -1;
            *src = st.MPI_SOURCE;
            *len = n;
            return 1;
        }
        if (timeout_ms >= 0 && waited >= timeout_ms)
            return 0;
        nanosleep(&pause, NULL);
    }
}

#else

int bd_ranks_begin(int *rank, int *size, char *err, size_t errlen)
{
    *rank = 0;
    *size = 1;
    if (bd_ranks_launched()) {
        snprintf(err, errlen, "this beltdyn was built without MPI, so under mpirun every rank "
                 "would run the whole study: run it without mpirun (-j N), or install "
                 "libopenmpi-dev (scripts/bootstrap) and build again");
        return -1;
    }
    return 0;
}

void bd_ranks_end(void)
{
}

int bd_ranks_send(int dest, const void *buf, int len)
{
    (void)dest, (void)buf, (void)len;
    return -1;
}

int bd_ranks_recv(int *src, void *buf, int cap, int *len, int timeout_ms)
{
    (void)src, (void)buf, (void)cap, (void)len, (void)timeout_ms;
    return -1;
}

#endif
