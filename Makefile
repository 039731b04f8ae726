# The two commands: `make demo` and `make test`. Both install missing Debian
# packages, configure, build (Release, all cores) and run.
BUILD ?= build
DEBUG_BUILD ?= build-debug
SANITIZE_BUILD ?= build-sanitize
JOBS  ?= $(shell nproc)

.PHONY: all deps configure build debug-build sanitize-build demo test test-cluster test-sanitize fuzz bench paper paper-smoke format clean
all: build

deps:
	@scripts/install-deps.sh

CONFIGURE = cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DBOXLOD_DEBUG_BUILD=$(abspath $(DEBUG_BUILD)) \
  -DBOXLOD_SANITIZE_BUILD=$(abspath $(SANITIZE_BUILD)) >/dev/null

configure: deps
	@$(CONFIGURE)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The demo installs and builds only what it runs: the program (no tests,
# benchmarks or LaTeX; `make test` adds them to the same build folder).
demo:
	@scripts/install-deps.sh demo
	@$(CONFIGURE)
	@cmake --build $(BUILD) -j $(JOBS) --target boxlod
	@scripts/demo.sh $(BUILD)

test: build debug-build sanitize-build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The workflow's smoke profile through a one-node SLURM cluster started for the
# test, against the same profile run locally (docs/workflow.md: On a cluster):
# ctest runs workflow_end_to_end first, whose outputs it compares with (and
# which must pass); also part of `make test`.
test-cluster: build
	@cd $(BUILD) && ctest --output-on-failure -R workflow_on_slurm

# The Debug side of the Debug-against-Release tests (docs/testing.md: Determinism): -O0 (CGAL -O2)
# with the standard library's assertions, compiled for the one-definition-rule
# check (fat LTO objects; odr_check links them with LTO and -Werror=odr); only
# the program, the golden tests and the check.
debug-build: deps
	@cmake -S . -B $(DEBUG_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DBOXLOD_ODR_CHECK=ON -DBOXLOD_OPTIMISED_CGAL=ON \
	  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE >/dev/null
	@cmake --build $(DEBUG_BUILD) -j $(JOBS) --target debug_check_programs

# The lower layers' tests (base and renderer: the rasterizer's SIMD code, no
# CGAL) under AddressSanitizer + UndefinedBehaviorSanitizer, for `make test`;
# test-sanitize below builds the rest in the same folder.
SANITIZE_CONFIGURE = cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DBOXLOD_SANITIZE=ON -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE >/dev/null
sanitize-build: deps
	@$(SANITIZE_CONFIGURE)
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target base_tests renderer_tests

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer, in a
# Debug build (assertions on) at -O1: unoptimised Eigen and CGAL under ASan
# are a hundred times slower. Its golden images must match Release's exactly.
test-sanitize: deps
	@$(SANITIZE_CONFIGURE)
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	@cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS)

# libFuzzer on every reader of untrusted bytes (tests/fuzz), ASan + UBSan, for
# FUZZ_SECONDS each (default 60), starting from the corpora in tests/fuzz/corpus
# (docs/testing.md: Hardening). Inputs found go to build-fuzz/corpus, crashes to
# build-fuzz/crashes; a crash fails the run.
FUZZ_SECONDS ?= 60
fuzz:
	@scripts/install-deps.sh fuzz
	@CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DBOXLOD_FUZZ=ON \
	  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE >/dev/null
	@cmake --build build-fuzz -j $(JOBS) --target fuzz_targets
	@scripts/fuzz.sh build-fuzz $(FUZZ_SECONDS)

# Benchmarks against their peers (docs/performance.md), each repeated with
# boxlod's and the peer's runs interleaved at random, so both see the same
# states of a shared machine; ratio_table.py prints the medians with their
# spread as one table, naming the CPU. Each writes its JSON to $(BUILD)/bench/.
BENCHMARKS = rasterizer metrics png gltf simplification city
BENCH_REPETITIONS ?= 5
REPEATED = --benchmark_repetitions=$(BENCH_REPETITIONS) --benchmark_enable_random_interleaving=true
bench:
	@scripts/install-deps.sh bench
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target $(BENCHMARKS:%=%_benchmark)
	@mkdir -p $(BUILD)/bench
	@for b in $(BENCHMARKS); do \
	  $(BUILD)/experiments/$${b}_benchmark $(REPEATED) \
	    --benchmark_out=$(BUILD)/bench/$$b.json --benchmark_out_format=json || exit 1; done
	@LP_NUM_THREADS=1 $(BUILD)/experiments/rasterizer_benchmark --benchmark_filter='_frame/1/' $(REPEATED) \
	  --benchmark_out=$(BUILD)/bench/rasterizer_1_thread.json --benchmark_out_format=json
	@experiments/benchmarks/ratio_table.py $(BUILD)/bench

# The paper: every sweep and city run of the workflow (experiments/Snakefile,
# profile full; the jobs Snakemake finds up to date are skipped), the notebooks
# and the PDF, copied to out/paper/paper.pdf. paper-smoke: the same chain on
# tiny inputs (profile smoke, out/paper/paper-smoke.pdf), under a minute.
paper: PROFILE = full
paper-smoke: PROFILE = smoke
paper paper-smoke:
	@scripts/install-deps.sh paper
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target boxlod
	@/usr/bin/snakemake -s experiments/Snakefile -j $(JOBS) --rerun-incomplete \
	  --config profile=$(PROFILE) boxlod=$(BUILD)/boxlod
	@mkdir -p out/paper
	@cp out/workflow/$(PROFILE)/paper/paper.pdf out/paper/$(if $(filter full,$(PROFILE)),paper,paper-$(PROFILE)).pdf
	@echo "paper: out/paper/$(if $(filter full,$(PROFILE)),paper,paper-$(PROFILE)).pdf (everything: out/workflow/$(PROFILE)/)"

# The project's layout (.clang-format), which ctest `formatted` checks.
format: deps
	@git ls-files '*.cpp' '*.h' | xargs clang-format-14 --style=file -i

clean:
	rm -rf $(BUILD) $(DEBUG_BUILD) $(SANITIZE_BUILD)
