/* HDF5 output of the tension field (`run --hdf5`, hdf5_out.c) */
#ifndef BD_HDF5_OUT_H
#define BD_HDF5_OUT_H

#include <stddef.h>

typedef struct bd_h5 bd_h5;

/* create the file at path (the caller renames it when complete) for a belt
 * of nelem elements; NULL with the reason in err on failure */
bd_h5 *bd_h5_open(const char *path, const char *model, int nelem, double belt_length_m,
                  char *err, size_t errlen);
/* the row buffers [nelem] the caller fills before bd_h5_row: position along
 * the belt (m), tension (N), speed (m/s) of every element */
double *bd_h5_s(bd_h5 *h);
double *bd_h5_tension(bd_h5 *h);
double *bd_h5_speed(bd_h5 *h);
/* append one output time with the buffers' contents; 0 ok */
int bd_h5_row(bd_h5 *h, double t, char *err, size_t errlen);
/* write what HDF5 holds in memory to the file */
void bd_h5_flush(bd_h5 *h);
/* close the file and free h; 0 ok. h may be NULL. */
int bd_h5_close(bd_h5 *h);

#endif
