/* seeds.h - placeholder until the seeds branch lands (same API). */
#ifndef ONB_CERTIFY_SEEDS_H
#define ONB_CERTIFY_SEEDS_H
typedef enum { SEED_RSQRTSS, SEED_INVSQRT_F, SEED_INVSQRT_D, NSEED } seed_kind;
typedef struct { double bound; double worst_x; double worst; double x_lo, x_hi; const char *how; } seed_bound;
int seed_bound_get(seed_kind k, seed_bound *out);
#endif
