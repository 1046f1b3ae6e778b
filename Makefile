# onbstudy - a plain, non-recursive Makefile.
#   make            libonb.a and the study CLI ./onbstudy
#   make lib        libonb.a alone (a C compiler and make; no packages)
#   make cross-check  arm64 and s390x under qemu (scripts/cross-check.sh)
#   make test       every test (installs missing packages: scripts/install-deps.sh --test)
#   make bench      the default benchmark run
#   make plots      charts of the newest run
#   make mpi        onbstudy-mpi, the MPI driver of the sweep (needs Open MPI's mpicc)
#   make gpu        onbstudy-gpu and the shader kernels (libvulkan, glslang; make test builds it)
#   make robustness the hardening checks, then results/robustness.md
#   make install    PREFIX=/usr/local DESTDIR=  (libonb/onb.h, libonb.a, onb.pc,
#                   onb.3, onbstudy.1; make install-compat adds the old <onb.h>)
#   make uninstall, make clean

CC      ?= cc
PREFIX  ?= /usr/local
DESTDIR ?=
AR      ?= ar

# Floating-point flags, each with its reason.  They are part of the study:
# every figure in results/ was produced with exactly these.
#  -ffp-contract=off   no silent contraction into FMA: a*b+c rounds twice, as
#                      the published listings assume, on every -march.  FMA is
#                      studied on purpose by a second copy of the kernels (--fma).
#  -fno-math-errno     sqrt() need not set errno, so loops calling it vectorize
#                      (sqrtps/sqrtpd) instead of falling back to scalar code.
#  -fno-trapping-math  we never read the FP exception flags; this lets GCC
#                      if-convert the branchy kernels (duff, frisvad) into blends.
#                      It changes no value, only which flags could be raised.
#  no -ffast-math      reassociation and reciprocal approximations would
#                      change every result.
# None of these reach a client: onb.pc carries only -I, -L and -l.  onb.h
# inlines its kernels only where the client's flags cannot change their
# bits, and calls these out-of-line copies otherwise (docs/library.md).
FPFLAGS = -ffp-contract=off -fno-math-errno -fno-trapping-math
# Where GCC in ISO C mode evaluates float in double (FLT_EVAL_METHOD 1,
# e.g. on s390x), binary32 rounding needs -fexcess-precision=fast; onb.h
# refuses to build the library without it.  x86-64: 0, no flag.
FLT_EVAL := $(shell printf '__FLT_EVAL_METHOD__\n' | $(CC) -std=c99 -E -P - 2>/dev/null | tr -d ' ')
ifneq ($(filter 1 2,$(FLT_EVAL)),)
  FPFLAGS += -fexcess-precision=fast
endif
OPT     ?= -O3
WARN    = -Wall -Wextra -Wpedantic -Wshadow -Werror=implicit-function-declaration
# The library is held to a stricter standard: -Wconversion and -Werror.
LIBWARN = $(WARN) -Wconversion -Werror
CFLAGS  ?= -g
SANITIZE ?=
ifneq ($(SANITIZE),)
  SANFLAGS = -fsanitize=$(SANITIZE) -fno-omit-frame-pointer -fno-sanitize-recover=all
endif
BASE    = -std=c99 $(OPT) $(FPFLAGS) $(CFLAGS) $(SANFLAGS) -Iinclude
# MPFR and GMP are linked statically: MPFR keeps its flags in thread-local
# storage, and the shared library reaches them through __tls_get_addr on
# every operation (11% of a sweep); the static archive uses direct TLS.
STUDY_LIBS = -Wl,-Bstatic -lmpfi -lmpfr -lgmp -Wl,-Bdynamic -lcjson -lm
OMP     = -fopenmp

B       = build
# --- libonb: `make lib` needs only a C compiler and make -------
# array.c, outline.c and batch.c are compiled once per method and precision
# (src/lib/split.h), so a static link pulls only the entry points a client
# calls; once more with -DONB_COMMON for their shared part.  The method
# names come from onb.h's two X-macro lists.
LIB_SRC = $(wildcard src/lib/*.c)
LIB_METHODS  := $(shell sed -n '/define ONB_METHOD_LIST/,/^$$/p' include/libonb/onb.h | grep -o 'X([a-z0-9_]*)' | sed 's/X(\(.*\))/\1/')
LIB_FMETHODS := $(shell grep 'define ONB_FLOAT_METHOD_LIST' include/libonb/onb.h | grep -o 'X([a-z0-9_]*)' | sed 's/X(\(.*\))/\1/')
LIB_SPLIT    = array outline batch
LIB_OBJ = $(LIB_SRC:src/lib/%.c=$(B)/lib/%.o) $(B)/lib/half_f16c.o \
          $(foreach f,$(LIB_SPLIT),$(LIB_METHODS:%=$(B)/lib/split/$(f)-d-%.o) \
                                   $(LIB_METHODS:%=$(B)/lib/split/$(f)-f-%.o) \
                                   $(LIB_FMETHODS:%=$(B)/lib/split/$(f)-f-%.o))
# The study's build installs its packages first (scripts/install-deps.sh);
# the library alone (make lib, make install, make uninstall) does not.
ifeq ($(filter-out lib install install-compat uninstall clean,$(MAKECMDGOALS)),)
ifneq ($(MAKECMDGOALS),)
LIB_DEPS =
else
LIB_DEPS = $(B)/deps.stamp
endif
else
LIB_DEPS = $(B)/deps.stamp
endif
# --- end libonb ------------------------------------------------------------
# The study: every src/<folder>/*.c but src/lib/ (libonb) and src/mpi/ (the
# MPI driver, built by `make mpi` only) and src/gpu/ (onbstudy-gpu, `make gpu`).  A new folder src/<name>/ is picked
# up by these wildcards with no edit here; its objects go to build/<name>/.
# Includes name their folder from -Isrc ("sweep/engine.h"); libonb/onb.h
# comes from -Iinclude.
STUDY_SRC = $(filter-out src/lib/% src/mpi/% src/gpu/%,$(wildcard src/*/*.c))
STUDY_OBJ = $(STUDY_SRC:src/%.c=$(B)/%.o)
STUDY_HDR = $(filter-out src/lib/% src/gpu/%,$(wildcard src/*/*.h src/*/*.inc))
MAIN_OBJ  = $(B)/cli/main.o
# Everything of the study but main(), so tests can link the study's modules.
STUDY_LIB = $(B)/libstudy.a
TEST_SRC  = $(wildcard tests/test_*.c)
TEST_BIN  = $(TEST_SRC:tests/%.c=$(B)/tests/%)
# Helpers that shell tests call (not run on their own); found_walk is the
# outside search that certify's found side is measured against.
TEST_AUX  = $(B)/tests/certify_check $(B)/tests/found_walk
GIT_REV  := $(shell git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(shell git diff --quiet HEAD -- . ':(exclude)results' 2>/dev/null || echo -dirty)
PROV     = -DONB_GIT_REV='"$(GIT_REV)"' -DONB_CC='"$(shell $(CC) --version | head -1)"' \
           -DONB_CFLAGS='"$(BASE)"'

.PHONY: all test bench plots install uninstall clean deps
all: libonb.a onbstudy

# Dependencies: installed by the script when missing (a stamp records
# success): the study's few for `make`, the charts' for `make plots` and
# `make render`, Open MPI for `make mpi`, and everything the tests and CI
# use for `make test` (docs/install.md gives what
# each costs).  The stamps come one after the other: two apt-get runs at
# once would fight over dpkg's lock under make -j.
$(B)/deps.stamp: scripts/install-deps.sh
	@mkdir -p $(B)
	sh scripts/install-deps.sh
	@touch $@
$(B)/plot-deps.stamp: scripts/install-deps.sh $(B)/deps.stamp
	sh scripts/install-deps.sh --plots
	@touch $@
$(B)/mpi-deps.stamp: scripts/install-deps.sh $(B)/deps.stamp
	sh scripts/install-deps.sh --mpi
	@touch $@
$(B)/test-deps.stamp: scripts/install-deps.sh $(B)/deps.stamp
	sh scripts/install-deps.sh --test
	@touch $@
deps: $(B)/deps.stamp

# --- libonb rules ---
.PHONY: lib
lib: libonb.a
# The scalar entry points (one basis per call: array, outline, checked)
# are built without basic-block (SLP) vectorization.  With it GCC reads
# n.y and n.z as one 8-byte (float) or 16-byte (double) load; when the
# caller has just stored them one at a time, or when the by-value struct
# comes in two registers that the entry spills, that load cannot be
# forwarded from the store buffer and a call cost up to 5x the kernel
# (results/clients/entries.md).  Same bits: SLP reorders no arithmetic.
# The batch loops keep it (their loads are of arrays written long before).
ENTRYFLAGS = -fno-tree-slp-vectorize
ENTRYFLAGS_array = $(ENTRYFLAGS)
ENTRYFLAGS_outline = $(ENTRYFLAGS)
ENTRYFLAGS_checked = $(ENTRYFLAGS)
$(B)/lib/%.o: src/lib/%.c include/libonb/onb.h src/lib/split.h Makefile | $(LIB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(BASE) $(LIBWARN) $(ENTRYFLAGS_$*) -DONB_COMMON -c $< -o $@
define ONB_SPLIT_RULE
$(B)/lib/split/$(1)-$(2)-%.o: src/lib/$(1).c include/libonb/onb.h src/lib/split.h Makefile | $(LIB_DEPS)
	@mkdir -p $$(@D)
	$$(CC) $$(BASE) $$(LIBWARN) $$(ENTRYFLAGS_$(1)) -DONB_ONE=$$* -DONB_ONE_$(3) -c $$< -o $$@
endef
$(foreach f,$(LIB_SPLIT),$(eval $(call ONB_SPLIT_RULE,$(f),d,D))$(eval $(call ONB_SPLIT_RULE,$(f),f,F)))

# half.c again with F16C conversions (vcvtph2ps, vcvtps2ph): the copy its
# ifuncs pick on CPUs with F16C (half.c says why; an empty object where
# there is no dispatch: clang, other architectures).
ifeq ($(shell uname -m),x86_64)
HALF_F16C_FLAGS = -mf16c
endif
$(B)/lib/half_f16c.o: src/lib/half.c include/libonb/onb.h src/lib/split.h Makefile | $(LIB_DEPS)
	@mkdir -p $(@D)
	$(CC) $(BASE) $(LIBWARN) $(HALF_F16C_FLAGS) -DONB__HALF_F16C -c $< -o $@

libonb.a: $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $(LIB_OBJ)
# make cross-check: the library, its tests and the mesh readers' tests on
# arm64 and s390x under qemu-user, bit identity to x86-64; the record of
# the last run goes to results/cross-check/ (scripts/cross-check.sh).
.PHONY: cross-check
cross-check:
	sh scripts/cross-check.sh results/cross-check
# --- end libonb rules ---

$(filter-out $(B)/bench/yardstick.o,$(STUDY_OBJ)): $(B)/%.o: src/%.c include/libonb/onb.h $(STUDY_HDR) Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) $(WARN) $(OMP) $(PROV) $(XFLAGS) -Isrc -D_POSIX_C_SOURCE=200809L -c $< -o $@

# Provenance: output.o and main.o carry the git revision and the flags.
# rev.stamp changes whenever they do (checked on every make), so a result
# file never names a stale revision.  (Its temporary file is the shell's
# own: tests that run make run two at a time, scripts/test-run.sh.)
$(B)/rev.stamp: FORCE
	@mkdir -p $(B)
	@t=$@.tmp.$$$$; echo '$(GIT_REV) $(BASE)' > $$t; if cmp -s $$t $@; then rm -f $$t; else mv $$t $@; fi
$(B)/common/output.o $(MAIN_OBJ): $(B)/rev.stamp
# certify's keys (src/certify/keys.c): a hash of the sources that decide a
# region's result beyond its method; engine.stamp changes when it does.
CERT_ENGINE_SRC = $(sort $(wildcard src/certify/*.[ch] src/model/*.[ch] src/reference/*.[ch] src/inputs/*.[ch] src/arith/*.[ch] src/common/prec.h))
CERT_ENGINE_SUM := $(shell cat $(CERT_ENGINE_SRC) 2>/dev/null | cksum | cut -d' ' -f1)
# ... named by an earlier sum where src/certify/engines.txt declares the two
# engines' results byte-identical (a faster evaluation of the same
# enclosures: the keys of results made by the earlier one stay current)
CERT_ENGINE := $(shell awk -v s=$(CERT_ENGINE_SUM) '$$1 == s { print $$2; f = 1; exit } END { if (!f) print s }' src/certify/engines.txt 2>/dev/null || echo $(CERT_ENGINE_SUM))
$(B)/engine.stamp: FORCE
	@mkdir -p $(B)
	@t=$@.tmp.$$$$; echo '$(CERT_ENGINE)' > $$t; if cmp -s $$t $@; then rm -f $$t; else mv $$t $@; fi
$(B)/certify/keys.o: $(B)/engine.stamp
$(B)/certify/keys.o: XFLAGS += -DONB_CERT_ENGINE='"$(CERT_ENGINE)"' -DONB_CODE_KEYS -I$(B)/certify
.PHONY: FORCE
FORCE:

# The FMA copy of the kernels for `sweep --fma`: contraction on, on purpose.
# Never instrumented: a sanitizer changes which products GCC contracts, and
# certify --fma's models are checked bit-exact against this object as a
# client's plain -ffp-contract=fast build compiles it (tests/test_certify).
$(B)/methods/fma_kernels.o: SANFLAGS =
ifeq ($(shell uname -m),x86_64)
$(B)/methods/fma_kernels.o: XFLAGS = -mfma -ffp-contract=fast
else
$(B)/methods/fma_kernels.o: XFLAGS = -ffp-contract=fast
endif

# The fast reference: TwoProd through the fma instruction.  Only
# fma() calls use it: -ffp-contract=off (BASE) still forbids contraction.
# reffast_usable() refuses this path on a CPU without FMA.
ifeq ($(shell uname -m),x86_64)
$(B)/reference/reffast.o $(B)/reference/reffast_f.o: XFLAGS = -mfma
endif

# reffast_f.c is reffast.c compiled again with pairs of doubles.
$(B)/reference/reffast_f.o: src/reference/reffast.c

# Each family file (src/families/family.h) is compiled three more times
# beside the study's rule: its branch rule with contraction, as the FMA
# copy of the kernels (FAMILY_PASS=1), and its fast-reference formula in
# pairs of doubles (2) and of long doubles (3), with reffast.c's flags.
FAMILY_SRC  = $(filter-out src/families/families.c,$(wildcard src/families/*.c))
# families.c's list of every family comes from the family files themselves
# (scripts/family-list.sh), so a new family is listed by being defined.
$(B)/families/families.o: XFLAGS = '-DSTUDY_FAMILY_LIST(X)=$(shell sh scripts/family-list.sh)'
$(B)/families/families.o: $(FAMILY_SRC) scripts/family-list.sh
FAMILY_PASS_OBJ = $(foreach p,fma pair_d pair_l,$(FAMILY_SRC:src/families/%.c=$(B)/families/$(p)/%.o))
ifeq ($(shell uname -m),x86_64)
FAMILY_FMA_FLAGS  = -mfma -ffp-contract=fast
FAMILY_PAIR_FLAGS = -mfma
else
FAMILY_FMA_FLAGS  = -ffp-contract=fast
FAMILY_PAIR_FLAGS =
endif
FAMILY_CC = $(CC) $(BASE) $(WARN) $(OMP) -Isrc -D_POSIX_C_SOURCE=200809L
$(B)/families/fma/%.o: src/families/%.c include/libonb/onb.h $(STUDY_HDR) Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(FAMILY_CC) -DFAMILY_PASS=1 $(FAMILY_FMA_FLAGS) -c $< -o $@
$(B)/families/pair_d/%.o: src/families/%.c include/libonb/onb.h $(STUDY_HDR) Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(FAMILY_CC) -DFAMILY_PASS=2 $(FAMILY_PAIR_FLAGS) -c $< -o $@
$(B)/families/pair_l/%.o: src/families/%.c include/libonb/onb.h $(STUDY_HDR) Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(FAMILY_CC) -DFAMILY_PASS=3 $(FAMILY_PAIR_FLAGS) -c $< -o $@

# certify's keys also take, per method, a checksum of its compiled kernel and its family's
# compiled model (scripts/code-keys.sh), so that a changed kernel or model
# makes new keys for exactly the methods whose code changed.
CODE_KEY_OBJ = $(filter $(B)/lib/split/outline-%,$(LIB_OBJ)) $(FAMILY_SRC:src/families/%.c=$(B)/families/%.o) \
               $(FAMILY_PASS_OBJ) $(B)/methods/fma_kernels.o $(B)/methods/kernels.o $(B)/lib/half.o $(B)/lib/half_f16c.o
$(B)/certify/code_keys.h: scripts/code-keys.sh $(CODE_KEY_OBJ)
	@mkdir -p $(@D)
	sh scripts/code-keys.sh $(B) > $@.tmp && mv $@.tmp $@
$(B)/certify/keys.o: $(B)/certify/code_keys.h

# The benchmark's yardstick: plain loops built for this CPU, beside
# libonb's run-time dispatch.  Same FPFLAGS; no memcpy idiom for the copy.
# (left out of the study's rule above, which compiles every other object)
$(B)/bench/yardstick.o: src/bench/yardstick.c src/bench/yardstick.h include/libonb/onb.h Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) -march=native -fno-tree-loop-distribute-patterns $(WARN) -Isrc -c $< -o $@

# Certify: src/certify/ is compiled by the study's rule above; its
# interval proofs use MPFI (linked statically, before MPFR, for the reason
# given at STUDY_LIBS).
STUDY_LIBS := -Wl,-Bstatic -lmpfi -Wl,-Bdynamic $(STUDY_LIBS)

$(STUDY_LIB): $(filter-out $(MAIN_OBJ),$(STUDY_OBJ)) $(FAMILY_PASS_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

onbstudy: $(MAIN_OBJ) $(STUDY_LIB) libonb.a
	$(CC) $(BASE) $(OMP) -o $@ $(MAIN_OBJ) $(STUDY_LIB) libonb.a $(STUDY_LIBS)

$(B)/tests/%: tests/%.c $(STUDY_LIB) libonb.a include/libonb/onb.h $(wildcard tests/*.h) $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) $(WARN) $(OMP) $(PROV) -D_POSIX_C_SOURCE=200809L -Isrc -o $@ $< $(STUDY_LIB) libonb.a $(STUDY_LIBS)

# Under SANITIZE the checks of documents and charts against committed
# results are left out: they run no C code that other tests do not run
# (sweep, threshold, bench and table have their own), so a sanitizer has
# nothing more to find there, and they take minutes.  So is the check of the
# committed certify keys: a key holds checksums of the plain build's
# compiled kernels and models, which an instrumented build never matches.
# Three more run no C code of ours that a sanitizer could watch, or only
# what another sanitized test runs: function_lengths.sh (awk over the
# sources), lib_minimal.sh (cc -M, dpkg -S and make -n: the same
# commands, the same result, with or without SANITIZE; 69 s by the wall
# clock for 4 s of CPU at load 24) and man_pages.sh (help2man over every
# command's --help, which tests/cli_getopt.sh runs under the sanitizer,
# --help and -h of every command).  The plain suite runs all of them.
SANITIZE_SKIP = tests/doc_links.sh tests/findings.sh tests/plots_cli.sh tests/wild.sh tests/charts_committed.sh tests/charts_small.sh tests/certify_keys_committed.sh \
                tests/function_lengths.sh tests/lib_minimal.sh tests/man_pages.sh
TEST_SH = $(filter-out tests/lib.sh $(if $(SANITIZE),$(SANITIZE_SKIP)),$(wildcard tests/*.sh))
# Under SANITIZE the C tests that repeat the same code over more inputs run
# smaller budgets (TEST:ARGUMENT; the plain suite runs the full ones): the
# same distributions, methods, precisions and special inputs, fewer random
# ones per method.  test_reffast 500 inputs per distribution (2000),
# test_certify 10^5 per method and precision (10^6), test_indep --quick
# (16384 uniform inputs, every pole and threshold input; 10^6).
SANITIZE_ARGS = test_reffast:500 test_certify:100000 test_indep:--quick
# everything the tests need, built (in parallel with make -jN test-build:
# CI does that first; the MPI driver and aorender too, which tests/mpi.sh,
# certify_mpi.sh and render_obj.sh would otherwise build while other tests
# run); `make test` then runs the tests TEST_JOBS at a time
# (scripts/test-run.sh: each test's output whole, in this order; TEST_JOBS=1
# runs them one by one).  Wall and CPU seconds per test go to
# $(B)/test-times.tsv.
TEST_JOBS ?= 2
.PHONY: test-build
test-build: $(B)/test-deps.stamp all $(TEST_BIN) $(TEST_AUX) gpu onbstudy-mpi $(B)/aorender
test: test-build
	@$(if $(SANITIZE),echo "make test: not run under SANITIZE: $(SANITIZE_SKIP)";) \
	fail=0; ONB_SANFLAGS='$(SANFLAGS)' sh scripts/test-run.sh $(TEST_JOBS) $(B)/test-logs \
	  $(foreach t,$(TEST_BIN) $(TEST_SH),$(t)$(if $(SANITIZE),$(patsubst $(notdir $(t)):%,:%,$(filter $(notdir $(t)):%,$(SANITIZE_ARGS))))) || fail=1; \
	cp $(B)/test-logs/times.tsv $(B)/test-times.tsv; \
	echo "make test: seconds per test, wall and CPU (the slowest five; all in $(B)/test-times.tsv):"; sort -k2,2nr $(B)/test-times.tsv | head -5; \
	awk -F'\t' '{ w += $$2; c += $$3 } END { printf "make test: %d tests, %.0f s of wall and %.0f s of CPU summed over the tests, $(TEST_JOBS) at a time\n", NR, w, c }' $(B)/test-times.tsv; \
	if [ $$fail -ne 0 ]; then echo "make test: FAILED"; exit 1; fi; echo "make test: all passed"

# make check-method M=NAME: what a new method needs, in about a minute:
# its parts (test_parts NAME: registry, family, kernel against its
# family's formula, eval's branch words, axes rows, man page, header index),
# the independent transliterations (test_indep --quick), its rounding model
# bit-exact on 20000 inputs (test_certify), and a small sweep and certify.
CHECK_OUT = $(B)/check-method
.PHONY: check-method
check-method: all $(B)/tests/test_parts $(B)/tests/test_indep $(B)/tests/test_certify
	@test -n "$(M)" || { echo "usage: make check-method M=NAME"; exit 2; }
	$(B)/tests/test_parts $(M)
	$(B)/tests/test_indep --quick
	$(B)/tests/test_certify 20000 $(M)
	./onbstudy sweep --methods $(M) --samples 4096 --exhaustive-count 512 --grid 4x8 --threads 2 --quiet --out $(CHECK_OUT)
	./onbstudy certify --methods $(M) --quick --quiet --out $(CHECK_OUT)
	@echo "check-method $(M): passed"

bench: onbstudy
	./onbstudy bench

# make plots [RUN=results/<run>]: charts of a run (default results/latest)
# The run's data is looked for first, before anything is built or installed.
RUN ?= results/latest
plots:
	@test -f $(RUN)/summary.csv && test -f $(RUN)/by_nz.csv || { \
	  echo "plots: no sweep data in $(RUN) (summary.csv, by_nz.csv): run a sweep first, \`make && ./onbstudy sweep\`, or give RUN=DIR" >&2; exit 2; }
	$(MAKE) --no-print-directory onbstudy $(B)/plot-deps.stamp
	sh scripts/plots.sh $(RUN)

# # make robustness: the hardening run (scripts/harden.sh: its steps took 1740 s
# on 2 cores at load 1-4 in results/quickstart/ci-rehearsal.txt),
# then the committed results/robustness.md and docs/testing.md's copy of its
# summary from that run's logs.  CI runs the same checks but writes its
# table to build/harden/ only, so it changes no tracked file.
FUZZ_SECS ?= 120
.PHONY: robustness
robustness:
	sh scripts/harden.sh $(FUZZ_SECS)
	sh scripts/robustness.sh

# onb.pc is written for the PREFIX of this very `make install`, every time,
# straight into the destination: no generated file in the tree to go stale.
ONB_PC = prefix=%s\nincludedir=$${prefix}/include\nlibdir=$${prefix}/lib\n\nName: onb\nDescription: orthonormal bases from a unit vector (onbstudy)\nVersion: 0.1.0\nCflags: -I$${includedir}\nLibs: -L$${libdir} -lonb -lm\n
# The header goes to include/libonb/onb.h: clients write <libonb/onb.h>, so a
# renderer's own onb.h (a common name) cannot shadow it or be shadowed.
# `make install-compat` adds include/onb.h, a short forward for code
# written against the old <onb.h>; it is opt-in because it takes that name.
install: libonb.a
	install -d $(DESTDIR)$(PREFIX)/include/libonb $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/libonb/onb.h $(DESTDIR)$(PREFIX)/include/libonb/onb.h
	install -m 644 libonb.a $(DESTDIR)$(PREFIX)/lib/libonb.a
	printf '$(ONB_PC)' '$(PREFIX)' > $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc.tmp
	mv -f $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc.tmp $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc

# include/onb.h is removed only when it is libonb's (the forward, or the
# header itself as installed before it moved to libonb/).
uninstall:
	rm -f $(DESTDIR)$(PREFIX)/include/libonb/onb.h $(DESTDIR)$(PREFIX)/lib/libonb.a \
	      $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc
	rmdir $(DESTDIR)$(PREFIX)/include/libonb 2>/dev/null || true
	if grep -qs 'LIBONB_COMPAT_ONB_H\|^ \* onb.h - orthonormal bases {b1, b2, n}' $(DESTDIR)$(PREFIX)/include/onb.h; then \
	  rm -f $(DESTDIR)$(PREFIX)/include/onb.h; fi
.PHONY: install-compat
install-compat: install
	install -m 644 include/compat/onb.h $(DESTDIR)$(PREFIX)/include/onb.h

clean:
	rm -rf $(B) libonb.a onbstudy onbstudy-mpi onbstudy-gpu onb.pc   # onb.pc: left by older Makefiles

# The MPI driver: `make mpi` builds onbstudy-mpi with Open MPI's
# mpicc (installed by scripts/install-deps.sh --mpi when missing); the
# default build does not need MPI.  It links the same study
# library, so it runs the same engine as ./onbstudy.
MPICC ?= mpicc
.PHONY: mpi
mpi: onbstudy-mpi
MPI_OBJ = $(B)/mpi/onbstudy_mpi.o $(B)/mpi/certify_mpi.o
$(MPI_OBJ): $(B)/mpi/%.o: src/mpi/%.c src/mpi/certify_mpi.h $(STUDY_HDR) include/libonb/onb.h Makefile $(B)/rev.stamp $(B)/mpi-deps.stamp
	@mkdir -p $(@D)
	$(MPICC) $(BASE) $(WARN) $(OMP) $(PROV) -Isrc -D_POSIX_C_SOURCE=200809L -c $< -o $@
onbstudy-mpi: $(MPI_OBJ) $(STUDY_LIB) libonb.a
	$(MPICC) $(BASE) $(OMP) -o $@ $(MPI_OBJ) $(STUDY_LIB) libonb.a $(STUDY_LIBS) -lpthread

# The shader study: `make gpu` builds onbstudy-gpu, which runs libonb's
# GLSL and HLSL kernels (include/libonb/onb.glsl, onb.hlsl) and the shader
# engines' lines on a Vulkan driver (Mesa's lavapipe) against the C
# kernels, and compiles those kernels to SPIR-V with glslang.  It links
# libvulkan, so it comes with the test packages (install-deps.sh --test)
# and `make test` builds it; `make` and `make lib` never need Vulkan.
# The kernels: GLSL as written and with ONB_PRECISE=precise (every
# operation NoContraction), the same two through glslang's HLSL front end
# (-D -e main), and GLSL without ONB_FLOAT64 (compiled only: onb.glsl
# must build on a device without shaderFloat64).
GLSLANG ?= glslangValidator
GPU_SRC  = $(wildcard src/gpu/*.c)
GPU_OBJ  = $(GPU_SRC:src/%.c=$(B)/%.o)
GPU_SPV  = $(addprefix $(B)/gpu/,onb_glsl.spv onb_glsl_precise.spv onb_hlsl.spv onb_hlsl_precise.spv onb_glsl_nof64.spv ops.spv ops_preserve.spv half.spv relaxed/gltf_viewer.spv) $(WILD_SPV)
# The shader engines' own lines: one file each under src/gpu/wild/, each
# compiled with the harness wild.comp (which includes it as engine.glsl).
WILD_SPV = $(patsubst src/gpu/wild/%.glsl,$(B)/gpu/wild/%.spv,$(wildcard src/gpu/wild/*.glsl))
GPU_KDEPS = include/libonb/onb.glsl include/libonb/onb.hlsl src/gpu/methods.inc $(B)/test-deps.stamp
GLSLC    = $(GLSLANG) -V -Iinclude -Isrc --quiet
.PHONY: gpu
gpu: onbstudy-gpu $(GPU_SPV)
$(GPU_OBJ): $(B)/%.o: src/%.c $(wildcard src/gpu/*.h) src/gpu/methods.inc src/gpu/half_methods.inc $(STUDY_HDR) include/libonb/onb.h Makefile $(B)/test-deps.stamp $(B)/rev.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) $(WARN) $(PROV) -DONB_GLSLANG='"$(shell $(GLSLANG) --version 2>/dev/null | head -1)"' -Isrc -D_POSIX_C_SOURCE=200809L -c $< -o $@
onbstudy-gpu: $(GPU_OBJ) $(STUDY_LIB) libonb.a
	$(CC) $(BASE) $(OMP) -o $@ $(GPU_OBJ) $(STUDY_LIB) libonb.a $(STUDY_LIBS) -lvulkan
$(B)/gpu/onb_glsl.spv: src/gpu/kernel.comp $(GPU_KDEPS)
	@mkdir -p $(@D)
	$(GLSLC) -DONB_FLOAT64 $< -o $@
$(B)/gpu/onb_glsl_precise.spv: src/gpu/kernel.comp $(GPU_KDEPS)
	@mkdir -p $(@D)
	$(GLSLC) -DONB_FLOAT64 -DONB_PRECISE=precise $< -o $@
$(B)/gpu/onb_glsl_nof64.spv: src/gpu/kernel.comp $(GPU_KDEPS)
	@mkdir -p $(@D)
	$(GLSLC) $< -o $@
$(B)/gpu/onb_hlsl.spv: src/gpu/kernel.hlsl $(GPU_KDEPS)
	@mkdir -p $(@D)
	$(GLSLC) -D -e main -S comp -DONB_FLOAT64 $< -o $@
$(B)/gpu/onb_hlsl_precise.spv: src/gpu/kernel.hlsl $(GPU_KDEPS)
	@mkdir -p $(@D)
	$(GLSLC) -D -e main -S comp -DONB_FLOAT64 -DONB_PRECISE=precise $< -o $@
$(B)/gpu/half.spv: src/gpu/half.comp src/gpu/half_methods.inc $(B)/test-deps.stamp
	@mkdir -p $(@D)
	$(GLSLC) $< -o $@
# gltf_viewer as its source declares it, `precision mediump float` (RelaxedPrecision)
$(B)/gpu/relaxed/gltf_viewer.spv: src/gpu/wild/gltf_viewer.glsl src/gpu/wild.comp $(B)/test-deps.stamp
	@mkdir -p $(B)/gpu/relaxed/gltf_viewer
	cp $< $(B)/gpu/relaxed/gltf_viewer/engine.glsl
	$(GLSLC) -DONB_MEDIUMP -I$(B)/gpu/relaxed/gltf_viewer src/gpu/wild.comp -o $@
$(B)/gpu/ops_preserve.spv: src/gpu/ops.comp $(B)/test-deps.stamp
	@mkdir -p $(@D)
	$(GLSLC) -DONB_PRESERVE $< -o $@
$(B)/gpu/wild/%.spv: src/gpu/wild/%.glsl src/gpu/wild.comp $(B)/test-deps.stamp
	@mkdir -p $(B)/gpu/wild/$*
	cp $< $(B)/gpu/wild/$*/engine.glsl
	$(GLSLC) -I$(B)/gpu/wild/$* src/gpu/wild.comp -o $@
$(B)/gpu/%.spv: src/gpu/%.comp $(B)/test-deps.stamp
	@mkdir -p $(@D)
	$(GLSLC) $< -o $@

# The example renderer links libonb.a and libm, as a user's would, and the
# scene reader (meshio, whose glTF part links cJSON) for --obj.
MESHIO_SRC = $(wildcard src/mesh/*.c)
$(B)/aorender: examples/aorender.c $(MESHIO_SRC) $(wildcard src/mesh/*.h) libonb.a include/libonb/onb.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -ffp-contract=off $(SANFLAGS) -Wall -Wextra -Wpedantic -Wshadow -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -o $@ examples/aorender.c $(MESHIO_SRC) libonb.a -lcjson -lm
RENDERS = results/reference/renders
RENDER_GREY = frisvad tangent_cross_z
# the brushed-metal renders (aorender --brushed, scripts/brushed.gp): the
# methods whose frames the metrics separate, one chart each, with its
# scale and caption
RENDER_BRUSHED = duff duff_branchless hughes_moeller frisvad frisvad_max naive_nonorm hughes_moeller_nonorm tangent_cross_z
.PHONY: render render-brushed
render-brushed: $(B)/aorender $(B)/plot-deps.stamp
	@mkdir -p $(RENDERS)/brushed
	@for m in $(RENDER_BRUSHED); do \
	  l=$$($(B)/aorender --method $$m --precision float --brushed $(B)/brushed-$$m.dat) || exit 1; echo "$$l"; \
	  mx=$$(echo "$$l" | sed 's/.*max |image - exact frame| \([^ ]*\) .*/\1/'); nn=$$(echo "$$l" | sed 's/.*NaN pixels //'); \
	  e=$$(echo $$m | sed 's/_/\\_/g'); \
	  gnuplot -e "here='scripts'; nosvg=1; file='$(B)/brushed-$$m.dat'; out='$(RENDERS)/brushed/$$m-float'; name='$$e'; prec='float'; maxd=$$mx; nan=$$nn" scripts/brushed.gp || exit 1; \
	  if command -v pngquant >/dev/null 2>&1; then pngquant --force --skip-if-larger --speed 1 --output $(RENDERS)/brushed/$$m-float.png 256 $(RENDERS)/brushed/$$m-float.png || true; fi; \
	done | tee $(RENDERS)/brushed/summary.txt
render: $(B)/aorender $(B)/plot-deps.stamp render-brushed
	@mkdir -p $(RENDERS)
	@# every render a chart (scripts/ao.gp: title, scales, what to look
	@# for, a legible font): the reference's image; every method's
	@# difference to it, beside its image only for RENDER_GREY (the
	@# others' images look the same as the reference's)
	$(B)/aorender --method duff_branchless --precision double --out $(B)/render-ref.png
	gnuplot -e "here='scripts'; nosvg=1; grey='$(B)/render-ref.png'; out='$(RENDERS)/reference-double'; name='duff\\_branchless'; prec='double'; maxd=0; over=0; nan=0" scripts/ao.gp
	@# (the methods of the reference run that aorender has: the study's
	@# frisvad_rotate is not in libonb)
	@$(B)/aorender --list > $(B)/render-list.txt
	@for m in $$(awk -F, '!/^#/ && $$1 != "method" { sub(/\+fma$$/, "", $$1); if (!s[$$1]++) print $$1 }' results/reference/summary.csv | grep -Fx -f $(B)/render-list.txt); do \
	  l=$$($(B)/aorender --method $$m --precision float --out $(B)/render-grey.png --diff $(B)/render-diff.png) || exit 1; echo "$$l"; \
	  case " $(RENDER_GREY) " in *" $$m "*) g="grey='$(B)/render-grey.png';";; *) g="";; esac; \
	  mx=$$(echo "$$l" | sed 's/.* max \([^ ]*\) .*/\1/'); ov=$$(echo "$$l" | sed 's/.*pixels > [^:]*: *\([0-9]*\) .*/\1/'); nn=$$(echo "$$l" | sed 's/.*NaN pixels //'); \
	  e=$$(echo $$m | sed 's/_/\\_/g'); \
	  gnuplot -e "here='scripts'; nosvg=1; $$g diff='$(B)/render-diff.png'; out='$(RENDERS)/$$m-float-diff'; name='$$e'; prec='float'; maxd=$$mx; over=$$ov; nan=$$nn" scripts/ao.gp || exit 1; \
	done | tee $(RENDERS)/summary.txt
	@if command -v pngquant >/dev/null 2>&1; then for f in $(RENDERS)/*.png; do \
	  pngquant --force --skip-if-larger --speed 1 --output $$f 256 $$f || true; done; \
	else echo "render: pngquant missing (scripts/install-deps.sh --plots): the PNGs stay uncompressed"; fi

# Man pages: man/onbstudy.1 is generated from the commands' own
# --help by help2man (`make man`, scripts/man.sh; tests/man_pages.sh fails
# when it is stale), man/onb.3 is written by hand from include/libonb/onb.h.
# `make install` installs both under $(MANDIR); neither needs a tool to install.
MANDIR ?= $(PREFIX)/share/man
.PHONY: man install-man uninstall-man
man: onbstudy
	sh scripts/man.sh
install: install-man
install-man:
	install -d $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man3
	install -m 644 man/onbstudy.1 $(DESTDIR)$(MANDIR)/man1/onbstudy.1
	install -m 644 man/onb.3 $(DESTDIR)$(MANDIR)/man3/onb.3
uninstall: uninstall-man
uninstall-man:
	rm -f $(DESTDIR)$(MANDIR)/man1/onbstudy.1 $(DESTDIR)$(MANDIR)/man3/onb.3
