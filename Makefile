# Top-level wrapper.
#   make        installs missing Debian packages, builds, regenerates every
#               chapter at paper fidelity (the `full` draw-bend meshes) and
#               writes build-full/report/index.html (+ study.html); Chapter 8 runs its quick
#               tier there (its whole full study takes hours: `make test-full`);
#   make quick  the same report from the quick meshes of the test suite in
#               build/report/index.html (quicker: the quick meshes of `make test`);
#   make test   builds and runs the CTest suite (unit + chapter + report) in build/;
#   make install PREFIX=DIR  installs drawbend, its data and docs under DIR (/usr/local).
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
CTEST_ARGS ?=

.PHONY: all quick deps configure build study report test test-full full gold bench install clean

all: full

quick: report

deps:
	@bash scripts/install-deps.sh

FIDELITY ?= quick

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DDRAWBEND_FIDELITY=$(FIDELITY) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Two chapters side by side: each runs its cases side by side too (one OpenMP
# thread per case when it has several), and a chapter's last case would
# otherwise leave a core idle.  Chapters that read another's outputs wait for
# it (NEEDS in chapters/CMakeLists.txt).
study: build
	@cmake --build $(BUILD) --target study -j $(JOBS)

report: study
	@cmake --build $(BUILD) --target report
	@echo "report: $(BUILD)/report/index.html (one file: $(BUILD)/report/study.html)"

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'full|pending' $(CTEST_ARGS)

test-full: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# The report at paper fidelity (finer draw-bend meshes) in its own build
# folder, so that `make test` in build/ never overwrites its chapters.
full:
	@$(MAKE) --no-print-directory report BUILD=build-full FIDELITY=full

# Solver cost per element-cycle at 1 and 2 threads -> build/bench/results.csv
bench: build
	-@bash scripts/install-deps.sh --bench  # CalculiX is optional: without it the bench says so and goes on
	@cmake --build $(BUILD) --target bench

# Rewrite the regression gold files from the current code (review the diff!).
gold: build
	@cmake --build $(BUILD) --target gold

# The binary, its run-time data and the docs under PREFIX (bin/, share/drawbend/, share/doc/drawbend/).
PREFIX ?= /usr/local
install: build
	@cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	@rm -rf $(BUILD) build-full build-asan build-fuzz build-fuzz-loop
