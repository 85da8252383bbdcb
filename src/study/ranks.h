/* Ranks of an MPI job (ranks.c): the only place that knows MPI. A study
 * started by mpirun (or srun) runs one worker per rank; rank 0 hands out
 * the cases and gathers (runner.c). Messages are plain bytes with one tag.
 * Built without MPI, every function says so and nothing runs under a
 * launcher. */
#ifndef BD_STUDY_RANKS_H
#define BD_STUDY_RANKS_H

#include <stddef.h>

/* 1 when an MPI launcher started this process (its environment says so:
 * OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_RANK) */
int bd_ranks_launched(void);

/* start MPI when launched; *rank and *size (0 and 1 when not launched).
 * Once per process. 0 ok, else a message in err */
int bd_ranks_begin(int *rank, int *size, char *err, size_t errlen);

/* MPI_Finalize, when bd_ranks_begin started it */
void bd_ranks_end(void);

/* len bytes to rank dest; 0 ok, -1 failed */
int bd_ranks_send(int dest, const void *buf, int len);

/* a message from any rank into buf (at most cap bytes): waits at most
 * timeout_ms (0: only looks, < 0: until one comes), sleeping between
 * looks so that a waiting rank leaves its core to the others. 1 got one
 * (*src, *len), 0 none yet, -1 failed or too long */
int bd_ranks_recv(int *src, void *buf, int cap, int *len, int timeout_ms);

#endif
