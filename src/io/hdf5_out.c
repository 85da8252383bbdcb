/* The tension field of a run in HDF5 (`beltdyn run --hdf5`, issue 6 "Large
 * runs"): DIR/tension.h5 with
 *   /t_s        [ntimes]             output times, s
 *   /s_m        [ntimes x nelements] element position along the belt, m
 *   /tension_N  [ntimes x nelements] element tension, N
 *   /speed_mps  [ntimes x nelements] element speed along the belt, m/s
 * every dataset extendible along time and chunked, one row appended at each
 * output interval; a string attribute "units" on each dataset and "model"
 * on the root group. The row buffers, memory dataspaces and datasets are
 * made once in bd_h5_open: a row only extends, selects and writes. */
#include "io/hdf5_out.h"

#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { H5_T = 0, H5_S, H5_TENSION, H5_SPEED, H5_NSETS };

struct bd_h5 {
    hid_t file;
    hid_t set[H5_NSETS];
    hid_t mem_row;     /* [1 x nelem] */
    hid_t mem_one;     /* [1] */
    hsize_t nelem;
    hsize_t rows;
    double *buf[3];    /* s, tension, speed: [nelem] */
};

static const char *const set_name[H5_NSETS] = {"t_s", "s_m", "tension_N", "speed_mps"};
static const char *const set_units[H5_NSETS] = {"s", "m", "N", "m/s"};
static const char *const set_what[H5_NSETS] = {
    "output time",
    "element centre position along the belt from the start of the first span",
    "belt tension of the element (negative: compression)",
    "belt speed of the element along the belt"};

static int string_attr(hid_t obj, const char *name, const char *value)
{
    hid_t type = H5Tcopy(H5T_C_S1);
    if (type < 0)
        return 1;
    /* fixed length with room for the terminating NUL */
    int bad = H5Tset_size(type, strlen(value) + 1) < 0 || H5Tset_strpad(type, H5T_STR_NULLTERM) < 0;
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t attr = space >= 0 && !bad ? H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
    bad |= attr < 0 || H5Awrite(attr, type, value) < 0;
    if (attr >= 0)
        H5Aclose(attr);
    if (space >= 0)
        H5Sclose(space);
    H5Tclose(type);
    return bad;
}

static int double_attr(hid_t obj, const char *name, double value)
{
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t attr = space >= 0 ? H5Acreate2(obj, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
    int bad = attr < 0 || H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) < 0;
    if (attr >= 0)
        H5Aclose(attr);
    if (space >= 0)
        H5Sclose(space);
    return bad;
}

/* an empty dataset of rank 1 ([0], time) or 2 ([0 x nelem]) growing in time */
static hid_t make_set(hid_t file, int which, hsize_t nelem)
{
    int rank = which == H5_T ? 1 : 2;
    hsize_t dims[2] = {0, nelem};
    hsize_t maxdims[2] = {H5S_UNLIMITED, nelem};
    /* chunks of about 256 KiB: whole rows while a row fits */
    hsize_t chunk[2];
    if (rank == 1) {
        chunk[0] = 4096;
    } else {
        hsize_t per_chunk = 32768; /* doubles */
        chunk[1] = nelem < per_chunk ? nelem : per_chunk;
        chunk[0] = per_chunk / chunk[1];
        if (chunk[0] < 1)
            chunk[0] = 1;
    }
    hid_t space = H5Screate_simple(rank, dims, maxdims);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hid_t set = -1;
    /* compressed where the library has zlib (Debian's does): byte shuffle
     * then deflate level 4, lossless; noisy doubles shrink little:
     * head_drive's field 23.0 → 16.2 MB) */
    int ok = space >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, rank, chunk) >= 0;
    if (ok && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0)
        ok = H5Pset_shuffle(dcpl) >= 0 && H5Pset_deflate(dcpl, 4) >= 0;
    if (ok)
        set = H5Dcreate2(file, set_name[which], H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl,
                         H5P_DEFAULT);
    if (dcpl >= 0)
        H5Pclose(dcpl);
    if (space >= 0)
        H5Sclose(space);
    if (set >= 0 && (string_attr(set, "units", set_units[which])
                     || string_attr(set, "description", set_what[which]))) {
        H5Dclose(set);
        set = -1;
    }
    return set;
}

bd_h5 *bd_h5_open(const char *path, const char *model, int nelem, double belt_length_m,
                  char *err, size_t errlen)
{
    /* our messages say what failed; HDF5's error stack print is noise here */
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    if (nelem < 1) {
        snprintf(err, errlen, "HDF5 output: no belt elements");
        return NULL;
    }
    bd_h5 *h = calloc(1, sizeof *h);
    if (!h) {
        snprintf(err, errlen, "HDF5 output: out of memory");
        return NULL;
    }
    h->nelem = (hsize_t)nelem;
    h->mem_row = h->mem_one = -1;
    for (int i = 0; i < H5_NSETS; i++)
        h->set[i] = -1;
    for (int i = 0; i < 3; i++) {
        h->buf[i] = calloc((size_t)nelem, sizeof *h->buf[i]);
        if (!h->buf[i]) {
            snprintf(err, errlen, "HDF5 output: out of memory");
            bd_h5_close(h);
            return NULL;
        }
    }
    h->file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (h->file < 0) {
        snprintf(err, errlen, "cannot create HDF5 file '%s'", path);
        bd_h5_close(h);
        return NULL;
    }
    int bad = string_attr(h->file, "model", model ? model : "")
            || string_attr(h->file, "program", "beltdyn")
            || double_attr(h->file, "belt_length_m", belt_length_m);
    for (int i = 0; i < H5_NSETS && !bad; i++) {
        h->set[i] = make_set(h->file, i, h->nelem);
        bad = h->set[i] < 0;
    }
    hsize_t row[2] = {1, h->nelem};
    h->mem_row = bad ? -1 : H5Screate_simple(2, row, NULL);
    h->mem_one = bad ? -1 : H5Screate_simple(1, row, NULL);
    if (bad || h->mem_row < 0 || h->mem_one < 0) {
        snprintf(err, errlen, "cannot write the datasets of HDF5 file '%s'", path);
        bd_h5_close(h);
        return NULL;
    }
    return h;
}

double *bd_h5_s(bd_h5 *h) { return h->buf[0]; }
double *bd_h5_tension(bd_h5 *h) { return h->buf[1]; }
double *bd_h5_speed(bd_h5 *h) { return h->buf[2]; }

/* grow set by one row and write data (rank 1: one value; rank 2: one row) */
static int append(bd_h5 *h, int which, const double *data)
{
    int rank = which == H5_T ? 1 : 2;
    hsize_t dims[2] = {h->rows + 1, h->nelem};
    hsize_t start[2] = {h->rows, 0};
    hsize_t count[2] = {1, h->nelem};
    if (H5Dset_extent(h->set[which], dims) < 0)
        return 1;
    hid_t space = H5Dget_space(h->set[which]);
    if (space < 0)
        return 1;
    int bad = H5Sselect_hyperslab(space, H5S_SELECT_SET, start, NULL, count, NULL) < 0
           || H5Dwrite(h->set[which], H5T_NATIVE_DOUBLE, rank == 1 ? h->mem_one : h->mem_row,
                       space, H5P_DEFAULT, data) < 0;
    H5Sclose(space);
    return bad;
}

int bd_h5_row(bd_h5 *h, double t, char *err, size_t errlen)
{
    int bad = append(h, H5_T, &t) || append(h, H5_S, h->buf[0])
           || append(h, H5_TENSION, h->buf[1]) || append(h, H5_SPEED, h->buf[2]);
    if (bad) {
        snprintf(err, errlen, "cannot write output time %.6f s to the HDF5 file", t);
        return 1;
    }
    h->rows++;
    return 0;
}

void bd_h5_flush(bd_h5 *h)
{
    if (h && h->file >= 0)
        H5Fflush(h->file, H5F_SCOPE_GLOBAL);
}

int bd_h5_close(bd_h5 *h)
{
    if (!h)
        return 0;
    int bad = 0;
    for (int i = 0; i < H5_NSETS; i++)
        if (h->set[i] >= 0)
            bad |= H5Dclose(h->set[i]) < 0;
    if (h->mem_row >= 0)
        bad |= H5Sclose(h->mem_row) < 0;
    if (h->mem_one >= 0)
        bad |= H5Sclose(h->mem_one) < 0;
    if (h->file > 0)
        bad |= H5Fclose(h->file) < 0;
    for (int i = 0; i < 3; i++)
        free(h->buf[i]);
    free(h);
    return bad;
}
