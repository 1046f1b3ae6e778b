/*
 * certify_mpi.h - `onbstudy-mpi certify` (certify_mpi.c), called by
 * onbstudy_mpi.c's main after MPI_Init_thread.
 */
#ifndef ONB_MPI_CERTIFY_MPI_H
#define ONB_MPI_CERTIFY_MPI_H

/* cmd_certify's arguments (the options after "certify") on every rank;
   provided: MPI_Init_thread's thread level.  The exit status, the same
   on every rank. */
int certify_mpi(int argc, char **argv, int rank, int nranks, int provided);

#endif
