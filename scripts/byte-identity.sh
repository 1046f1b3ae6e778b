#!/bin/sh
# byte-identity.sh - the runs whose CSV files must not change under a
# refactoring, and their comparison.
#   sh scripts/byte-identity.sh runs DIR        run them with ./onbstudy and
#                                               ./onbstudy-mpi (make all mpi)
#   sh scripts/byte-identity.sh compare OLD NEW every CSV and stdout of two
#                                               such DIRs, '#' lines stripped
# The runs: a default sweep (2 threads); two MPI sweeps on 2 ranks (fast and
# MPFR reference); a default threshold; threshold on 2 shards + merge; a small
# sweep on 2 shards + merge.
set -u
runs() {
	O=$1; rm -rf "$O"; mkdir -p "$O"
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
	export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
	A="--samples 1024 --exhaustive-count 512 --grid 4x8 --quiet"
	M="timeout 900 mpirun --oversubscribe -n 2 ./onbstudy-mpi"
	run() { n=$1; shift; "$@" > "$O/$n.out" 2> "$O/$n.err"; echo "$n: exit $?"; }
	run sweep ./onbstudy sweep --threads 2 --quiet --out "$O/sweep"
	run mpi $M sweep $A --threads 1 --out "$O/mpi"
	run mpimpfr $M sweep $A --ref mpfr --threads 1 --out "$O/mpimpfr"
	run thr ./onbstudy threshold --threads 2 --out "$O/thr"
	run thr0 ./onbstudy threshold --threads 2 --shard 0/2 --out "$O/thr0"
	run thr1 ./onbstudy threshold --threads 2 --shard 1/2 --out "$O/thr0"
	run merge ./onbstudy merge --out "$O/thrm" "$O"/thr0/threshold-state-0-of-2.bin "$O"/thr0/threshold-state-1-of-2.bin
	run sh0 ./onbstudy sweep $A --threads 2 --shard 0/2 --out "$O/sh"
	run sh1 ./onbstudy sweep $A --threads 2 --shard 1/2 --out "$O/sh"
	run shm ./onbstudy merge --threads 2 --out "$O/shm" "$O"/sh/sweep-state-0-of-2.bin "$O"/sh/sweep-state-1-of-2.bin
}
compare() {
	B=$1; A=$2; n=0; bad=0; T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
	for f in $(cd "$B" && find . -name '*.csv' -o -name '*.out' | sort); do
		n=$((n + 1))
		[ -f "$A/$f" ] || { echo "MISSING $f"; bad=$((bad + 1)); continue; }
		grep -v '^#' "$B/$f" > "$T/b"; grep -v '^#' "$A/$f" > "$T/a"
		cmp -s "$T/b" "$T/a" || { echo "DIFFERS $f"; bad=$((bad + 1)); }
	done
	[ "$(cd "$B" && find . -name '*.csv' | sort)" = "$(cd "$A" && find . -name '*.csv' | sort)" ] ||
		{ echo "the CSV file lists differ"; bad=$((bad + 1)); }
	echo "$n files compared (every CSV and stdout, '#' lines stripped): $bad differ"
	[ "$bad" -eq 0 ]
}
case "${1:-}" in
runs) [ $# -eq 2 ] || { echo "usage: sh scripts/byte-identity.sh runs DIR" >&2; exit 2; }; runs "$2" ;;
compare) [ $# -eq 3 ] || { echo "usage: sh scripts/byte-identity.sh compare OLD NEW" >&2; exit 2; }; compare "$2" "$3" ;;
*) echo "usage: sh scripts/byte-identity.sh runs DIR | compare OLD NEW" >&2; exit 2 ;;
esac
