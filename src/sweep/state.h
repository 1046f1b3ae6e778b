/*
 * sweep/state.h - the sweep's accumulators and its state (state.c): the
 * one owner of the cells, the grid layout, slices, merging and the state
 * files that shards, merge, the MPI driver and its checkpoints write and read.
 */
#ifndef ONB_STATE_H
#define ONB_STATE_H

#include <stdio.h>
#include <stdint.h>
#include "sweep/fx.h"
#include "inputs/inputs.h"
#include "methods/kernels.h"
#include "reference/reference.h"

#define SWEEP_MAX_KERNELS 256
/* grid cells: the maps keep per-cell arrays for every method (about 40
   bytes per cell, method and precision) */
#define SWEEP_MAX_GRID_CELLS (1u << 20)
/* The precisions a sweep holds, the index of its per-precision arrays:
   float, double and binary16 (PREC_*, common/prec.h). */
#define SWEEP_NPREC PREC_COUNT
#define NWORST 5
/* by_nz bins: n.z in [-1, 1]; log10(1 + n.z) in [-17, 0] for n.z <= 0;
   log10| |n|-1 | in [-9, -1]; log10(1 - n.z) in [-17, 0] for n.z >= 0 */
#define NB_NZ   100
#define NB_LOG  68
#define NB_NORM 32
#define NBINS   (NB_NZ + NB_LOG + NB_NORM + NB_LOG)

typedef struct {
	uint64_t count;
	fx sumsq;
	double max;
	uint64_t fcount;     /* the floor of the same inputs */
	fx fsumsq;
	double fmax;
} bin_t;

typedef struct {
	double key;          /* the per-input error; +inf for non-finite output */
	uint64_t index;      /* input index, or UINT64_MAX when empty          */
	int source;          /* 0 sampled, 1 found by the worst-case walk      */
	int branch;
	double n[3], out[6], ref[6];
	double defect, ulp, bits_max, dir_norm, dir_cos;
} worst_t;

/* Per stratum (inputs.h NSTRAT) sums for the estimates and their 95%
   intervals: the per-input quantities Q_* (their sum s and sum of squares
   s2), and for mean_bits the ratio's x = bits, y = components. */
enum { Q_SQ = 0, Q_DEF2, Q_DIRC2, Q_DUFF, NQ };
typedef struct {
	uint64_t n, by, by2;  /* finite inputs; sum of y and y^2 (integers)   */
	fx s[NQ], s2[NQ];
	fx bx, bx2, bxy;      /* bits: sum of x, x^2, x y                      */
} stratum_t;

/* Per stratum sums of the floor's estimates: inputs with a
   finite floor (fn, sum of floor^2), and of those with the kernel's output
   finite too (rn, sum of ratio^2, rat: ratio <= 1). */
typedef struct {
	uint64_t fn, rn, rat;
	fx f2, r2;
} fstrat_t;

typedef struct {
	uint64_t count, finite, nonfinite, wrong, comps;
	fx sumsq, sumdef2, bits, dirn2, dirc2;
	double max_defect, max_ulp, max_abs_eps, max_bits, max_in_norm, max_dir_norm, max_dir_cos;
	fx duffms;           /* Duff et al. 2017 footnote 1: sum of the per-input mean squares */
	double max_duff_rms; /* ... and the largest per-input root of it                     */
	stratum_t st[NSTRAT];
	worst_t worst[NWORST];
	bin_t bins[NBINS];
	/* The accuracy floor (reference.c floor_eval): the per-input
	   error of the exact formula rounded once (defect; direction error for
	   frisvad_rotate), over the inputs where it is finite, and the ratio
	   max(error, u^2) / max(floor, u^2) over the inputs where the kernel's
	   output is finite too; ratio_at: inputs with ratio <= 1 (at the
	   floor, or below it). */
	uint64_t floor_n, ratio_n, ratio_at, ratio_idx;
	fx floor2, ratio2;
	double max_floor, max_floor_dir, max_ratio;
	double ratio_in[3];  /* the input of max_ratio; ratio_idx UINT64_MAX: none */
	int ratio_src;
	fstrat_t fst[NSTRAT]; /* the same per stratum, for the stratified estimates */
} cell_t;

/* Everything that defines a run's data (not its thread count or output). */
typedef struct {
	char magic[16];
	uint64_t seed, samples, ex_values;
	double ex_from;
	int ex_azimuths, grid_rows, grid_cols, ref_bits, fma, check_every;
	int prec_on[SWEEP_NPREC], dist_on[NDIST];
	int nk;
	char names[SWEEP_MAX_KERNELS][64];
	int shard_k, shard_n;
	uint64_t counts[SWEEP_NPREC][NDIST];    /* inputs per distribution (before the walk) */
	uint64_t evals, checked;      /* referenced evaluations; two-precision checks */
	/* the reference path: 0 the certified fast path (reffast.c)
	   with MPFR where it cannot decide, 1 MPFR only (--ref mpfr); per
	   precision and kernel, the evaluations, those that fell back to MPFR,
	   and those whose ref[] MPFR filled in for the worst rows */
	int ref_mpfr;
	uint64_t ref_evals[SWEEP_NPREC][SWEEP_MAX_KERNELS], ref_fallback[SWEEP_NPREC][SWEEP_MAX_KERNELS],
	         ref_worst[SWEEP_NPREC][SWEEP_MAX_KERNELS];
} sweep_cfg;

typedef struct {
	sweep_cfg cfg;
	study_kernel kernels[SWEEP_MAX_KERNELS];
	cell_t *cells;                /* [prec][dist][kernel]                    */
	/* grid, per [prec][kernel][cell]: the per-input error, mean bits, b1 */
	double *g_err, *g_bits, *g_b1;
	unsigned char *g_done;        /* [prec][cell] computed by this state     */
} sweep_state;

/* The cell of (precision, distribution, kernel); _at for reading. */
cell_t *sweep_cell(sweep_state *s, int prec, int dist, int k);
const cell_t *sweep_cell_at(const sweep_state *s, int prec, int dist, int k);
void cell_init(cell_t *c);
void cell_merge(cell_t *dst, const cell_t *src);
void cell_add(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source);
/* The same, faster, for a cell filled from cell_init and settled once
   before it is read: six of the cell's sums (sumdef2, duffms, dirc2, bits,
   floor2, ratio2) are left out, and cell_settle adds them from the strata
   that hold the same terms.  Mixing cell_add into such a cell, or settling
   twice, counts those terms twice. */
void cell_add_lazy(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source);
void cell_settle(cell_t *c);

/* by_nz's bin of h in quarter decades, clampi((int)floor((log10(h) +
   off4 / 4) * 4), 0, nb - 1) for h > 0, else 0; exposed for the tests. */
int  sweep_log_bin(double h, int off4, int nb);

int  sweep_alloc(sweep_state *s);          /* 0, or -1 after a message */
void sweep_free(sweep_state *s);
/* Restore the kernels from cfg.names. */
int  sweep_kernels_from_names(sweep_state *s);

/* State files, sweep's and threshold's: a header starting with its magic
   string, then parts of known sizes.  open reads the header (NULL after
   "PATH: not a NOT_ONE" or the system's message); parts reads or writes
   each part in order (0, or -1 at a short read or write). */
typedef struct { void *p; size_t bytes; } state_part;
FILE *state_file_open(const char *path, void *hdr, size_t len, const char *magic, const char *not_one);
int   state_file_parts(FILE *f, const state_part *parts, int n, int write);
/* Close a file being read: 0, or -1 after "PATH: WHAT" when bad is set or
   bytes remain. */
int   state_file_end(FILE *f, const char *path, int bad, const char *what);

int  sweep_save_state(const sweep_state *s, const char *dir, const char *name);
int  sweep_load_state(sweep_state *s, const char *path);
/* The same with extra bytes after the state (the MPI driver's checkpoint:
   its done list); load returns them in a malloc'd buffer. */
int  sweep_save_state_x(const sweep_state *s, const char *dir, const char *name, const void *extra, size_t len);
int  sweep_load_state_x(sweep_state *s, const char *path, unsigned char **extra, size_t *len);
/* Whether two runs' data agree (all but the shard index and the counters:
   evals, checked, the reference path's); and adding s's counters to d's
   (a new counter in sweep_cfg goes in both). */
int  sweep_cfg_same(const sweep_cfg *a, const sweep_cfg *b);
void sweep_cfg_add_counters(sweep_cfg *d, const sweep_cfg *s);
int  sweep_merge_into(sweep_state *dst, const sweep_state *src);

/* The grid, per [prec][kernel][cell]: the layout is spelled out in
   sweep_grid_index alone.  put sets a cell of kernel k and marks the
   (prec, cell) computed; done says whether this state computed it. */
size_t sweep_grid_cells(const sweep_state *s);       /* rows * cols */
size_t sweep_grid_index(const sweep_state *s, int p, int k, size_t cell);
void   sweep_grid_put(sweep_state *s, int p, int k, size_t cell, double err, double bits, const double b1[3]);
int    sweep_grid_done(const sweep_state *s, int p, size_t cell);

/* Slices, the MPI driver's deltas: the cells [lo, hi) (index of
   sweep_cell's order) and, when grid != 0, the whole grid, as bytes.
   merge adds such bytes into d (-1 when n or [lo, hi) does not fit d);
   clear empties every cell and the grid's done marks. */
size_t sweep_slice_bytes(const sweep_state *s, size_t lo, size_t hi, int grid);
void   sweep_slice_pack(const sweep_state *s, size_t lo, size_t hi, int grid, unsigned char *out);
int    sweep_slice_merge(sweep_state *d, size_t lo, size_t hi, int grid, const unsigned char *in, size_t n);
void   sweep_clear(sweep_state *s);

#endif
