/*
 * csv.h - reading the study's own CSV files back (bench.csv, certify.csv,
 * summary.csv): a line split into fields, and a column found by name in
 * the header.  The ground floor: it includes nothing of the study.
 */
#ifndef ONB_COMMON_CSV_H
#define ONB_COMMON_CSV_H

/* Splits line (modified in place: its line ending removed, each field
   ended where its comma was) into f[0..], at most maxf fields; returns
   how many.  With quotes, a field that starts with '"' runs to the next
   '"' (both dropped; what follows up to the comma is dropped too), so
   it may hold commas; without, '"' is an ordinary character. */
int csv_split(char *line, char **f, int maxf, int quotes);

/* The index of the field called name among h[0..nh), or -1. */
int csv_col(char *const *h, int nh, const char *name);

#endif
