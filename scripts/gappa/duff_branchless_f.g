# duff_branchless_f.g - Gappa proof of the orthonormality defect of
# onb_duff_branchlessf (include/libonb/onb.h; float, round to nearest, no FMA)
# over the region n.z in [0.5, 0.75], every azimuth.
#
# Domain: n = (rnd(ux), rnd(uy), rnd(uz)) for a REAL unit vector u with
# uz in [0.5, 0.75] (so n.z in [0.5, 0.75]: rounding is monotone and both
# ends are floats).  The unit constraint is the hypothesis eps = 0 with
# eps = ux^2 + uy^2 + uz^2 - 1; it enters the proof only through
#   |n|^2 - 1 = (nx - ux)(nx + ux) + (ny - uy)(ny + uy) + (nz - uz)(nz + uz) + eps,
# an identity Gappa checks, so the input's own rounding is carried as the
# error terms nx - ux, ... .  Sub-boxes of (ux, uy) where eps cannot be 0
# (e.g. both near 0.87) are infeasible, and Gappa discards them.
#
# The kernel, op by op, with sign = copysign(1, n.z) = +1 here (n.z > 0):
#   a = -1/(sign + n.z); b = n.x*n.y*a;
#   b1 = (1 + sign*n.x*n.x*a, sign*b, -sign*n.x); b2 = (b, sign + n.y*n.y*a, -n.y)
# sign*n.x and the negations are exact; each other op rounds once.
#
# Defect = max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|), on the
# rounded outputs, exactly.  Each is bounded from the same basis computed
# EXACTLY from the float input n (E*): its error is the kernel's rounding,
# and E(n)'s own defect is a multiple of |n|^2 - 1 (identities below: the
# hints are rational identities, which Gappa verifies before using them).
#
# This file is the shared model followed by one block per defect term,
# each starting with a line '#== name'.  scripts/gappa.sh runs each block
# with the model as its own Gappa script (one goal at a time keeps Gappa's
# search small: the five goals at once ran for minutes and gave up
# iterating), and the defect's bound is the largest of the five.

@rnd = float<ieee_32, ne>;

nx = rnd(ux);
ny = rnd(uy);
nz = rnd(uz);

t   = rnd(1 + nz);
a   = rnd(-1 / t);
nxy = rnd(nx * ny);
b   = rnd(nxy * a);
nxx = rnd(nx * nx);
p1  = rnd(nxx * a);
b1x = rnd(1 + p1);
nyy = rnd(ny * ny);
p2  = rnd(nyy * a);
b2y = rnd(1 + p2);

# the same formula in exact arithmetic on the float input n
Et   = 1 + nz;
Ea   = -1 / Et;
Enxy = nx * ny;
Eb   = Enxy * Ea;
Enxx = nx * nx;
Ep1  = Enxx * Ea;
E1x  = 1 + Ep1;
Enyy = ny * ny;
Ep2  = Enyy * Ea;
E2y  = 1 + Ep2;

eps = ux * ux + uy * uy + uz * uz - 1;
Nn  = nx * nx + ny * ny + nz * nz;

d1n = b1x * nx + b * ny - nx * nz;
d2n = b * nx + b2y * ny - ny * nz;
d12 = b1x * b + b * b2y + nx * ny;
N1  = b1x * b1x + b * b + nx * nx;
N2  = b * b + b2y * b2y + ny * ny;
D1  = sqrt(N1) - 1;
D2  = sqrt(N2) - 1;

#== b1.n
# Each output's error, split into its roundings and the error of a (whose
# term is written with nx^2 + ny^2 = |n|^2 - nz^2 so that the unit
# constraint bounds it); E(n).n = nx (|n|^2 - 1) Ea.
{ ux in [-0.87, 0.87] /\ uy in [-0.87, 0.87] /\ uz in [0.5, 0.75] /\ eps in [0, 0]
  -> d1n in ? }
Nn - 1 -> (nx - ux) * (nx + ux) + (ny - uy) * (ny + uy) + (nz - uz) * (nz + uz) + eps;
d1n -> ((b1x - (1 + p1)) + (p1 - nxx * a) + (nxx - nx * nx) * a) * nx
     + ((b - nxy * a) + (nxy - nx * ny) * a) * ny
     + nx * ((Nn - 1) + 1 - nz * nz) * (a - Ea) + nx * (Nn - 1) * Ea { nz + 1 <> 0 };
$ ux in 32, uy in 32;

#== b2.n
{ ux in [-0.87, 0.87] /\ uy in [-0.87, 0.87] /\ uz in [0.5, 0.75] /\ eps in [0, 0]
  -> d2n in ? }
Nn - 1 -> (nx - ux) * (nx + ux) + (ny - uy) * (ny + uy) + (nz - uz) * (nz + uz) + eps;
d2n -> ((b - nxy * a) + (nxy - nx * ny) * a) * nx
     + ((b2y - (1 + p2)) + (p2 - nyy * a) + (nyy - ny * ny) * a) * ny
     + ny * ((Nn - 1) + 1 - nz * nz) * (a - Ea) + ny * (Nn - 1) * Ea { nz + 1 <> 0 };
$ uy in 32, ux in 32;

#== b1.b2
# E1.E2 = nx ny Ea^2 (|n|^2 - 1); the error of a enters both b and the
# diagonal, coherently: nx ny (a - Ea) (b1x + b2y + Ea (nx^2 + ny^2)).
{ ux in [-0.87, 0.87] /\ uy in [-0.87, 0.87] /\ uz in [0.5, 0.75] /\ eps in [0, 0]
  -> d12 in ? }
Nn - 1 -> (nx - ux) * (nx + ux) + (ny - uy) * (ny + uy) + (nz - uz) * (nz + uz) + eps;
d12 -> ((b - nxy * a) + (nxy - nx * ny) * a) * (b1x + b2y)
     + Eb * ((b1x - (1 + p1)) + (p1 - nxx * a) + (nxx - nx * nx) * a
           + (b2y - (1 + p2)) + (p2 - nyy * a) + (nyy - ny * ny) * a)
     + nx * ny * (a - Ea) * (b1x + b2y + Ea * ((Nn - 1) + 1 - nz * nz))
     + nx * ny * (Nn - 1) * Ea * Ea { nz + 1 <> 0 };
$ ux in 8, uy in 8;

#== |b1|-1
# |E1|^2 - 1 = nx^2 Ea^2 (|n|^2 - 1); |b1| - 1 = (|b1|^2 - 1)/(|b1| + 1),
# written with sqrt(N1)^2 for N1 so that the hint is a rational identity.
{ ux in [-0.87, 0.87] /\ uy in [-0.87, 0.87] /\ uz in [0.5, 0.75] /\ eps in [0, 0]
  -> D1 in ? }
Nn - 1 -> (nx - ux) * (nx + ux) + (ny - uy) * (ny + uy) + (nz - uz) * (nz + uz) + eps;
N1 - 1 -> (b1x - E1x) * (b1x + E1x) + (b - Eb) * (b + Eb) + nx * nx * (Nn - 1) * Ea * Ea { nz + 1 <> 0 };
N1 -> (N1 - 1) + 1;
D1 -> (sqrt(N1) * sqrt(N1) - 1) / (sqrt(N1) + 1) { sqrt(N1) + 1 <> 0 };
$ ux in 8, uy in 8;

#== |b2|-1
{ ux in [-0.87, 0.87] /\ uy in [-0.87, 0.87] /\ uz in [0.5, 0.75] /\ eps in [0, 0]
  -> D2 in ? }
Nn - 1 -> (nx - ux) * (nx + ux) + (ny - uy) * (ny + uy) + (nz - uz) * (nz + uz) + eps;
N2 - 1 -> (b2y - E2y) * (b2y + E2y) + (b - Eb) * (b + Eb) + ny * ny * (Nn - 1) * Ea * Ea { nz + 1 <> 0 };
N2 -> (N2 - 1) + 1;
D2 -> (sqrt(N2) * sqrt(N2) - 1) / (sqrt(N2) + 1) { sqrt(N2) + 1 <> 0 };
$ uy in 8, ux in 8;
