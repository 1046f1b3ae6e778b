# onbstudy - a plain, non-recursive Makefile.
#   make            libonb.a and the study CLI ./onbstudy
#   make test       every test (installs missing packages via scripts/install-deps.sh)
#   make bench      the default benchmark run
#   make plots      charts of the newest run
#   make mpi        onbstudy-mpi, the MPI driver of the sweep (needs Open MPI's mpicc)
#   make robustness the hardening checks, then results/robustness.md
#   make install    PREFIX=/usr/local DESTDIR=  (header, libonb.a, onb.pc)
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
#  no -ffast-math      onb.h stops at #error under it (unless the client
#                      defines ONB_ALLOW_FAST_MATH): reassociation and
#                      reciprocal approximations would change every result.
# None of these reach a client: onb.pc carries only -I, -L and -l, and onb.h
# turns contraction off for its own functions by pragma (README "Using
# libonb in your renderer" says what each compiler does with that).
FPFLAGS = -ffp-contract=off -fno-math-errno -fno-trapping-math
OPT     ?= -O3
WARN    = -Wall -Wextra -Wpedantic -Wshadow
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
LIB_SRC = $(wildcard src/lib/*.c)
LIB_OBJ = $(LIB_SRC:src/lib/%.c=$(B)/lib/%.o)
# The study: every src/<folder>/*.c but src/lib/ (libonb) and src/mpi/ (the
# MPI driver, built by `make mpi` only).  A new folder src/<name>/ is picked
# up by these wildcards with no edit here; its objects go to build/<name>/.
# Includes name their folder from -Isrc ("sweep/engine.h"); onb.h comes
# from -Iinclude.
STUDY_SRC = $(filter-out src/lib/% src/mpi/%,$(wildcard src/*/*.c))
STUDY_OBJ = $(STUDY_SRC:src/%.c=$(B)/%.o)
STUDY_HDR = $(filter-out src/lib/%,$(wildcard src/*/*.h src/*/*.inc))
MAIN_OBJ  = $(B)/cli/main.o
# Everything of the study but main(), so tests can link the study's modules.
STUDY_LIB = $(B)/libstudy.a
TEST_SRC  = $(wildcard tests/test_*.c)
TEST_BIN  = $(TEST_SRC:tests/%.c=$(B)/tests/%)
# Helpers that shell tests call (not run on their own).
TEST_AUX  = $(B)/tests/certify_check
GIT_REV  := $(shell git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(shell git diff --quiet HEAD -- . ':(exclude)results' 2>/dev/null || echo -dirty)
PROV     = -DONB_GIT_REV='"$(GIT_REV)"' -DONB_CC='"$(shell $(CC) --version | head -1)"' \
           -DONB_CFLAGS='"$(BASE)"'

.PHONY: all test bench plots install uninstall clean deps
all: libonb.a onbstudy

# Dependencies: installed by the script when missing (a stamp records success).
$(B)/deps.stamp: scripts/install-deps.sh
	@mkdir -p $(B)
	sh scripts/install-deps.sh
	@touch $@
deps: $(B)/deps.stamp

$(B)/lib/%.o: src/lib/%.c include/onb.h Makefile
	@mkdir -p $(@D)
	$(CC) $(BASE) $(LIBWARN) -c $< -o $@

libonb.a: $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $(LIB_OBJ)

$(filter-out $(B)/bench/yardstick.o,$(STUDY_OBJ)): $(B)/%.o: src/%.c include/onb.h $(STUDY_HDR) Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) $(WARN) $(OMP) $(PROV) $(XFLAGS) -Isrc -D_POSIX_C_SOURCE=200809L -c $< -o $@

# Provenance: output.o and main.o carry the git revision and the flags.
# rev.stamp changes whenever they do (checked on every make), so a result
# file never names a stale revision.
$(B)/rev.stamp: FORCE
	@mkdir -p $(B)
	@echo '$(GIT_REV) $(BASE)' > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi
$(B)/cli/output.o $(MAIN_OBJ): $(B)/rev.stamp
.PHONY: FORCE
FORCE:

# The FMA copy of the kernels for `sweep --fma`: contraction on, on purpose.
ifeq ($(shell uname -m),x86_64)
$(B)/methods/fma_kernels.o: XFLAGS = -mfma -ffp-contract=fast
else
$(B)/methods/fma_kernels.o: XFLAGS = -ffp-contract=fast
endif

# The fast reference (issue 14): TwoProd through the fma instruction.  Only
# fma() calls use it: -ffp-contract=off (BASE) still forbids contraction.
# reffast_usable() refuses this path on a CPU without FMA.
ifeq ($(shell uname -m),x86_64)
$(B)/reference/reffast.o $(B)/reference/reffast_f.o: XFLAGS = -mfma
endif

# reffast_f.c is reffast.c compiled again with pairs of doubles.
$(B)/reference/reffast_f.o: src/reference/reffast.c

# The benchmark's yardstick (issue 4): plain loops built for this CPU, beside
# libonb's run-time dispatch.  Same FPFLAGS; no memcpy idiom for the copy.
# (left out of the study's rule above, which compiles every other object)
$(B)/bench/yardstick.o: src/bench/yardstick.c src/bench/yardstick.h include/onb.h Makefile $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) -march=native -fno-tree-loop-distribute-patterns $(WARN) -Isrc -c $< -o $@

# Certify (issue 22): src/certify/ is compiled by the study's rule above; its
# interval proofs use MPFI (linked statically, before MPFR, for the reason
# given at STUDY_LIBS).
STUDY_LIBS := -Wl,-Bstatic -lmpfi -Wl,-Bdynamic $(STUDY_LIBS)

$(STUDY_LIB): $(filter-out $(MAIN_OBJ),$(STUDY_OBJ))
	rm -f $@
	$(AR) rcs $@ $^

onbstudy: $(MAIN_OBJ) $(STUDY_LIB) libonb.a
	$(CC) $(BASE) $(OMP) -o $@ $(MAIN_OBJ) $(STUDY_LIB) libonb.a $(STUDY_LIBS)

$(B)/tests/%: tests/%.c $(STUDY_LIB) libonb.a include/onb.h $(wildcard tests/*.h) $(B)/deps.stamp
	@mkdir -p $(@D)
	$(CC) $(BASE) $(WARN) $(OMP) $(PROV) -D_POSIX_C_SOURCE=200809L -Isrc -o $@ $< $(STUDY_LIB) libonb.a $(STUDY_LIBS)

test: $(B)/deps.stamp all $(TEST_BIN) $(TEST_AUX)
	@fail=0; for t in $(TEST_BIN); do echo "== $$t"; $$t || fail=1; done; \
	for t in tests/*.sh; do [ -f "$$t" ] || continue; echo "== $$t"; ONB_SANFLAGS='$(SANFLAGS)' sh $$t || fail=1; done; \
	if [ $$fail -ne 0 ]; then echo "make test: FAILED"; exit 1; fi; echo "make test: all passed"

bench: onbstudy
	./onbstudy bench

# make plots [RUN=results/<run>]: charts of a run (default results/latest)
RUN ?= results/latest
plots: onbstudy
	sh scripts/plots.sh $(RUN)

# # make robustness: the hardening run (scripts/harden.sh, ~10 min on 2 cores),
# then the committed results/robustness.md and the README's copy of its
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
install: libonb.a
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/onb.h $(DESTDIR)$(PREFIX)/include/onb.h
	install -m 644 libonb.a $(DESTDIR)$(PREFIX)/lib/libonb.a
	printf '$(ONB_PC)' '$(PREFIX)' > $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc.tmp
	mv -f $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc.tmp $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/include/onb.h $(DESTDIR)$(PREFIX)/lib/libonb.a \
	      $(DESTDIR)$(PREFIX)/lib/pkgconfig/onb.pc

clean:
	rm -rf $(B) libonb.a onbstudy onbstudy-mpi onb.pc   # onb.pc: left by older Makefiles

# The MPI driver (issue 13): `make mpi` builds onbstudy-mpi with Open MPI's
# mpicc; the default build does not need MPI.  It links the same study
# library, so it runs the same engine as ./onbstudy.
MPICC ?= mpicc
.PHONY: mpi
mpi: onbstudy-mpi
$(B)/mpi/onbstudy_mpi.o: src/mpi/onbstudy_mpi.c $(STUDY_HDR) include/onb.h Makefile $(B)/rev.stamp
	@mkdir -p $(@D)
	$(MPICC) $(BASE) $(WARN) $(OMP) $(PROV) -Isrc -D_POSIX_C_SOURCE=200809L -c $< -o $@
onbstudy-mpi: $(B)/mpi/onbstudy_mpi.o $(STUDY_LIB) libonb.a
	$(MPICC) $(BASE) $(OMP) -o $@ $(B)/mpi/onbstudy_mpi.o $(STUDY_LIB) libonb.a $(STUDY_LIBS) -lpthread

# The example renderer links libonb.a and libm, as a user's would, and the
# scene reader (meshio, whose glTF part links cJSON) for --obj.
MESHIO_SRC = $(wildcard src/mesh/*.c)
$(B)/aorender: examples/aorender.c $(MESHIO_SRC) $(wildcard src/mesh/*.h) libonb.a include/onb.h
	@mkdir -p $(@D)
	$(CC) -std=c99 -O2 -ffp-contract=off $(SANFLAGS) -Wall -Wextra -Wpedantic -Wshadow -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -o $@ examples/aorender.c $(MESHIO_SRC) libonb.a -lcjson -lm
RENDERS = results/reference/renders
.PHONY: render
render: $(B)/aorender
	@mkdir -p $(RENDERS)
	$(B)/aorender --method duff_branchless --precision double --out $(RENDERS)/reference-double.png
	@for m in $$($(B)/aorender --list); do \
	  $(B)/aorender --method $$m --precision float --out $(RENDERS)/$$m-float.png --diff $(RENDERS)/$$m-float-diff.png || exit 1; \
	done | tee $(RENDERS)/summary.txt
