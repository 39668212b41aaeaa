# Top-level wrapper. `make` installs missing Debian packages, builds,
# regenerates every chapter and writes build/report/study.html.
# `make test` builds and runs the CTest suite (unit + chapter + report).
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
CTEST_ARGS ?=

.PHONY: all deps configure build study report test test-full full gold bench clean

all: report

deps:
	@bash scripts/install-deps.sh

FIDELITY ?= quick

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DDRAWBEND_FIDELITY=$(FIDELITY) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

study: build
	@cmake --build $(BUILD) --target study

report: study
	@cmake --build $(BUILD) --target report
	@echo "report: $(BUILD)/report/study.html"

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE 'full|pending' $(CTEST_ARGS)

test-full: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# The report at paper fidelity (finer draw-bend meshes; hours on 2 cores) in
# its own build folder: build-full/report/study.html.
full:
	@$(MAKE) --no-print-directory report BUILD=build-full FIDELITY=full

# Solver cost per element-cycle at 1 and 2 threads -> build/bench/results.csv
bench: build
	@cmake --build $(BUILD) --target bench

# Rewrite the regression gold files from the current code (review the diff!).
gold: build
	@cmake --build $(BUILD) --target gold

clean:
	@rm -rf $(BUILD) build-asan build-fuzz
