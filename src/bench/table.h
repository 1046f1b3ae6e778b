/*
 * bench/table.h - `onbstudy table` (table.c): bench.csv joined with a sweep's
 * summary.csv, the Pareto front, tradeoff.csv.
 */
#ifndef ONB_TABLE_H
#define ONB_TABLE_H


int cmd_table(int argc, char **argv);

/* ---- the trade table (table.c) ---------------------------------------- */
typedef struct {
	char   method[64];
	int    prec;              /* PREC_FLOAT or PREC_DOUBLE                   */
	double batch1;            /* batch M bases/s, 1 thread, L2-resident      */
	double batchn;            /* batch M bases/s, all threads, L2-resident   */
	int    threads;           /* threads of batchn                           */
	double call_ns;           /* call_throughput ns per call                 */
	double rmse_uniform;
	double max_south;         /* max_defect on south                         */
	double max_threshold;     /* max_defect on threshold                     */
	double max_worst;         /* max of max_defect over uniform, south, threshold */
	long   nonfinite;         /* nonfinite over the three                    */
	/* The accuracy floor on uniform (NaN when summary.csv
	   predates it): max_defect, the floor's max, x_floor = their ratio
	   (how far the method's worst case sits above the best the format can
	   hold), and the per-input ratio's RMS and max. */
	double max_uniform, max_floor_uniform, x_floor, rms_ratio_uniform, max_ratio_uniform;
	int    has_speed, has_accuracy;
	int    pareto;            /* 1 on the front of its precision             */
} tradeoff_row;

/* Reads bench.csv and summary.csv (lines starting with '#' skipped,
   columns found by header name) and joins them into rows (one per method
   and precision found in bench.csv, in its order) and marks the front.
   Returns the number of rows, or -1 with a message.  *rows is malloc'ed. */
int  tradeoff_load(const char *bench_csv, const char *summary_csv, double tol, tradeoff_row **rows);
/* Marks the Pareto front per precision, speeds within the fraction tol
   counting as equal (see table.c). */
void tradeoff_pareto(tradeoff_row *rows, int n, double tol);


#endif
